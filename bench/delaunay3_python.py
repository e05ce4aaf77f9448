"""Times one Python 3D Delaunay on one input file in a fresh process (bench/delaunay3_run.sh starts it
once per row) and prints one JSON line, like build/bench/hullkit_delaunay3_bench does natively.

    delaunay3_python.py --lib scipy|hullkit --input FILE.bin [--runs 1] [--budget 45]
                        [--threads 0] [--tets OUT.u32] [--furthest]

--lib scipy    scipy.spatial.Delaunay(points) (Qhull, scipy's options "Qbb Qc Qz Q12 Qt"), run with
               Debian's /usr/bin/python3 (its numpy and scipy);
--lib hullkit  hullkit.delaunay3(points, threads=N) from the hullkit package the interpreter imports;
               while that function does not exist the line says {"pending": "no Python binding ..."}.
--furthest     the furthest-site tetrahedralization instead: Delaunay(points, furthest_site=True)
               and hullkit.delaunay3(points, threads=N, furthest_site=True).
FILE.bin: raw little-endian float64 x y z triples (bench/delaunay3_inputs.mjs), read with numpy and
untimed, as are the imports. The first call is the headline ("first"), the median of the later calls
"warm"; no call starts once the calls so far add up to more than --budget seconds. --tets writes the
last call's tetrahedra as raw uint32 (4 per tetrahedron, from 0) for the harness to count and compare
(hullkit_delaunay3_bench --count OUT.u32 --format u32). peak_rss_mb is ru_maxrss of this process, taken
right after the calls.
"""
import argparse
import gc
import json
import os
import resource
import statistics
import time

import numpy as np


def tetrahedralize(lib, threads, furthest):
    """The call to time, as a function of the points, returning an (m, 4) integer array; or a reason
    why it cannot be made."""
    if lib == "scipy":
        from scipy.spatial import Delaunay

        return (lambda points: Delaunay(points, furthest_site=furthest).simplices), None
    try:
        import hullkit
    except ImportError as error:
        return None, f"no Python binding: {error} (the run script looks in build/python-bench-venv and build/python-venv)"
    if not callable(getattr(hullkit, "delaunay3", None)):
        return None, f"no Python binding: the hullkit package ({os.path.dirname(hullkit.__file__)}) has no delaunay3"
    if furthest:
        try:  # an installed package from before furthest_site (the run script installs ./python first)
            hullkit.delaunay3(np.eye(4, 3), furthest_site=True)
        except TypeError as error:
            return None, f"no furthest_site in the hullkit package ({os.path.dirname(hullkit.__file__)}): {error}"
    return (lambda points: hullkit.delaunay3(points, threads=threads, furthest_site=furthest).tetrahedra), None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lib", choices=["scipy", "hullkit"], required=True)
    parser.add_argument("--input", required=True)
    parser.add_argument("--runs", type=int, default=1)
    parser.add_argument("--budget", type=float, default=45.0)
    parser.add_argument("--threads", type=int, default=0)
    parser.add_argument("--tets")
    parser.add_argument("--furthest", action="store_true")
    args = parser.parse_args()
    name = os.path.basename(args.input).removesuffix(".bin")
    line = {"impl": f"{args.lib}-python" + ("-furthest" if args.furthest else ""), "input": name}

    points = np.fromfile(args.input, dtype="<f8").reshape(-1, 3)
    call, pending = tetrahedralize(args.lib, args.threads, args.furthest)
    if pending:
        print(json.dumps({**line, "pending": pending}))
        return
    runs, result = [], None
    while len(runs) < args.runs and (not runs or sum(runs) < args.budget):
        result = None
        gc.collect()
        start = time.perf_counter()
        result = call(points)
        runs.append(time.perf_counter() - start)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    if args.tets:
        np.ascontiguousarray(result, dtype="<u4").tofile(args.tets)
    print(json.dumps({**line, "n": len(points), "threads": args.threads if args.lib == "hullkit" else 1,
                      "first": runs[0], "runs": runs, "warm": statistics.median(runs[1:]) if len(runs) > 1 else None,
                      "tetrahedra": len(result), "peak_rss_mb": peak}))


if __name__ == "__main__":
    main()
