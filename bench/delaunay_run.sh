#!/usr/bin/env bash
# The Delaunay benchmark, side by side in one go, and its report:
#   1. builds hullkit_delaunay_bench (hullkit vs CGAL) in build/bench and, if the core changed since,
#      the wasm module (scripts/build.sh wasm);
#   2. writes the 2D inputs to bench/out/delaunay/ (bench/delaunay_inputs.mjs; kept when there);
#   3. runs every implementation x input, one process each, one after the other (never two at once:
#      the machine has 2 cores), collecting JSON lines in bench/out/delaunay/results.jsonl:
#        native  hullkit-incremental, cgal (build/bench/hullkit_delaunay_bench: first call + warm median);
#                hullkit-incremental again with --threads 1 (kind native-1thread)
#                qdelaunay Qt i (Qhull's command, timed whole, reading the same points as text;
#                each run is a fresh process, so every run is a first call)
#        js      hullkit-incremental (wasm), delaunator (bench/delaunay_wasm_bench.mjs)
#   4. bench/delaunay_report.mjs writes bench/results-delaunay.md and prints the targets summary.
# Environment:
#   HULLKIT_BENCH_QUICK=1     smoke test: 1e4 points, 3 runs each (the report says so)
#   HULLKIT_BENCH_NO_BUILD=1  use the built binaries as they are
#   HULLKIT_BENCH_BUILD=DIR   the native build directory (default build/bench)
set -euo pipefail
cd "$(dirname "$0")/.."
out=bench/out/delaunay
mkdir -p "$out"
quick=${HULLKIT_BENCH_QUICK:-0}
build=${HULLKIT_BENCH_BUILD:-build/bench}
started=$(date +%s)
say() { printf '%s\n' "$*" >&2; }

# ---- 1. build
if [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ]; then
  say "delaunay bench: building $build"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=ON >/dev/null
  cmake --build "$build" -j 2 --target hullkit_delaunay_bench >/dev/null
  wasm=build/wasm/hullkit_core.wasm
  if [ ! -f "$wasm" ] || [ -n "$(find native/src native/include wasm CMakeLists.txt -newer "$wasm" -type f 2>/dev/null | head -n 1)" ]; then
    say "delaunay bench: the core changed since the wasm build: bash scripts/build.sh wasm"
    bash scripts/build.sh wasm >/dev/null
  fi
