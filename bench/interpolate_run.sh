#!/usr/bin/env bash
# hullkit.interpolate against scipy.interpolate (Debian's scipy, /usr/bin/python3), side by side in one
# run; writes bench/results-interpolate.md. Each row is one fresh process (bench/interpolate_bench.py):
# build + first call (the headline), a second call on the same object beside it (warm):
#   1. LinearNDInterpolator 2D, 1e6 uniform points in the unit square, 1e6 uniform queries;
#      target hullkit <= 0.01x scipy;
#   2. LinearNDInterpolator 3D, 2e5 uniform points in the unit cube, 1e6 queries; target <= 0.02x;
#   3. CloughTocher2DInterpolator 2D, 1e6 points, 1e6 queries; target <= 0.02x;
#   4. NearestNDInterpolator 2D, 1e6 points, 1e6 queries (no target).
# Also NaN results inside the hull (hullkit must have none), the largest |hullkit - scipy| where both
# are finite, and each process's peak RSS. scipy's linear calls take minutes at these sizes (~290 s
# for the 2D queries: its walk from triangle to triangle), so in the full run scipy's linear and cubic rows are
# one process with no warm call, between hullkit's three; the nearest rows alternate, 3 processes each.
# Environment: HULLKIT_BENCH_QUICK=1 (a tenth of the points and queries, one process each, warm calls
# for all; report in bench/out/interpolate/results-interpolate.md), HULLKIT_BENCH_NO_BUILD=1 (use
# build/python-bench-venv as it is), HULLKIT_BENCH_VENV=DIR (use that venv as it is, e.g.
# build/python-venv; no build).
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
quick=${HULLKIT_BENCH_QUICK:-0}
work=bench/out/interpolate
mkdir -p "$work"
say() { printf 'interpolate bench: %s\n' "$*" >&2; }

venv=${HULLKIT_BENCH_VENV:-build/python-bench-venv}
if [ -z "${HULLKIT_BENCH_VENV:-}" ] && { [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ] || [ ! -x "$venv/bin/python" ]; }; then
  # As bench/python_run.sh, but python/build is kept: pip builds in it incrementally (CMake), and
  # another install from ./python may be using it.
  say "installing hullkit from ./python into $venv (Debian's /usr/bin/python3, its numpy and scipy)"
  rm -rf "$venv"
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  HULLKIT_BUILD_JOBS=$(nproc) "$venv/bin/pip" install --quiet --no-build-isolation --no-index ./python
fi
"$venv/bin/python" -c 'import hullkit.interpolate' || { say "$venv has no hullkit.interpolate"; exit 1; }
hullkit_py() { "$venv/bin/python" bench/interpolate_bench.py "$@"; }
scipy_py() { /usr/bin/python3 bench/interpolate_bench.py "$@"; }

if [ "$quick" = 1 ]; then
  scale=10 procs=1 scipy_calls=2
  report=$work/results-interpolate.md results=$work/results-quick.jsonl
else
  scale=1 procs=3 scipy_calls=1
  report=bench/results-interpolate.md results=$work/results.jsonl
fi
rm -f "$work"/*.npy
hullkit_py meta $([ "$quick" = 1 ] && echo --quick) > "$results"
record() { tee -a "$results" >&2; }

# case, points, queries (full sizes)
cases=("linear-2d 1000000 1000000" "linear-3d 200000 1000000" "cubic-2d 1000000 1000000" "nearest-2d 1000000 1000000")
for c in "${cases[@]}"; do
  read -r case n m <<< "$c"
  sizes=(--case "$case" --points $((n / scale)) --queries $((m / scale)) --dir "$work")
  say "[$case] the queries inside the hull, exactly ($((n / scale)) points, $((m / scale)) queries)"
  hullkit_py reference "${sizes[@]}" | record
  for ((k = 1; k <= procs; k++)); do
    say "[$case] hullkit, process $k"
    hullkit_py measure --lib hullkit "${sizes[@]}" | record
    # scipy: after hullkit's first process (its values are then compared with hullkit's), once for
    # the linear cases in the full run, every time for nearest (a few seconds).
    if [ "$k" = 1 ] || [ "${case%%-*}" = nearest ]; then
      calls=$scipy_calls
      [ "${case%%-*}" = nearest ] && calls=2
      say "[$case] scipy, process $k$([ "$calls" = 1 ] && echo ', no warm call')"
      scipy_py measure --lib scipy --calls "$calls" "${sizes[@]}" | record
    fi
  done
done
rm -f "$work"/*.npy

elapsed=$(($(date +%s) - started))
hullkit_py report --results "$results" --out "$report" --elapsed "$elapsed"
say "all done in $elapsed s"
