#!/usr/bin/env bash
# The 3D Delaunay benchmark (issue 29, "Lifting one dimension up"), side by side in one go, and its
# report:
#   1. builds hullkit_delaunay3_bench (hullkit vs CGAL, and the counter of the other programs'
#      tetrahedra) and the hullkit command in build/bench, and the wasm module (scripts/build.sh
#      wasm: incremental);
#   2. writes the inputs to bench/out/delaunay3/ (bench/delaunay3_inputs.mjs; kept when there);
#   3. finds a Python whose hullkit package has delaunay3 (build/python-bench-venv, which
#      bench/python_run.sh installs, or build/python-venv, scripts/python_test.sh's); without one
#      the Python rows say "pending";
#   4. bench/delaunay3_run.mjs runs every implementation x input, one process at a time, into
#      bench/out/delaunay3/results.jsonl (quick mode: results-quick.jsonl):
#        native   hullkit with 1 and 2 threads, CGAL's Delaunay_triangulation_3 (first call in a fresh
#                 process, warm median beside it; peak memory of the whole process)
#        command  hullkit delaunay3 FILE -o OUT.ele (text in, .ele and .node out), tetgen -NEFQ
#                 FILE.node (and -NFQ once, writing the .ele that is counted), qdelaunay Qt i;
#                 every run a fresh process, timed whole
#        python   scipy.spatial.Delaunay (Debian's /usr/bin/python3), hullkit.delaunay3
#        wasm     the public delaunay3() of wasm/hullkit.js in Node
#      and counts every result's tetrahedra, flat ones (exactly) and whether the set is hullkit's;
#   5. bench/delaunay3_report.mjs writes bench/results-delaunay3.md and prints the targets summary.
# Environment:
#   HULLKIT_BENCH_QUICK=1     smoke test: the 1e5 inputs, 3 runs, uniform-1e6 for the memory test;
#                             the report goes to bench/out/delaunay3/results-delaunay3.md
#   HULLKIT_BENCH_NO_BUILD=1  use the built binaries as they are
#   HULLKIT_BENCH_BUILD=DIR   the native build directory (default build/bench)
#   HULLKIT_BENCH_QDELAUNAY_TIMEOUT=S  stop a qdelaunay run after S seconds (default 300)
#   HULLKIT_BENCH_FRESH_ROUNDS=K  fresh processes per native library call, and per Python call on the
#                             target's input, taken in turns (default 3;
#                             quick mode 1 unless this is set)
set -euo pipefail
cd "$(dirname "$0")/.."
out=bench/out/delaunay3
mkdir -p "$out"
quick=${HULLKIT_BENCH_QUICK:-0}
build=${HULLKIT_BENCH_BUILD:-build/bench}
no_build=${HULLKIT_BENCH_NO_BUILD:-0}
started=$(date +%s)
say() { printf 'delaunay3 bench: %s\n' "$*" >&2; }

# ---- 1. build
if [ "$no_build" != 1 ]; then
  say "building $build (hullkit_delaunay3_bench, hullkit) and the wasm module"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=ON >/dev/null
  cmake --build "$build" -j 2 --target hullkit_delaunay3_bench hullkit >/dev/null
  bash scripts/build.sh wasm >/dev/null
fi
native=$(cd "$build" && pwd)
for program in hullkit_delaunay3_bench hullkit; do
  [ -x "$native/$program" ] || { say "$native/$program is missing (unset HULLKIT_BENCH_NO_BUILD)"; exit 1; }
done

# ---- 2. inputs
if [ "$quick" = 1 ]; then node bench/delaunay3_inputs.mjs --quick; else node bench/delaunay3_inputs.mjs; fi

# ---- 3. Python: the first virtual environment whose hullkit has delaunay3 (run from build/, so
# that the installed package is imported, not ./python's sources). Nothing is installed here:
# bench/python_run.sh (just before this in `npm run bench`) and scripts/python_test.sh install ./python
# into their environments, and share python/build while they do.
has_delaunay3() {
  [ -x "$1" ] && (cd build && "$1" -c 'import sys, hullkit; sys.exit(not callable(getattr(hullkit, "delaunay3", None)))') 2>/dev/null
}
python=/usr/bin/python3  # no hullkit there: its rows say "pending" and why
for venv in build/python-bench-venv build/python-venv; do
  if has_delaunay3 "$PWD/$venv/bin/python"; then python=$PWD/$venv/bin/python; break; fi
done
say "Python rows: scipy with /usr/bin/python3, hullkit with $python"

# ---- 4. the runs
results=$out/results.jsonl
[ "$quick" = 1 ] && results=$out/results-quick.jsonl  # never over a full run's results
node bench/delaunay3_run.mjs --native "$native" --python "$python" --quick "$quick" "$results"

# ---- 5. the report
elapsed=$(($(date +%s) - started))
say "all runs done in ${elapsed} s"
node bench/delaunay3_report.mjs --elapsed "$elapsed" "$results"