fi
case $build in /*) native_bench=$build/hullkit_delaunay_bench ;; *) native_bench=$PWD/$build/hullkit_delaunay_bench ;; esac
[ -x "$native_bench" ] || { say "delaunay bench: $native_bench is missing (unset HULLKIT_BENCH_NO_BUILD)"; exit 1; }

# ---- 2. inputs
if [ "$quick" = 1 ]; then
  node bench/delaunay_inputs.mjs --quick
  inputs=(uniform-1e4 gaussian-1e4 grid-1e4 circle-1e4)
else
  node bench/delaunay_inputs.mjs
  inputs=(uniform-1e5 gaussian-1e5 grid-1e5 circle-1e5 uniform-1e6 gaussian-1e6 grid-1e6)
fi

# runs_for INPUT [qdelaunay]: 5 at 1e6 (3 for qdelaunay, ~15 s a run), 7 at 1e5, 3 in quick mode.
runs_for() {
  if [ "$quick" = 1 ]; then echo 3; return; fi
  case $1 in
    *-1e6) [ "${2:-}" = qdelaunay ] && echo 3 || echo 5 ;;
    *) echo 7 ;;
  esac
}

results=$out/results.jsonl
: >"$results"

# record KIND LINE: tags a result line with its kind, appends it and prints a progress line.
record() {
  local line
  line=$(node -e 'const r = JSON.parse(process.argv[1]); r.kind = process.argv[2]; console.log(JSON.stringify(r))' "$2" "$1")
  printf '%s\n' "$line" >>"$results"
  node -e '
    const r = JSON.parse(process.argv[1]);
    const f = (s) => (s == null ? "-" : `${s.toPrecision(3)} s`);
    console.error(`delaunay bench: ${r.kind} ${r.impl} ${r.input}: ` +
      (r.error ? `error: ${r.error}` : `first ${f(r.first)}, warm ${f(r.warm)}, ${r.triangles} triangles, ${r.peak_rss_mb?.toFixed(0)} MB`));
  ' "$line"
}

# run_line IMPL INPUT CMD...: runs one process (stopped after 10 minutes) and prints its JSON line,
# or an error line when it printed none.
run_line() {
  local impl=$1 input=$2 line status=0
  shift 2
  line=$(timeout 600 "$@" 2>"$out/last_stderr.log") || status=$?
  line=$(printf '%s\n' "$line" | grep '^{' | tail -n 1 || true)
  if [ -z "$line" ]; then
    local why="exit status $status"
    [ "$status" = 124 ] && why="stopped after 600 s"
    line=$(node -e 'const [impl, input, error] = process.argv.slice(1); console.log(JSON.stringify({ impl, input, error }))' \
      "$impl" "$input" "$why: $(tail -c 300 "$out/last_stderr.log" | tr '\n' ' ')")
  fi
  printf '%s\n' "$line"
}

# qdelaunay_line INPUT RUNS: times `qdelaunay Qt i` as a whole command (parse, triangulate, write
# the triangles to /dev/null) RUNS times, with /usr/bin/time for elapsed seconds and peak memory.
qdelaunay_line() {
  local input=$1 runs=$2 times=() peak=0 k status
  for ((k = 0; k < runs; k++)); do
    status=0
    /usr/bin/time -f '%e %M' -o "$out/qdelaunay.time" timeout 600 qdelaunay Qt i <"$out/$input.txt" >"$out/qdelaunay.out" 2>"$out/last_stderr.log" || status=$?
    if [ "$status" != 0 ]; then
      node -e 'const [input, error] = process.argv.slice(1); console.log(JSON.stringify({ impl: "qdelaunay", input, error }))' \
        "$input" "exit status $status: $(tail -c 300 "$out/last_stderr.log" | tr '\n' ' ')"
      return
    fi
    read -r seconds kb <"$out/qdelaunay.time"
    times+=("$seconds")
    ((kb > peak)) && peak=$kb
  done
  local triangles
  triangles=$(head -n 1 "$out/qdelaunay.out")
  node -e '
    const [input, triangles, peak, ...runs] = process.argv.slice(1);
    const t = runs.map(Number);
    const later = t.slice(1).sort((a, b) => a - b);
    const m = later.length;
    const warm = m === 0 ? null : m % 2 ? later[(m - 1) / 2] : (later[m / 2 - 1] + later[m / 2]) / 2;
    console.log(JSON.stringify({ impl: "qdelaunay", input, first: t[0], runs: t, warm, triangles: Number(triangles),
      peak_rss_mb: Number(peak) / 1024, detail: "qdelaunay Qt i < FILE.txt > /dev/null, whole command (parsing and output included)" }));
  ' "$input" "$triangles" "$peak" "${times[@]}"
  rm -f "$out/qdelaunay.out" "$out/qdelaunay.time"
}

say "delaunay bench: native runs"
for input in "${inputs[@]}"; do
  for impl in hullkit-incremental cgal; do
    record native "$(run_line "$impl" "$input" "$native_bench" --impl "$impl" --input "$out/$input.bin" --runs "$(runs_for "$input")" --budget 60)"
  done
  # The library's default takes a second thread for the output stage of large inputs; the same with
  # one thread, for reference (CGAL's insert is single-threaded).
  record native-1thread "$(run_line hullkit-incremental "$input" "$native_bench" --impl hullkit-incremental --threads 1 --input "$out/$input.bin" --runs "$(runs_for "$input")" --budget 60)"
  record native "$(qdelaunay_line "$input" "$(runs_for "$input" qdelaunay)")"
done

say "delaunay bench: JavaScript runs (Node $(node --version))"
for input in "${inputs[@]}"; do
  for impl in hullkit-incremental delaunator; do
    record js "$(run_line "$impl" "$input" node --expose-gc bench/delaunay_wasm_bench.mjs --impl "$impl" --input "$out/$input.bin" --runs "$(runs_for "$input")" --budget 60)"
  done
done
rm -f "$out/last_stderr.log"

elapsed=$(($(date +%s) - started))
say "delaunay bench: all runs done in ${elapsed} s"
node bench/delaunay_report.mjs --quick "$quick" --elapsed "$elapsed" "$results"
