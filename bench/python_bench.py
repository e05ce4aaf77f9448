"""The Python package's benchmark (issue 15), one measurement per process: bench/python_run.sh
starts this script once per row and alternates the contenders, so that every figure is a first
call in a fresh process; it prints one JSON line.

    python_bench.py hull --lib hullkit|scipy --n N              ConvexHull of N points on a sphere
    python_bench.py delaunay --lib hullkit|scipy --n N          Delaunay of N uniform 2D points
    python_bench.py halfspace --lib hullkit|scipy --n N         HalfspaceIntersection of N planes tangent to a sphere
    python_bench.py voronoi --lib hullkit|scipy --n N           Voronoi of N uniform 2D points (hullkit: with cell areas)
    python_bench.py conversions --lib "float64 C"|"float32 Fortran" --n N   hullkit.hull outside the core
    python_bench.py write-ply --n N --files K --dir D           a ball of N points as K binary PLY
    python_bench.py files --mode single|dask --dir D            the hull of those files
    python_bench.py routes --mode single|dask|dask-send --legs L --scene S --route R [--one-route]
"""
import argparse
import glob
import hashlib
import json
import os
import resource
import sys
import time

import numpy as np


def peak_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def sphere(n, seed=15):
    points = np.random.default_rng(seed).normal(size=(n, 3))
    return points / np.linalg.norm(points, axis=1)[:, None]


def digest(*arrays):
    h = hashlib.sha256()
    for a in arrays:
        h.update(np.ascontiguousarray(a).tobytes())
    return h.hexdigest()[:16]


def spatial_class(lib, name):
    """hullkit.spatial's or scipy.spatial's class ``name``."""
    import importlib
    return getattr(importlib.import_module("hullkit.spatial" if lib == "hullkit" else "scipy.spatial"), name)


def run_hull(args):
    points = sphere(args.n)
    ConvexHull = spatial_class(args.lib, "ConvexHull")
    start = time.perf_counter()
    h = ConvexHull(points)
    seconds = time.perf_counter() - start
    return {"seconds": seconds, "vertices": int(len(h.vertices)), "simplices": int(len(h.simplices)),
            "volume": float(h.volume), "vertex_set": digest(np.sort(h.vertices))}


def run_delaunay(args):
    points = np.random.default_rng(16).random((args.n, 2))
    Delaunay = spatial_class(args.lib, "Delaunay")
    start = time.perf_counter()
    d = Delaunay(points)
    seconds = time.perf_counter() - start
    return {"seconds": seconds, "simplices": int(len(d.simplices)),
            "triangle_set": digest(np.sort(np.sort(d.simplices, axis=1), axis=0))}


def run_halfspace(args):
    normals = sphere(args.n, seed=17)
    halfspaces = np.column_stack([normals, -np.ones(args.n)])  # n . x <= 1: tangent to the unit sphere
    HalfspaceIntersection = spatial_class(args.lib, "HalfspaceIntersection")
    start = time.perf_counter()
    hs = HalfspaceIntersection(halfspaces, np.zeros(3))
    seconds = time.perf_counter() - start
    return {"seconds": seconds, "corners": int(len(hs.intersections)),
            "vertex_set": digest(np.sort(np.asarray(hs.dual_vertices, dtype=np.int64)))}


def run_voronoi(args):
    points = np.random.default_rng(18).random((args.n, 2))
    Voronoi = spatial_class(args.lib, "Voronoi")
    start = time.perf_counter()
    v = Voronoi(points)
    areas = v.volumes if args.lib == "hullkit" else None  # scipy has none
    seconds = time.perf_counter() - start
    # Then scipy's lists (hullkit makes them on first use; scipy's exist already).
    start = time.perf_counter()
    regions, ridges = v.regions, v.ridge_vertices
    lists = time.perf_counter() - start
    bounded = sum(1 for r in regions if r and -1 not in r)
    return {"seconds": seconds, "lists_seconds": lists, "with_lists": seconds + lists, "vertices": int(len(v.vertices)),
            "ridges": len(ridges), "bounded": bounded,
            "vertex_set": f"{len(v.vertices)}-{len(ridges)}-{bounded}",
            "finite_areas": None if areas is None else int(np.isfinite(areas).sum())}


def run_conversions(args):
    """The first hullkit.hull call of the process, in its parts: converting the input
    (as_points: nothing to do for float64 C input, one converting copy for float32 Fortran), the
    core (C++), and wrapping its arrays (Hull); "outside" = (convert + wrap) / whole."""
    import hullkit
    from hullkit import _core

    name = args.lib  # "float64 C" or "float32 Fortran", one kind per process
    points = sphere(args.n)
    if name == "float32 Fortran":
        points = np.asfortranarray(points.astype(np.float32))
    start = time.perf_counter()
    array = hullkit.as_points(points, 3)
    converted = time.perf_counter()
    result = _core.hull(array, "quickhull", False, 0)
    cored = time.perf_counter()
    h = hullkit.Hull(result, array)
    done = time.perf_counter()
    convert, core, wrap = converted - start, cored - converted, done - cored
    return {"kind": name, "whole": done - start, "convert": convert, "core": core, "wrap": wrap,
            "outside": (convert + wrap) / (done - start), "triangles": int(len(h.triangles))}


