"""hullkit.interpolate against scipy.interpolate, one measurement per process: bench/interpolate_run.sh
starts this script once per row, so that every headline figure is a first call in a fresh process; it
prints one JSON line (the report step prints the markdown report instead).

    interpolate_bench.py meta [--quick]                                    the machine and versions
    interpolate_bench.py reference --case C --points N --queries M --dir D which queries are inside the hull
    interpolate_bench.py measure --case C --lib hullkit|scipy --points N --queries M --dir D [--calls 1|2]
    interpolate_bench.py report --results R.jsonl --out REPORT.md [--elapsed S]

Cases: linear-2d, linear-3d (LinearNDInterpolator), cubic-2d (CloughTocher2DInterpolator),
nearest-2d (NearestNDInterpolator). The inputs are
seeded: N points uniform in the unit square (cube), values a smooth function of them, M queries uniform in
the same square (cube). measure times the constructor ("build") and the first call on the M queries,
whose sum is the headline, then (--calls 2) a second call on the same object ("warm"). After the clock:
NaN results inside and outside the hull (reference's exact mask), the largest |hullkit - scipy| where both
are finite (against the other library's values, saved in D by an earlier process of this run), and the
process's peak RSS (ru_maxrss) right after the first call and after all calls.
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys
import time
from fractions import Fraction

import numpy as np

from python_bench import digest, peak_mb

CASES = {
    "linear-2d": {"kind": "linear", "ndim": 2, "target": 0.01, "title": "LinearNDInterpolator, 2D"},
    "linear-3d": {"kind": "linear", "ndim": 3, "target": 0.02, "title": "LinearNDInterpolator, 3D"},
    "cubic-2d": {"kind": "cubic", "ndim": 2, "target": 0.02, "title": "CloughTocher2DInterpolator, 2D"},
    "nearest-2d": {"kind": "nearest", "ndim": 2, "target": None, "title": "NearestNDInterpolator, 2D"},
}
TOLERANCE = 1e-12  # above any rounding of a plane test on coordinates in [0, 1] (errors ~1e-15)


def smooth(p):
    f = np.sin(4 * p[:, 0]) * np.cos(3 * p[:, 1]) + p[:, 0] * p[:, 1]
    return f + 0.5 * np.sin(5 * p[:, 2]) if p.shape[1] == 3 else f


def inputs(case, n, m):
    ndim = CASES[case]["ndim"]
    points = np.random.default_rng(40 + ndim).random((n, ndim))
    queries = np.random.default_rng(50 + ndim).random((m, ndim))
    return points, smooth(points), queries


def exact_orientation(corners, q):
    """The sign of the plane test of q against a hull facet (its corners), in rational arithmetic:
    the determinant of the rows (corner - first corner, q - first corner)."""
    a = [Fraction(x) for x in corners[0]]
    rows = [[Fraction(x) - y for x, y in zip(p, a)] for p in (*corners[1:], q)]
    if len(rows) == 2:
        det = rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
    else:
        (a0, a1, a2), (b0, b1, b2), (c0, c1, c2) = rows
        det = a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0)
    return (det > 0) - (det < 0)


def inside_hull(points, facets, queries):
    """Whether each query is in the closed convex hull whose facets (edges in 2D, triangles in 3D)
    are given: a float plane test against every facet, the ones within TOLERANCE of zero decided
    exactly. Returns the mask and how many tests were decided exactly."""
    assert points.min() >= 0 and points.max() <= 1 and queries.min() >= 0 and queries.max() <= 1
    corners = points[facets]
    first = corners[:, 0]
    u = corners[:, 1] - first
    normal = np.stack([-u[:, 1], u[:, 0]], axis=1) if points.shape[1] == 2 else np.cross(u, corners[:, 2] - first)
    offset = np.einsum("ij,ij->i", normal, first)
    centre = points[np.unique(facets)].mean(axis=0)
    side = np.sign(normal @ centre - offset)  # the inner side of each facet
    assert np.all(side != 0)
    inside = np.ones(len(queries), dtype=bool)
    exact = 0
    step = max(1, 4_000_000 // len(facets))
    for start in range(0, len(queries), step):
        q = queries[start:start + step]
        det = (q @ normal.T - offset) * side
        out = (det < -TOLERANCE).any(axis=1)
        for i, f in np.argwhere((np.abs(det) <= TOLERANCE) & ~out[:, None]):
            exact += 1
            if exact_orientation(corners[f], q[i]) * side[f] < 0:
                out[i] = True
        inside[start:start + step] = ~out
    return inside, exact


def saved(directory, case, what):
    return os.path.join(directory, f"{case}-{what}.npy")


def run_reference(args):
    """The exact inside-the-hull mask of the queries, from hullkit's exact hull (checked against
    Qhull's vertex set), saved for the measurements."""
    from hullkit.spatial import ConvexHull
    from scipy.spatial import ConvexHull as QhullHull

    points, _, queries = inputs(args.case, args.points, args.queries)
    hull = ConvexHull(points)
    same = set(hull.vertices.tolist()) == set(QhullHull(points).vertices.tolist())
    start = time.perf_counter()
    inside, exact = inside_hull(points, hull.simplices, queries)
    np.save(saved(args.dir, args.case, "inside"), inside)
    return {"hull_vertices": int(len(hull.vertices)), "hull_facets": int(len(hull.simplices)),
            "same_hull_as_qhull": same, "outside": int((~inside).sum()), "exact_tests": exact,
            "mask_seconds": time.perf_counter() - start}


