#!/usr/bin/env bash
# The Python package's benchmark (issue 15), side by side in one run; writes
# bench/results-python.md. Every figure is the first call in a fresh process
# (bench/python_bench.py, one process per measurement, contenders alternating):
#   1. hullkit.spatial.ConvexHull against scipy.spatial.ConvexHull, 1e6 points on a sphere;
#      target hullkit <= 0.2x scipy;
#   2. hullkit.spatial.Delaunay against scipy.spatial.Delaunay, 1e6 uniform 2D points; target
#      <= 0.1x scipy;
#   3. hullkit.hull's time outside the C++ core (converting the input, wrapping the output), for
#      float64 C input and float32 Fortran input; target <= 5%;
#   4. the hull of 1e8 points in a ball as 16 binary PLY files: hullkit.dask.hull on a local
#      cluster of 2 worker processes (1 thread each) against one process doing the same work on
#      one thread; targets <= 0.65x, identical result, peak memory per worker <= 400 MB;
#   5. 10 000 route legs (the route benchmark's scenes, bench/make_route_scene.mjs):
#      hullkit.dask.check_routes on the 2-worker cluster against one process, one thread
#      (5 processes each; beside them, the same call with send_scene=True); target <= 0.65x,
#      identical reports. Four kinds of work: the benchmark's route as routes of 10 legs (the
#      target's row) and as one route, the same scene with mostly hitting legs, the aligned scene
#      (little checking per leg).
# Environment: HULLKIT_BENCH_QUICK=1 (a tenth of the sizes, one process each; the report goes to
# bench/out/python/results-python.md), HULLKIT_BENCH_NO_BUILD=1 (use build/python-bench-venv as
# it is).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
quick=${HULLKIT_BENCH_QUICK:-0}
work=bench/out/python
mkdir -p "$work"
say() { printf 'python bench: %s\n' "$*" >&2; }
cleanup() { rm -rf "$work/ply"; }
trap cleanup EXIT

. bench/python_venv.sh
py() { (cd build && "../$venv/bin/python" ../bench/python_bench.py "$@"); }

if [ "$quick" = 1 ]; then
  n_hull=100000 n_del=100000 n_half=10000 n_files=10000000 legs=1000 procs=1 route_procs=1
  report=$work/results-python.md results=$work/results-quick.jsonl
else
  n_hull=1000000 n_del=1000000 n_half=100000 n_files=100000000 legs=10000 procs=3 route_procs=5
  report=bench/results-python.md results=$work/results.jsonl
fi
: > "$results"
record() { tee -a "$results" >&2; }

for ((k = 0; k < procs; k++)); do
  for lib in hullkit scipy; do
    say "[hull] $lib $n_hull on a sphere, process $((k + 1))"
    py hull --lib "$lib" --n "$n_hull" | record
    say "[delaunay] $lib $n_del uniform, process $((k + 1))"
    py delaunay --lib "$lib" --n "$n_del" | record
    say "[halfspace] $lib $n_half planes tangent to a sphere, process $((k + 1))"
    py halfspace --lib "$lib" --n "$n_half" | record
    say "[voronoi] $lib $n_del uniform 2D, process $((k + 1))"
    py voronoi --lib "$lib" --n "$n_del" | record
  done
  for kind in "float64 C" "float32 Fortran"; do
    say "[conversions] $kind, process $((k + 1))"
    py conversions --lib "$kind" --n "$n_hull" | record
  done
done

say "[files] writing $n_files points in a ball as 16 binary PLY files"
py write-ply --n "$n_files" --files 16 --dir "../$work/ply" | record
for mode in single dask dask single; do
  [ "$quick" = 1 ] && [ "$mode" = single ] && [ -n "${did_single:-}" ] && continue
  say "[files] $mode"
  py files --mode "$mode" --dir "../$work/ply" | record
  did_single=1
done

if [ ! -f bench/out/route-scene.json ]; then
  say "[routes] writing the route benchmark's scene"
  node bench/make_route_scene.mjs
fi
# Four kinds of work with the same number of legs: the benchmark's route as routes of 10 legs
# (mostly clear legs, the target's row) and as one route (its legs cut between the workers), the
# same scene with mostly hitting legs, and the aligned scene (125 small boxes, a tenth of the
# checking: Dask's fixed cost per call shows).
works=("route-scene.json route-clear.json" "route-scene.json route-clear.json --one-route"
       "route-scene.json route-hit.json" "route-aligned-scene.json route-aligned.json")
for ((k = 0; k < route_procs; k++)); do
  for work in "${works[@]}"; do
    read -r scene route one <<< "$work"
    modes="single dask"
    [ "$route" = route-clear.json ] && [ -z "$one" ] && modes="single dask dask-send"
    for mode in $modes; do
      say "[routes] $route ${one:-}, $mode $legs legs, process $((k + 1))"
      py routes --mode "$mode" --legs "$legs" --scene "../bench/out/$scene" --route "../bench/out/$route" $one | record
    done
  done