def run_write_ply(args):
    os.makedirs(args.dir, exist_ok=True)
    rng = np.random.default_rng(17)
    per = args.n // args.files
    for k in range(args.files):
        count = per if k < args.files - 1 else args.n - per * (args.files - 1)
        path = os.path.join(args.dir, f"ball-{k:02d}.ply")
        with open(path, "wb") as f:
            f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {count}\nproperty double x\n"
                    f"property double y\nproperty double z\nend_header\n".encode())
            left = count
            while left:
                m = min(left, 1 << 21)
                p = rng.normal(size=(m, 3))
                p *= (rng.random(m) ** (1 / 3) / np.linalg.norm(p, axis=1))[:, None]
                f.write(np.ascontiguousarray(p, dtype="<f8").tobytes())
                left -= m
    return {"files": args.files, "points": args.n, "bytes": sum(os.path.getsize(p) for p in glob.glob(os.path.join(args.dir, "*.ply")))}


def run_files(args):
    import hullkit
    import hullkit.dask

    paths = sorted(glob.glob(os.path.join(args.dir, "ball-*.ply")))
    if args.mode == "single":
        # One process, one thread: each file streamed into its own HullBuilder (the map step, as
        # a worker does), then the merge; the same work as the cluster's, on one core.
        start = time.perf_counter()
        partials = []
        first = 0
        for path in paths:
            part = hullkit._core.hull_file(path, 1)
            part["index"] = part["index"] + np.uint64(first)
            first += part["point_count"]
            partials.append(part)
        merged = hullkit.dask._merge(partials, 1, final=True)
        seconds = time.perf_counter() - start
        h = hullkit.dask.DaskHull(merged)
        worker_peaks = [peak_mb()]
    else:
        from distributed import Client, LocalCluster

        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        client.run(lambda: None)  # workers up before the clock starts
        start = time.perf_counter()
        h = hullkit.dask.hull(paths, client=client)
        seconds = time.perf_counter() - start
        worker_peaks = sorted(client.run(peak_mb).values())
        client.close()
        cluster.close()
    return {"seconds": seconds, "points": h.point_count, "vertices": int(len(h.vertices)),
            "triangles": digest(h.triangles), "volume_bits": float(h.volume).hex(), "peak_mb": worker_peaks,
            "process_peak_mb": peak_mb()}


def run_routes(args):
    import hullkit
    import hullkit.dask

    with open(args.route) as f:
        waypoints = np.array(json.load(f), dtype=np.float64)
    # `legs` legs cycling through the route's waypoints, as routes of 10 legs each (or one route).
    cycle = np.array([waypoints[k % len(waypoints)] for k in range(args.legs + 1)])
    routes = [cycle] if args.one_route else [cycle[k:k + 11] for k in range(0, args.legs, 10)]
    strip = lambda r: {k: v for k, v in r.items() if k not in ("build_seconds", "seconds")}
    # First call (the checker built, the scene sent), then the same routes again (warm: the
    # checker reused, on the cluster one per worker).
    if args.mode == "single":
        start = time.perf_counter()
        checker = hullkit.RouteChecker(args.scene)
        reports = [checker.check(r, threads=1) for r in routes]
        seconds = time.perf_counter() - start
        start = time.perf_counter()
        again = [checker.check(r, threads=1) for r in routes]
        warm = time.perf_counter() - start
    else:
        from distributed import Client, LocalCluster

        # dask: the workers read the scene file themselves (the default on one machine);
        # dask-send: it is sent to them from here (send_scene=True, as to other machines).
        send = args.mode == "dask-send"
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        client.run(lambda: None)
        start = time.perf_counter()
        reports = hullkit.dask.check_routes(args.scene, routes, client=client, send_scene=send)
        seconds = time.perf_counter() - start
        start = time.perf_counter()
        again = hullkit.dask.check_routes(args.scene, routes, client=client, send_scene=send)
        warm = time.perf_counter() - start
        client.close()
        cluster.close()
    assert [strip(r) for r in again] == [strip(r) for r in reports]
    text = json.dumps([strip(r) for r in reports], sort_keys=True)
    return {"seconds": seconds, "warm_seconds": warm, "legs": sum(len(r["legs"]) for r in reports),
            "scene": os.path.basename(args.scene), "route": os.path.basename(args.route), "one_route": args.one_route,
            "not_clear": sum(leg["status"] != "clear" for r in reports for leg in r["legs"]),
            "reports": hashlib.sha256(text.encode()).hexdigest()[:16]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("what", choices=["hull", "delaunay", "halfspace", "voronoi", "conversions", "write-ply", "files", "routes"])
    parser.add_argument("--lib", default="hullkit")
    parser.add_argument("--n", type=float, default=1e6)
    parser.add_argument("--files", type=int, default=16)
    parser.add_argument("--dir", default="bench/out/python")
    parser.add_argument("--mode", default="single")
    parser.add_argument("--legs", type=int, default=10000)
    parser.add_argument("--scene")
    parser.add_argument("--route")
    parser.add_argument("--one-route", action="store_true", help="the legs as one route, not routes of 10 legs")
    args = parser.parse_args()
    args.n = int(args.n)
    result = {"hull": run_hull, "delaunay": run_delaunay, "halfspace": run_halfspace, "voronoi": run_voronoi, "conversions": run_conversions, "write-ply": run_write_ply,
              "files": run_files, "routes": run_routes}[args.what](args)
    print(json.dumps({"what": args.what, "lib": args.lib, "mode": args.mode, "n": args.n, **result,
                      "peak_rss_mb": peak_mb()}))
    sys.stdout.flush()


if __name__ == "__main__":
    main()