def run_measure(args):
    spec = CASES[args.case]
    points, values, queries = inputs(args.case, args.points, args.queries)
    if args.lib == "hullkit":
        from hullkit.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator, NearestNDInterpolator
    else:
        from scipy.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator, NearestNDInterpolator
    cls = {"linear": LinearNDInterpolator, "cubic": CloughTocher2DInterpolator, "nearest": NearestNDInterpolator}[spec["kind"]]
    start = time.perf_counter()
    f = cls(points, values)
    built = time.perf_counter()
    out = f(queries)
    called = time.perf_counter()
    peak_first = peak_mb()
    warm = same_again = None
    if args.calls > 1:
        again = f(queries)
        warm = time.perf_counter() - called
        same_again = bool(np.array_equal(out, again, equal_nan=True))
        del again
    peak_all = peak_mb()
    # Not timed: NaNs against the exact mask, and the other library's values if saved already.
    inside = np.load(saved(args.dir, args.case, "inside"))
    nan = np.isnan(out)
    line = {"build": built - start, "first": called - built, "seconds": called - start, "warm": warm,
            "same_again": same_again, "peak_first_mb": peak_first, "peak_mb": peak_all,
            "threads": 0 if args.lib == "hullkit" else 1, "nan_inside": int((nan & inside).sum()),
            "nan_outside": int((nan & ~inside).sum()), "outside": int((~inside).sum()), "values": digest(out)}
    np.save(saved(args.dir, args.case, args.lib), out)
    other = saved(args.dir, args.case, "scipy" if args.lib == "hullkit" else "hullkit")
    if os.path.exists(other):
        theirs = np.load(other)
        both = np.isfinite(out) & np.isfinite(theirs)
        diff = np.abs(out[both] - theirs[both])
        line.update(compared=int(both.sum()), max_abs_diff=float(diff.max()) if len(diff) else 0.0,
                    differing=int((diff != 0).sum()),
                    finite_mismatch_inside=int(((np.isfinite(out) != np.isfinite(theirs)) & inside).sum()))
    return line


def command_line(*command):
    try:
        return subprocess.run(command, capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None


def run_meta(args):
    import scipy

    try:
        import hullkit
        where = os.path.dirname(hullkit.__file__)
    except ImportError as error:
        where = f"not importable: {error}"
    cpu = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")), "unknown CPU")
    changed = command_line("git", "status", "--porcelain", "--", "native", "python")
    return {"date": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()), "quick": args.quick, "cpu": cpu,
            "cores": os.cpu_count(), "memory_gb": round(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30),
            "load_start": [round(x, 2) for x in os.getloadavg()], "commit": command_line("git", "rev-parse", "--short", "HEAD"),
            "uncommitted": len(changed.splitlines()) if changed else 0, "python": platform.python_version(),
            "numpy": np.__version__, "scipy": scipy.__version__, "hullkit": where}


# ------------------------------------------------------------------------------------------ report
def seconds(x):
    return "-" if x is None else f"{x:.3g} s"


def median_of(rows, key):
    xs = [r[key] for r in rows if r.get(key) is not None]
    return statistics.median(xs) if xs else None


def ratio_text(a, b):
    return "-" if a is None or b is None else f"{a / b:.4f}"


