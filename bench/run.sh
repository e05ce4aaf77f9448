#!/usr/bin/env bash
# Runs the whole benchmark, side by side in one go, and writes the report:
#   1. builds build/bench (hullkit_bench: hullkit vs Qhull vs CGAL) and, if the core changed since,
#      the wasm module (scripts/build.sh wasm);
#   2. writes the inputs to bench/out/ (bench/make_inputs.mjs; kept when already there);
#   3. runs every implementation x input, one process each, one after the other (never two at
#      once: the machine has 2 cores), collecting the JSON lines in bench/out/results.jsonl; the
#      first run of each process is its first call (reported beside the warm median), and the
#      whole command (hullkit hull FILE -o OUT.off vs qconvex o < FILE > OUT.off) runs in a fresh
#      process per run on the text copies of the 1e6 cube and sphere;
#   4. bench/report.mjs turns them into bench/out/results.json, bench/results.md and
#      bench/results.svg and prints the targets summary.
# Environment:
#   HULLKIT_BENCH_QUICK=1   smoke test: 1 run each, no 1e6 inputs (the report then says so)
#   HULLKIT_BENCH_NO_BUILD=1  use build/bench and build/wasm as they are
# `npm run bench` installs the peers and builds everything first, then runs this.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=bench/out
mkdir -p "$out"
quick=${HULLKIT_BENCH_QUICK:-0}
started=$(date +%s)

say() { printf '%s\n' "$*" >&2; }

# ---- 1. build
if [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ]; then
  say "bench: building build/bench"
  cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=ON >/dev/null
  cmake --build build/bench -j 2 --target hullkit_bench hullkit >/dev/null
  wasm=build/wasm/hullkit_core.wasm
  if [ ! -f "$wasm" ] || [ -n "$(find native/src native/include wasm CMakeLists.txt -newer "$wasm" -type f 2>/dev/null | head -n 1)" ]; then
    say "bench: the core changed since the wasm build: bash scripts/build.sh wasm"
    bash scripts/build.sh wasm >/dev/null
  fi
fi
native_bench=$root/build/bench/hullkit_bench
[ -x "$native_bench" ] || { say "bench: $native_bench is missing (unset HULLKIT_BENCH_NO_BUILD)"; exit 1; }

# ---- 2. inputs
node bench/make_inputs.mjs

# ---- 3. runs
results=$out/results.jsonl
: >"$results"
node bench/report.mjs --meta "$quick" >"$out/meta.json"

if [ "$quick" = 1 ]; then
  big=()
  sizes_note="quick"
else
  big=(cube-1e6 ball-1e6 sphere-1e6)
  sizes_note="full"
fi
small=(cube-1e5 ball-1e5 sphere-1e5)
all_inputs=("${small[@]}" "${big[@]}" bunny)

# runs_for INPUT: 5 at 1e6 (more would not fit the time), 7 at 1e5, 21 for the small ones whose
# times are in milliseconds and so most exposed to a noisy machine.
runs_for() {
  if [ "$quick" = 1 ]; then echo 1; return; fi
  case $1 in
    *-1e6) echo 5 ;;
    *-1e5) echo 7 ;;
    *) echo 21 ;;
  esac
}

step=0
# error_line IMPL INPUT MESSAGE: a result line for a process that died or was stopped.
error_line() {
  node -e 'const [impl, input, error] = process.argv.slice(1); console.log(JSON.stringify({ impl, input, error }))' "$1" "$2" "$3"
}

# bench_one KIND IMPL INPUT: runs one process (native or node) and appends its JSON line.
# A process is stopped after 10 minutes whatever happens (each stops itself after ~60 s of runs).
bench_one() {
  local kind=$1 impl=$2 input=$3 line status
  local runs
  runs=$(runs_for "$input")
  step=$((step + 1))
  local cmd
  if [ "$kind" = command ]; then
    # The whole command, one fresh process per run, 3 runs: text file in, OFF file out.
    runs=$([ "$quick" = 1 ] && echo 1 || echo 3)
    cmd=("$native_bench" --impl "$impl" --input "$out/$input.txt" --name "$input" --runs "$runs" --budget 60)
  elif [ "$kind" = native ]; then
    cmd=("$native_bench" --impl "$impl" --input "$out/$input.bin" --runs "$runs" --budget 60)
  else
    cmd=(node bench/wasm_bench.mjs --impl "$impl" --input "$out/$input.bin" --runs "$runs" --budget 60 --cap 60)
  fi
  status=0
  line=$(timeout 600 "${cmd[@]}" 2>"$out/last_stderr.log") || status=$?
  line=$(printf '%s\n' "$line" | grep '^{' | tail -n 1 || true)
  if [ -z "$line" ]; then
    local why="exit status $status"
    [ "$status" = 124 ] && why="stopped after 600 s"
    line=$(error_line "$impl" "$input" "$why: $(tail -c 300 "$out/last_stderr.log" | tr '\n' ' ')")
  fi
  line=$(node -e 'const r = JSON.parse(process.argv[1]); r.kind = process.argv[2]; console.log(JSON.stringify(r))' "$line" "$kind")
  printf '%s\n' "$line" >>"$results"
  node -e '
    const r = JSON.parse(process.argv[1]);
    const t = r.error ? `error: ${r.error}` : r.capped && r.median === null ? `> ${r.cap_seconds} s`
      : `first ${r.first == null ? "> cap" : r.first.toPrecision(3) + " s"}, median ${r.median.toPrecision(3)} s over ${r.runs.length} run(s), ${r.vertices} hull vertices` +
        (r.kind === "command" ? `, peak ${r.peak_rss_mb.toFixed(1)} MB` : "");
    console.error(`bench: [${process.argv[2]}] ${r.kind} ${r.impl} ${r.input}: ${t}`);
  ' "$line" "$step"
}

say "bench: native runs (hullkit_bench)"
for input in "${all_inputs[@]}"; do
  for impl in hullkit-quickhull qhull cgal; do
    bench_one native "$impl" "$input"
  done
done
# Gift wrapping is O(n h): fine on the bunny and on 1e5 points in a cube or a ball, never on the
# sphere inputs where h = n. Its scaling series is n = 1e3 ... 1e5 in a ball.
for input in bunny cube-1e5 ball-1e3 ball-3e3 ball-1e4 ball-3e4 ball-1e5; do
  bench_one native hullkit-giftwrap "$input"
done

say "bench: the whole command: hullkit hull FILE -o OUT.off vs qconvex o < FILE > OUT.off"
if [ "$quick" = 1 ]; then command_inputs=(cube-1e5 sphere-1e5); else command_inputs=(cube-1e6 sphere-1e6); fi
for input in "${command_inputs[@]}"; do
  for impl in command-hullkit command-qconvex; do
    bench_one command "$impl" "$input"
  done
done

say "bench: JavaScript runs (Node $(node --version): hullkit wasm, quickhull3d, three.js)"
for input in "${all_inputs[@]}"; do
  for impl in hullkit-quickhull quickhull3d three; do
    bench_one js "$impl" "$input"
  done
done
for input in bunny cube-1e5; do
  bench_one js hullkit-giftwrap "$input"
done
rm -f "$out/last_stderr.log"

# ---- 4. report
elapsed=$(( $(date +%s) - started ))
say "bench: all runs done in ${elapsed} s ($sizes_note)"
node bench/report.mjs --elapsed "$elapsed" "$out/meta.json" "$results"