done

elapsed=$(($(date +%s) - started))
"$venv/bin/python" - "$results" "$report" "$elapsed" <<'EOF'
import json, platform, statistics, subprocess, sys, time
results, report, elapsed = sys.argv[1], sys.argv[2], int(sys.argv[3])
rows = [json.loads(line) for line in open(results) if line.strip()]
def pick(**kw):
    return [r for r in rows if all(r.get(k) == v for k, v in kw.items())]
def med(rs, key="seconds"):
    return statistics.median(r[key] for r in rs) if rs else float("nan")
def runs(rs, key="seconds"):
    return ", ".join(f"{r[key]:.3g}" for r in rs)
def status(ok):
    return "met" if ok else "not met"
commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
import numpy, scipy, dask, distributed
out = [f"# Python package benchmark (issue 15)", "",
       f"Written by `bash bench/python_run.sh` on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} in {elapsed // 60} min {elapsed % 60} s. "
       f"hullkit at commit {commit} plus the working tree, built by pip from ./python (-O3, -ffp-contract=off); Python {platform.python_version()}, "
       f"numpy {numpy.__version__}, scipy {scipy.__version__} (Qhull), dask {dask.__version__}, distributed {distributed.__version__} (Debian). "
       "Every figure is the first call in a fresh process (bench/python_bench.py), the contenders alternating; medians over processes, every run listed. "
       "The machine has 2 cores and is shared: compare ratios.", ""]
out += ["## 1. scipy.spatial against hullkit.spatial", "",
        "| call | points | hullkit | scipy | hullkit ÷ scipy | target | same answer | runs hullkit | runs scipy |",
        "|---|---:|---:|---:|---:|---|---|---|---|"]
for what, target, key, label in (("hull", 0.2, "vertex_set", "ConvexHull, on a sphere"), ("delaunay", 0.1, "triangle_set", "Delaunay, uniform 2D"),
                                  ("halfspace", None, "vertex_set", "HalfspaceIntersection, planes tangent to a sphere (3D)"),
                                  ("voronoi", 0.05, "vertex_set", "Voronoi, uniform 2D (hullkit with cell areas; its lists on first use)")):
    h, s = pick(what=what, lib="hullkit"), pick(what=what, lib="scipy")
    ratio = med(h) / med(s)
    same = "yes" if h and s and len({r[key] for r in h + s}) == 1 else "no"
    goal = "no target" if target is None else f"<= {target}, {status(ratio <= target)}"
    out.append(f"| {label} | {h[0]['n'] if h else '-'} | {med(h):.3g} s | {med(s):.3g} s | {ratio:.3f} | {goal} | {same} | {runs(h)} | {runs(s)} |")
vh, vs = pick(what="voronoi", lib="hullkit"), pick(what="voronoi", lib="scipy")
if vh and vs:
    whole = statistics.median(r["with_lists"] for r in vh)
    out.append(f"| Voronoi, the same, with hullkit's regions and ridge_vertices lists made too | {vh[0]['n']} | {whole:.3g} s | {med(vs):.3g} s | "
               f"{whole / med(vs):.3f} | no target | | {runs(vh, 'with_lists')} | |")
conv = pick(what="conversions")
out += ["", "## 2. Time outside the core", "",
        "The first `hullkit.hull(points)` of a process timed in its parts, 1e6 points on a sphere: converting the input (`as_points`: nothing to do for float64 C input, one converting copy for float32 Fortran), the C++ core, and wrapping its arrays (`Hull`: numpy arrays that take over the core's vectors). \"outside\" = (convert + wrap) / whole. Target: <= 5%.", "",
        "| input | whole, median | convert | core | wrap | outside, median | target |", "|---|---:|---:|---:|---:|---:|---|"]
for name in ("float64 C", "float32 Fortran"):
    rs = [r for r in conv if r.get("kind") == name]
    if rs:
        m = lambda key: statistics.median(r[key] for r in rs)
        out.append(f"| {name} | {m('whole'):.3g} s | {m('convert') * 1e3:.3g} ms | {m('core'):.3g} s | {m('wrap') * 1e3:.3g} ms | {100 * m('outside'):.2f}% | <= 5%, {status(m('outside') <= 0.05)} |")