def case_section(number, case, rows, refs, quick):
    spec = CASES[case]
    hk = [r for r in rows if r["lib"] == "hullkit" and r["case"] == case]
    sp = [r for r in rows if r["lib"] == "scipy" and r["case"] == case]
    if not hk and not sp:
        return [], None
    some = (hk or sp)[0]
    ref = next((r for r in refs if r["case"] == case), {})
    out = [f"## {number}. {spec['title']}", "",
           f"{some['points']:,} points uniform in the unit {'square' if spec['ndim'] == 2 else 'cube'}, values a smooth function, "
           f"{some['queries']:,} uniform queries in the same {'square' if spec['ndim'] == 2 else 'cube'} "
           f"({ref.get('outside', '?')} of them outside the points' hull: {ref.get('hull_vertices', '?')} vertices, "
           f"the same as Qhull's: {'yes' if ref.get('same_hull_as_qhull') else 'no'}).", "",
           "| | build + first call | build | first call | warm call | peak RSS, first call (all) | NaN inside hull | NaN outside hull | runs (build + first) |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for name, rs in (("hullkit", hk), ("scipy", sp)):
        if not rs:
            out.append(f"| {name} | not run | | | | | | | |")
            continue
        warm = median_of(rs, "warm")
        out.append(f"| {name}, {len(rs)} process{'es' if len(rs) > 1 else ''} | **{seconds(median_of(rs, 'seconds'))}** | "
                   f"{seconds(median_of(rs, 'build'))} | {seconds(median_of(rs, 'first'))} | "
                   f"{seconds(warm) if warm is not None else 'not run'} | "
                   f"{median_of(rs, 'peak_first_mb'):.0f} MB ({median_of(rs, 'peak_mb'):.0f} MB) | "
                   f"{', '.join(str(r['nan_inside']) for r in rs)} | {', '.join(str(r['nan_outside']) for r in rs)} | "
                   f"{', '.join(format(r['seconds'], '.3g') for r in rs)} |")
    ratio = None
    if hk and sp:
        ratio = median_of(hk, "seconds") / median_of(sp, "seconds")
        out.append(f"| hullkit ÷ scipy | **{ratio:.4f}** | - | "
                   f"{ratio_text(median_of(hk, 'first'), median_of(sp, 'first'))} | {ratio_text(median_of(hk, 'warm'), median_of(sp, 'warm'))} | "
                   f"{median_of(hk, 'peak_first_mb') / median_of(sp, 'peak_first_mb'):.2f} | | | |")
    out.append("")
    if spec["target"] is not None:
        verdict = "not measured" if ratio is None else "**met**" if ratio <= spec["target"] else "**not met**"
        out.append(f"Target: hullkit's build + first call <= {spec['target']}× scipy's: {verdict}"
                   f"{'' if ratio is None else f' ({ratio:.4f}×, {1 / ratio:.0f} times faster)'}"
                   f"{' (at a tenth of the sizes: the target is for the full run)' if quick else ''}.")
    else:
        out.append("No target" + ("" if ratio is None else f": hullkit's build + first call is {ratio:.4f}× scipy's."))
    compared = [r for r in rows if r["case"] == case and "max_abs_diff" in r]
    if compared:
        worst = max(compared, key=lambda r: r["max_abs_diff"])
        out.append(f"Largest |hullkit − scipy| where both are finite: {worst['max_abs_diff']:.3g} "
                   f"(over {worst['compared']:,} queries; values not bit-identical (rounding: another triangulation or summation order): "
                   f"{', '.join(str(r['differing']) for r in compared)}; finite in one and NaN in the other, inside the hull: "
                   f"{', '.join(str(r['finite_mismatch_inside']) for r in compared)}; one figure per process compared).")
    same_values = len({r["values"] for r in hk}) <= 1
    again = [r["same_again"] for r in hk + sp if r["same_again"] is not None]
    out.append(f"hullkit's values identical in every process: {'yes' if same_values else 'no'}; "
               f"the warm call's values identical to the first call's: {'yes' if all(again) else 'no'}"
               f"{'' if again else ' (no warm call)'}.")
    out.append("")
    summary = (spec["title"], median_of(hk, "seconds"), median_of(sp, "seconds"), ratio, spec["target"],
               median_of(hk, "warm"), median_of(sp, "warm"), max((r["nan_inside"] for r in hk), default="-"),
               max((r["nan_inside"] for r in sp), default="-"))
    return out, summary


def run_report(args):
    rows = [json.loads(line) for line in open(args.results) if line.strip()]
    meta = next((r for r in rows if r["what"] == "meta"), {})
    refs = [r for r in rows if r["what"] == "reference"]
    measured = [r for r in rows if r["what"] == "measure"]
    # The load at the end only when called by the run script (--elapsed), not when re-rendered later.
    load_end = f", {' '.join(str(round(x, 2)) for x in os.getloadavg())} at the end" if args.elapsed is not None else ""
    minutes = f"{args.elapsed // 60} min {args.elapsed % 60} s" if args.elapsed is not None else "?"
    out = ["# Interpolation benchmark: hullkit.interpolate against scipy.interpolate" + (" (quick run)" if meta.get("quick") else ""), "",
           f"Written by `bash bench/interpolate_run.sh` on {meta.get('date', '?')} in {minutes}. "
           f"Machine: {meta.get('cpu', '?')}, {meta.get('cores', '?')} cores, {meta.get('memory_gb', '?')} GB; shared and noisy, so compare ratios "
           f"(load average {' '.join(map(str, meta.get('load_start', [])))} at the start{load_end}). "
           f"hullkit at commit {meta.get('commit', '?')}"
           f"{f' with {n} uncommitted files in native/ and python/' if (n := meta.get('uncommitted')) else ''}, built by pip from ./python "
           f"(-O3, -ffp-contract=off; {meta.get('hullkit', '?')}); Python {meta.get('python', '?')}, numpy {meta.get('numpy', '?')}, "
           f"scipy {meta.get('scipy', '?')} (Debian's, run by /usr/bin/python3).", "",
           *([f"**The machine was busy** (load average {meta['load_start'][0]:.1f} on {meta['cores']} cores when the run started): "
              "other work shared the cores, so times and ratios are rough.", ""]
             if meta.get("load_start") and meta["load_start"][0] > meta.get("cores", 2) / 2 else []),
           "Each row is one fresh process (bench/interpolate_bench.py): the inputs generated from fixed seeds and the library imported "
           "(untimed), then the constructor (**build**), the first call on all queries (**first call**; their sum is the headline), and a "
           "second call on the same object (**warm**). hullkit's constructor only keeps the inputs: its triangulation is built in the "
           "first call. hullkit runs with its default `threads=0` (both cores); scipy is single-threaded (Qhull, its walk to each query's "
           "triangle; scipy 1.10's NearestNDInterpolator queries its cKDTree with one worker and takes no query options). "
           "NaN counts are against an exact mask of the queries inside the points' convex hull (hullkit's exact hull, its vertex set "
           "checked against Qhull's; plane tests in floating point, any within 1e-12 of zero redone in rational arithmetic). "
           "Peak RSS is ru_maxrss of the whole process (Python, numpy, inputs and outputs included). Medians over processes, every run listed.", ""]
    sections, summaries = [], []
    for number, case in enumerate(CASES, 1):
        lines, summary = case_section(number, case, measured, refs, meta.get("quick"))
        sections += lines
        if summary:
            summaries.append(summary)
    out += ["## Summary", "",
            "| case | hullkit, build + first call | scipy | hullkit ÷ scipy | target | hullkit warm | scipy warm | NaN inside hull (most in a process), hullkit / scipy |",
            "|---|---:|---:|---:|---|---:|---:|---|"]
    for title, h, s, ratio, target, hw, sw, hn, sn in summaries:
        status = "-" if target is None else "not measured" if ratio is None else f"<= {target}, {'met' if ratio <= target else 'not met'}"
        status += " (quick sizes)" if meta.get("quick") and target is not None else ""
        out.append(f"| {title} | {seconds(h)} | {seconds(s)} | {'-' if ratio is None else f'{ratio:.4f}'} | {status} | {seconds(hw)} | "
                   f"{seconds(sw) if sw is not None else 'not run'} | {hn} / {sn} |")
    out += [""] + sections + [f"Raw figures: `{args.results}` (one JSON line per process).", ""]
    with open(args.out, "w") as f:
        f.write("\n".join(out))
    print(f"interpolate bench: wrote {args.out}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("what", choices=["meta", "reference", "measure", "report"])
    parser.add_argument("--case", choices=list(CASES))
    parser.add_argument("--lib", default="hullkit", choices=["hullkit", "scipy"])
    parser.add_argument("--points", type=float, default=1e6)
    parser.add_argument("--queries", type=float, default=1e6)
    parser.add_argument("--calls", type=int, default=2, help="1: no warm call")
    parser.add_argument("--dir", default="bench/out/interpolate")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--results")
    parser.add_argument("--out")
    parser.add_argument("--elapsed", type=int)
    args = parser.parse_args()
    if args.what == "report":
        return run_report(args)
    args.points, args.queries = int(args.points), int(args.queries)
    result = {"meta": run_meta, "reference": run_reference, "measure": run_measure}[args.what](args)
    print(json.dumps({"what": args.what, "case": args.case, "lib": args.lib, "points": args.points,
                      "queries": args.queries, **result, "process_peak_mb": peak_mb()}))
    sys.stdout.flush()


if __name__ == "__main__":
    main()
