"""hullkit.dask.interpolate against one process (issue 30's Dask target): 1e8 queries against a 1e6-point
2D LinearNDInterpolator, over a LocalCluster of 2 worker processes (1 thread each) and in one process on
one thread, the same queries block by block. bench/interpolate_dask_run.sh runs each mode in a fresh
process (alternating) and prints the report.

    interpolate_dask_bench.py measure --mode single|dask --points N --queries M --block B
    interpolate_dask_bench.py report --results R.jsonl --out REPORT.md [--elapsed S]

The points are seeded, uniform in the unit square, values a smooth function; the queries are made block
by block (block k from seed 1000 + k, uniform in the square enlarged by 10% so that some fall outside)
where they are evaluated: on the workers for dask, in the loop for single. Both modes return each
block's SHA-256 of its values and the count of NaN; the blocks must agree bit for bit. Timed: from
before the interpolator is made (here) to the last block's digest (cluster start not timed). The dask
mode's interpolator is made here and sent to each worker once, which builds its triangulation there.
"""
import argparse
import hashlib
import json
import statistics
import sys
import time

import numpy as np

from python_bench import peak_mb


def inputs(n):
    rng = np.random.default_rng(60)
    points = rng.random((n, 2))
    return points, np.sin(4 * points[:, 0]) * np.cos(3 * points[:, 1]) + points[:, 0] * points[:, 1]


def block_queries(k, size):
    return np.random.default_rng(1000 + k).random((size, 2)) * 1.1 - 0.05


def block_summary(values):
    return hashlib.sha256(np.ascontiguousarray(values).tobytes()).hexdigest()[:16], int(np.isnan(values).sum())


def measure(args):
    from hullkit.interpolate import LinearNDInterpolator

    points, values = inputs(args.points)
    blocks = args.queries // args.block
    if args.mode == "single":
        start = time.perf_counter()
        f = LinearNDInterpolator(points, values, threads=1)
        summaries = [block_summary(f(block_queries(k, args.block))) for k in range(blocks)]
        seconds = time.perf_counter() - start
        peaks = [peak_mb()]
    else:
        import dask
        import dask.array as da
        from distributed import Client, LocalCluster

        import hullkit.dask

        with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, \
                Client(cluster) as client:
            client.run(lambda: __import__("hullkit.interpolate"))  # imports not timed, as the cluster start
            start = time.perf_counter()
            f = LinearNDInterpolator(points, values, threads=1)
            queries = da.concatenate([da.from_delayed(dask.delayed(block_queries)(k, args.block), (args.block, 2), float)
                                      for k in range(blocks)])
            out = hullkit.dask.interpolate(f, queries, threads=1)
            summaries = [tuple(s) for s in dask.compute(*[dask.delayed(block_summary)(b) for b in out.to_delayed().ravel()])]
            seconds = time.perf_counter() - start
            peaks = sorted(client.run(peak_mb).values())
    print(json.dumps({"mode": args.mode, "points": args.points, "queries": args.queries, "block": args.block,
                      "seconds": seconds, "blocks": [list(s) for s in summaries],
                      "nan": sum(s[1] for s in summaries), "peak_mb": peaks}))


def report(args):
    rows = [json.loads(line) for line in open(args.results) if line.strip()]
    single = [r for r in rows if r["mode"] == "single"]
    dsk = [r for r in rows if r["mode"] == "dask"]
    med = lambda rs: statistics.median(r["seconds"] for r in rs) if rs else float("nan")
    runs = lambda rs: ", ".join(f"{r['seconds']:.3g}" for r in rs)
    ratio = med(dsk) / med(single)
    same = len({json.dumps(r["blocks"]) for r in rows}) == 1
    first = rows[0]
    out = ["# hullkit.dask.interpolate against one process", "",
           f"Written by `bash bench/interpolate_dask_run.sh` on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}"
           + (f" in {int(args.elapsed) // 60} min {int(args.elapsed) % 60} s" if args.elapsed else "") + ". "
           f"LinearNDInterpolator on {first['points']} uniform 2D points; {first['queries']} queries in blocks of "
           f"{first['block']}, made where they are evaluated. single: one process, one thread. dask: "
           "`hullkit.dask.interpolate` on `LocalCluster(n_workers=2, threads_per_worker=1, processes=True)` (cluster "
           "start not timed; the interpolator made in the client and sent to each worker once, which builds its "
           "triangulation). Each run in a fresh process, the modes alternating; medians. The machine has 2 cores and is "
           "shared.", "",
           "| mode | wall, median | runs | peak RSS |", "|---|---:|---|---|",
           f"| single process, 1 thread | {med(single):.3g} s | {runs(single)} | "
           f"{max(r['peak_mb'][0] for r in single):.0f} MB |" if single else "| single | - | - | - |",
           f"| dask, 2 workers | {med(dsk):.3g} s | {runs(dsk)} | workers "
           f"{', '.join(f'{m:.0f}' for r in dsk for m in r['peak_mb'])} MB |" if dsk else "| dask | - | - | - |",
           "", "| target | figure | status |", "|---|---:|---|",
           f"| dask <= 0.65 x single | {ratio:.3f} | {'met' if ratio <= 0.65 else 'NOT MET'} |",
           f"| the same values, block for block (SHA-256) | {'yes' if same else 'NO'} | {'met' if same else 'NOT MET'} |",
           "", f"Queries outside the hull (NaN): {first['nan']} of {first['queries']}.", ""]
    open(args.out, "w").write("\n".join(out))
    print("\n".join(out))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("what", choices=["measure", "report"])
    parser.add_argument("--mode", choices=["single", "dask"], default="single")
    parser.add_argument("--points", type=float, default=1e6)
    parser.add_argument("--queries", type=float, default=1e8)
    parser.add_argument("--block", type=float, default=2e6)
    parser.add_argument("--results")
    parser.add_argument("--out")
    parser.add_argument("--elapsed", type=float, default=0)
    args = parser.parse_args()
    args.points, args.queries, args.block = int(args.points), int(args.queries), int(args.block)
    if args.what == "measure":
        measure(args)
    else:
        report(args)
    sys.stdout.flush()


if __name__ == "__main__":
    main()