files = pick(what="files")
single, dsk = [r for r in files if r["mode"] == "single"], [r for r in files if r["mode"] == "dask"]
written = pick(what="write-ply")
if files:
    ratio = med(dsk) / med(single)
    same = "yes" if len({(r["triangles"], r["volume_bits"]) for r in files}) == 1 else "no"
    worker_peak = max(max(r["peak_mb"]) for r in dsk) if dsk else float("nan")
    out += ["", "## 3. Hull of files across a cluster", "",
            f"{written[0]['points'] if written else '?'} points in a ball as {written[0]['files'] if written else '?'} binary little-endian float64 PLY files ({(written[0]['bytes'] / 1e9) if written else 0:.2f} GB). "
            "dask: `hullkit.dask.hull(files, client)` on `LocalCluster(n_workers=2, threads_per_worker=1, processes=True)` (cluster start not timed); "
            "single: one process doing the same work on one thread (each file streamed into its own HullBuilder, then the merge). "
            "Peak memory: each worker process's peak RSS (ru_maxrss), Python, numpy and distributed included.", "",
            "| run | wall, median | runs | peak RSS |", "|---|---:|---|---|",
            f"| single process, 1 thread | {med(single):.3g} s | {runs(single)} | {max(r['peak_mb'][0] for r in single):.0f} MB |",
            f"| dask, 2 workers | {med(dsk):.3g} s | {runs(dsk)} | workers {', '.join(f'{m:.0f}' for r in dsk for m in r['peak_mb'])} MB |",
            "", "| target | figure | status |", "|---|---:|---|",
            f"| dask <= 0.65 × single | {ratio:.3f} | {status(ratio <= 0.65)} |",
            f"| identical result (triangles, volume bits) | {same} | {status(same == 'yes')} |",
            f"| peak memory per worker <= 400 MB | {worker_peak:.0f} MB | {status(worker_peak <= 400)} |"]
routes = pick(what="routes")
works = [("route-scene.json", "route-clear.json", False, "the benchmark's route: routes of 10 legs cycling through route-clear.json's waypoints among the bunnies (the target's row)"),
         ("route-scene.json", "route-clear.json", True, "the same legs as one route (cut between the workers' tasks, the reports joined)"),
         ("route-scene.json", "route-hit.json", False, "the same scene, route-hit.json's waypoints: most legs hit a bunny"),
         ("route-aligned-scene.json", "route-aligned.json", False, "the aligned scene: 125 axis-aligned boxes, legs along the corridors (a tenth of the checking per leg)")]
if routes:
    out += ["", "## 4. Route batches across a cluster", "",
            f"{routes[0]['legs']} legs for each of four kinds of work. "
            "single: one RouteChecker, one thread, the whole call including building it; dask: `hullkit.dask.check_routes(scene, routes, client)` on the 2-worker cluster "
            "(cluster start not timed), one checker per worker: each worker reads the scene file itself (the same path; used because its digest matches what the client read); "
            "scene sent: `send_scene=True`, the scene's bytes sent to every worker from the client, as to workers on other machines (not a target, shown beside). "
            "again: the same call a second time in the process (checkers reused).", "",
            "| work | legs not clear | single, first (again) | dask, first (again) | dask ÷ single, first | again | runs single / dask (first) | target <= 0.65, first / again |",
            "|---|---:|---:|---:|---:|---:|---|---|"]
    for scene, route, one, label in works:
        rs = [r for r in routes if r.get("scene") == scene and r.get("route") == route and r.get("one_route", False) == one]
        single, dsk = [r for r in rs if r["mode"] == "single"], [r for r in rs if r["mode"] == "dask"]
        if not single or not dsk:
            continue
        first, again = med(dsk) / med(single), med(dsk, "warm_seconds") / med(single, "warm_seconds")
        out.append(f"| {label} | {rs[0]['not_clear']} | {med(single):.3g} s ({med(single, 'warm_seconds'):.3g}) | {med(dsk):.3g} s ({med(dsk, 'warm_seconds'):.3g}) "
                   f"| {first:.3f} | {again:.3f} | {runs(single)} / {runs(dsk)} | {status(first <= 0.65)} / {status(again <= 0.65)} |")
    sent = [r for r in routes if r["mode"] == "dask-send"]
    clear_single = [r for r in routes if r["mode"] == "single" and r.get("route") == "route-clear.json" and not r.get("one_route")]
    if sent and clear_single:
        out.append(f"| the benchmark's route, scene sent (`send_scene=True`) | {sent[0]['not_clear']} | | {med(sent):.3g} s ({med(sent, 'warm_seconds'):.3g}) "
                   f"| {med(sent) / med(clear_single):.3f} | {med(sent, 'warm_seconds') / med(clear_single, 'warm_seconds'):.3f} | {runs(sent)} | not a target |")
    same = all(len({r["reports"] for r in routes if r.get("route") == route and r.get("one_route", False) == one}) == 1
               for _, route, one, _ in works)
    out += ["", f"Identical reports in every mode and process, for each work: {'yes' if same else 'no'} ({status(same)})."]
out += ["", f"Raw figures: `{results}` (one JSON line per process)."]
open(report, "w").write("\n".join(out) + "\n")
print(f"python bench: wrote {report}", file=sys.stderr)
EOF
say "all done in $elapsed s"
