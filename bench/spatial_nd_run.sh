#!/usr/bin/env bash
# hullkit.spatial against scipy.spatial (Qhull) in 4 to 7 dimensions, side by side in one run;
# writes bench/results-spatial-nd.md. Every figure is the first call in a fresh process
# (bench/spatial_nd_bench.py), the contenders alternating, medians over 3 processes. No target of
# its own (issue 30 asks for scipy's classes in these dimensions; the figures say what they cost).
# Environment: HULLKIT_BENCH_QUICK=1 (smaller inputs, one process each; the report goes to
# bench/out/spatial-nd/), HULLKIT_BENCH_NO_BUILD=1 (use build/python-bench-venv as it is).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
quick=${HULLKIT_BENCH_QUICK:-0}
work=bench/out/spatial-nd
mkdir -p "$work"
say() { printf 'spatial-nd bench: %s\n' "$*" >&2; }
. bench/python_venv.sh
py() { (cd build && "../$venv/bin/python" ../bench/spatial_nd_bench.py "$@"); }
if [ "$quick" = 1 ]; then
  procs=1 scale=10 report=$work/results-spatial-nd.md
else
  procs=3 scale=1 report=bench/results-spatial-nd.md
fi
results=$work/results.jsonl
: > "$results"
# what dim n: Delaunay of uniform points, ConvexHull of Gaussian ones, Voronoi of uniform ones (and
# with each cell's volume: scipy's users take the ConvexHull of each region).
rows=("delaunay 4 20000" "delaunay 5 3000" "delaunay 6 600" "delaunay 7 150"
      "hull 4 200000" "hull 5 50000" "hull 6 10000" "voronoi 4 5000" "volumes 4 2000" "volumes 5 500")
for ((k = 0; k < procs; k++)); do
  for row in "${rows[@]}"; do
    read -r what dim n <<< "$row"
    n=$((n / scale))
    for lib in hullkit scipy; do
      say "[$what ${dim}D] $lib $n points, process $((k + 1))"
      py "$what" --lib "$lib" --dim "$dim" --n "$n" | tee -a "$results" >&2
    done
  done
done
elapsed=$(($(date +%s) - started))
"$venv/bin/python" - "$results" "$report" "$elapsed" <<'PY'
import json, platform, statistics, subprocess, sys, time
import numpy, scipy
results, report, elapsed = sys.argv[1], sys.argv[2], int(sys.argv[3])
rows = [json.loads(line) for line in open(results) if line.strip()]
commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
out = ["# hullkit.spatial against scipy.spatial above 3 dimensions", "",
       f"Written by `bash bench/spatial_nd_run.sh` on {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} in {elapsed // 60} min {elapsed % 60} s; "
       f"hullkit at {commit} plus the working tree (pip, -O3), Python {platform.python_version()}, numpy {numpy.__version__}, scipy {scipy.__version__} (Qhull). "
       "Each figure is the first call in a fresh process, hullkit and scipy alternating; medians, every run listed. "
       "\"same\": the same set of simplices (Voronoi: of ridges) from both. 2 shared cores: compare ratios.", "",
       "| call | points | hullkit | scipy | hullkit ÷ scipy | simplices (ridges) hullkit / scipy | same | runs hullkit | runs scipy |",
       "|---|---:|---:|---:|---:|---:|---|---|---|"]
def runs(rs):
    return ", ".join(format(r["seconds"], ".3g") for r in rs)
keys = []
for r in rows:
    key = (r["what"], r["dim"], r["n"])
    if key not in keys:
        keys.append(key)
names = {"delaunay": "Delaunay, uniform", "hull": "ConvexHull, Gaussian", "voronoi": "Voronoi, uniform (vertices; ridges compared)",
         "volumes": "Voronoi with cell volumes (bounded cells; volumes compared to 8 digits)"}
for what, dim, n in keys:
    h = [r for r in rows if (r["what"], r["dim"], r["n"], r["lib"]) == (what, dim, n, "hullkit")]
    s = [r for r in rows if (r["what"], r["dim"], r["n"], r["lib"]) == (what, dim, n, "scipy")]
    if not h or not s:
        continue
    mh, ms = statistics.median(r["seconds"] for r in h), statistics.median(r["seconds"] for r in s)
    same = "yes" if len({r["set"] for r in h + s}) == 1 else "no"
    count = f"{h[0].get('ridges', h[0]['count'])} / {s[0].get('ridges', s[0]['count'])}"
    out.append(f"| {names[what]}, {dim}D | {n} | {mh:.3g} s | {ms:.3g} s | {mh / ms:.2f} | {count} | {same} | "
               f"{runs(h)} | {runs(s)} |")
out += ["", "Voronoi ridges differ where Qhull leaves out unbounded ridges around a hull edge with one or two simplices "
        "(listed by hullkit: they are 3-dimensional all the same; docs/python.md).", "",
        "Cell volumes: hullkit's `Voronoi.volumes` (each cell a signed sum of orthoschemes over the Delaunay "
        "triangulation's faces, hullkit::voronoi_nd_volumes); for scipy, `ConvexHull(vor.vertices[region]).volume` "
        "for each bounded region, inf for the others, as scipy's users write it.", "",
        f"Raw figures: `{results}` (one JSON line per process)."]
open(report, "w").write("\n".join(out) + "\n")
print(f"spatial-nd bench: wrote {report}", file=sys.stderr)
PY
say "all done in $elapsed s"
