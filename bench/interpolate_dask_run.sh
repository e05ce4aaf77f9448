#!/usr/bin/env bash
# hullkit.dask.interpolate against one process (bench/interpolate_dask_bench.py): 1e8 queries against a
# 1e6-point 2D LinearNDInterpolator, 2 runs of each mode alternating, each in a fresh process; writes
# bench/results-interpolate-dask.md. Target: dask (2 workers) <= 0.65x one process on one thread, the
# same values bit for bit. Environment: HULLKIT_BENCH_QUICK=1 (1e7 queries, 1e5 points, one run each;
# report in bench/out/interpolate-dask/), HULLKIT_BENCH_VENV=DIR (a venv with hullkit installed; default
# build/python-bench-venv, made by bench/python_run.sh or bench/interpolate_run.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
work=bench/out/interpolate-dask
mkdir -p "$work"
say() { printf 'interpolate dask bench: %s\n' "$*" >&2; }
venv=${HULLKIT_BENCH_VENV:-build/python-bench-venv}
"$venv/bin/python" -c 'import hullkit.dask, hullkit.interpolate' || { say "$venv has no hullkit (run bench/interpolate_run.sh first)"; exit 1; }
root=$(pwd)
case "$venv" in /*) ;; *) venv=$root/$venv ;; esac
py() { (cd bench && "$venv/bin/python" interpolate_dask_bench.py "$@"); }
if [ "${HULLKIT_BENCH_QUICK:-0}" = 1 ]; then
  sizes=(--points 100000 --queries 10000000 --block 1000000) runs=1 report=$work/results-interpolate-dask.md
else
  sizes=(--points 1000000 --queries 100000000 --block 2000000) runs=2 report=bench/results-interpolate-dask.md
fi
results=$work/results.jsonl
: > "$results"
for ((k = 1; k <= runs; k++)); do
  for mode in single dask; do
    say "[$mode] run $k"
    py measure --mode "$mode" "${sizes[@]}" | tee -a "$results" >&2
  done
done
py report --results "$root/$results" --out "$root/$report" --elapsed $(($(date +%s) - started)) > /dev/null
cat "$report"
