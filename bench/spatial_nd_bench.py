"""hullkit.spatial against scipy.spatial above 3 dimensions, one measurement per process (started by
bench/spatial_nd_run.sh, contenders alternating, so every figure is a first call in a fresh
process); prints one JSON line.

    spatial_nd_bench.py delaunay --lib hullkit|scipy --dim D --n N   Delaunay of N uniform points in [0, 1)^D
    spatial_nd_bench.py hull --lib hullkit|scipy --dim D --n N       ConvexHull of N Gaussian points
    spatial_nd_bench.py voronoi --lib hullkit|scipy --dim D --n N    Voronoi of N uniform points
    spatial_nd_bench.py volumes --lib hullkit|scipy --dim D --n N    the same with each cell's volume:
        hullkit's Voronoi.volumes; for scipy, what its users write (scipy issues 7604, 20118): the
        ConvexHull volume of each bounded region's vertices, inf for the unbounded ones
"""
import argparse
import hashlib
import importlib
import json
import resource
import time

import numpy as np


def digest_rows(rows):
    """A digest of a set of index rows, each sorted, independent of their order."""
    rows = np.sort(np.asarray(rows, dtype=np.int64), axis=1)
    rows = rows[np.lexsort(rows.T[::-1])]
    return hashlib.sha256(rows.tobytes()).hexdigest()[:16]


def cell_volumes(diagram, module):
    """Each point's cell volume from scipy's diagram, as its users compute it: the convex hull of
    the region's vertices, inf when the region is unbounded."""
    volumes = np.full(len(diagram.points), np.inf)
    for p, r in enumerate(diagram.point_region):
        region = diagram.regions[r]
        if region and -1 not in region:
            volumes[p] = module.ConvexHull(diagram.vertices[region]).volume
    return volumes


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("what", choices=["delaunay", "hull", "voronoi", "volumes"])
    parser.add_argument("--lib", default="hullkit")
    parser.add_argument("--dim", type=int, required=True)
    parser.add_argument("--n", type=int, required=True)
    args = parser.parse_args()
    rng = np.random.default_rng(100 + args.dim)
    points = rng.normal(size=(args.n, args.dim)) if args.what == "hull" else rng.random((args.n, args.dim))
    module = importlib.import_module("hullkit.spatial" if args.lib == "hullkit" else "scipy.spatial")
    cls = {"delaunay": "Delaunay", "hull": "ConvexHull", "voronoi": "Voronoi", "volumes": "Voronoi"}[args.what]
    start = time.perf_counter()
    result = getattr(module, cls)(points)
    if args.what == "volumes":
        volumes = cell_volumes(result, module) if args.lib != "hullkit" else result.volumes
    seconds = time.perf_counter() - start
    row = {"what": args.what, "lib": args.lib, "dim": args.dim, "n": args.n, "seconds": seconds,
           "peak_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0}
    if args.what == "volumes":
        # Compared between the libraries by a digest of the volumes to 8 significant digits (inf
        # kept as it is).
        row["count"] = int(np.isfinite(volumes).sum())
        row["set"] = hashlib.sha256(np.array([float(f"{v:.8g}") for v in volumes]).tobytes()).hexdigest()[:16]
    elif args.what == "voronoi":
        row["count"] = int(len(result.vertices))
        row["set"] = digest_rows(result.ridge_points)
        row["ridges"] = int(len(result.ridge_points))
    else:
        row["count"] = int(len(result.simplices))
        row["set"] = digest_rows(result.simplices)
    print(json.dumps(row))


if __name__ == "__main__":
    main()
