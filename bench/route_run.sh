#!/usr/bin/env bash
# The route-checking benchmark, side by side in one run:
#   1. builds hullkit_route_bench (hullkit vs FCL 0.7) in build/bench;
#   2. writes the scenes and routes (bench/make_route_scene.mjs): the scene (~1e5 obstacle
#      triangles, a 1.5e3-vertex traverse) with a mostly-hitting and a mostly-clear route of 100
#      straight legs and route-turn, 100 legs that also turn (0-180 degrees each); the aligned scene
#      (an axis-aligned box traverse, axis-aligned walls and plates among the bunnies) with
#      route-aligned, 100 straight legs, most hitting face-on or edge-on;
#   3. runs hullkit_route_bench on each route (hullkit on one thread; FCL collide at 100 poses per
#      leg; FCL continuousCollide: the default request on straight routes, interp motion with
#      conservative advancement on route-turn; FCL at 2000 poses per leg as the reference; then
#      sanity checks of hullkit's reports against its own static test), one process at a time,
#      plus hullkit's first check with clearance in a fresh process, and the wasm RouteChecker's
#      20-leg re-check in Node (one fresh process per route);
#   4. threads: 10 000 legs (route-hit and route-clear in turn, over again) checked by hullkit with
#      RouteOptions::threads 1 and 2, clearance off and on, each in a fresh process (its first
#      check, then a warm median); prints time(1), time(2), time(2)/time(1) (target <= 0.6) and the
#      efficiency, and fails unless the two reports are identical bit for bit (cmp);
#   5. bench/route_report.mjs writes bench/results-route.md and prints the targets summary.
# Environment:
#   HULLKIT_BENCH_QUICK=1       smoke test: 20 legs, 9 bunnies, 1 run each; the report goes to
#                               bench/out/results-route.md, never over bench/results-route.md
#   HULLKIT_BENCH_THREADS_ONLY=1  step 4 alone (after building and writing the inputs); no report
#   HULLKIT_BENCH_NO_BUILD=1    use the build as it is
#   HULLKIT_BENCH_BUILD_DIR=D   where hullkit_route_bench is built (default build/bench)
#   HULLKIT_BENCH_ROUTES="hit turn"  only these routes in step 3 (of hit clear turn aligned)
#   HULLKIT_BENCH_NO_THREADS=1  skip step 4
# The wasm module is the one wasm/hullkit.js loads (build/wasm); build it first (scripts/build.sh wasm).
set -euo pipefail
cd "$(dirname "$0")/.."
out=bench/out
mkdir -p "$out"
quick=${HULLKIT_BENCH_QUICK:-0}
build=${HULLKIT_BENCH_BUILD_DIR:-build/bench}
started=$(date +%s)
say() { printf '%s\n' "$*" >&2; }

# ---- 1. build
if [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ]; then
  say "route bench: building $build/hullkit_route_bench"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=ON >/dev/null
  cmake --build "$build" -j 2 --target hullkit_route_bench >/dev/null
fi
native_bench=$build/hullkit_route_bench
[ -x "$native_bench" ] || { say "route bench: $native_bench is missing (is libfcl-dev installed?)"; exit 1; }
[ -f build/wasm/hullkit_core.wasm ] || [ "${HULLKIT_BENCH_THREADS_ONLY:-0}" = 1 ] ||
  say "route bench: build/wasm/hullkit_core.wasm is missing: the wasm rows will be empty"

# ---- 2. inputs
if [ "$quick" = 1 ]; then
  node bench/make_route_scene.mjs --quick
  runs=1
else
  node bench/make_route_scene.mjs
  runs=5
fi

# ---- 4. threads (a function: HULLKIT_BENCH_THREADS_ONLY runs it alone)
threads_step() {
  local legs=10000 threads_results=$out/route-threads.jsonl mode flag t
  : >"$threads_results"
  for mode in verdict clearance; do
    flag=$([ "$mode" = verdict ] && echo --no-clearance || true)
    for t in 1 2; do
      say "route bench: threads, $legs legs, $mode, threads=$t (a fresh process)"
      "$native_bench" --scene "$out/route-scene.json" --route "$out/route-hit.json" --route "$out/route-clear.json" \
        --legs "$legs" --threads "$t" $flag --runs "$runs" --dump "$out/route-threads-$mode-$t.txt" >>"$threads_results"
    done
    if ! cmp -s "$out/route-threads-$mode-1.txt" "$out/route-threads-$mode-2.txt"; then
      say "route bench: threads=1 and threads=2 reports differ ($mode): $(cmp "$out/route-threads-$mode-1.txt" "$out/route-threads-$mode-2.txt" 2>&1)"
      return 1
    fi
  done
  say "route bench: threads=1 and threads=2 reports are identical, bit for bit (clearance off and on)"
  node -e '
    const lines = require("fs").readFileSync(process.argv[1], "utf8").trim().split("\n").map((l) => JSON.parse(l));
    const f = (x) => x.toPrecision(3);
    console.log(`threads: ${lines[0].legs} legs (${lines[0].route}), ${lines[0].hardware_threads} hardware threads; first = the first check in a fresh process, warm = median of ${lines[0].runs}`);
    console.log("| clearance | legs not clear | time(1) first / warm | time(2) first / warm | time(2)/time(1) first / warm (target <= 0.6) | efficiency first / warm |");
    console.log("|---|---:|---:|---:|---:|---:|");
    for (const clearance of [false, true]) {
      const [one, two] = [1, 2].map((t) => lines.find((l) => l.threads === t && l.clearance === clearance));
      const ratio = (k) => two[k] / one[k];
      const eff = (k) => one[k] / (2 * two[k]);
      const status = ratio("warm_seconds") <= 0.6 ? "MET" : "NOT MET";
      console.log(`| ${clearance ? "on" : "off"} | ${one.legs_not_clear} | ${f(one.first_seconds)} s / ${f(one.warm_seconds)} s | ${f(two.first_seconds)} s / ${f(two.warm_seconds)} s | ${f(ratio("first_seconds"))} / ${f(ratio("warm_seconds"))} (${status}) | ${(100 * eff("first_seconds")).toFixed(0)}% / ${(100 * eff("warm_seconds")).toFixed(0)}% |`);
    }' "$threads_results"
}
if [ "${HULLKIT_BENCH_THREADS_ONLY:-0}" = 1 ]; then
  threads_step
  exit
fi

# ---- 3. runs (never two at once: the machine has 2 cores)
results=$out/route-results.jsonl
: >"$results"
node bench/route_report.mjs --meta "$quick" >"$out/route-meta.json"
scene_of() { [ "$1" = aligned ] && echo "$out/route-aligned-scene.json" || echo "$out/route-scene.json"; }
routes=${HULLKIT_BENCH_ROUTES:-hit clear turn aligned}
for route in $routes; do
  scene=$(scene_of "$route")
  say "route bench: native, route-$route (hullkit, FCL 100 poses, FCL continuousCollide, FCL 2000-pose reference, checks)"
  if ! timeout 2400 "$native_bench" --scene "$scene" --route "$out/route-$route.json" --runs "$runs" \
      >>"$results" 2>"$out/route-last-stderr.log"; then
    say "route bench: hullkit_route_bench failed on route-$route: $(tail -c 300 "$out/route-last-stderr.log")"
  fi
  say "route bench: native, route-$route, hullkit's first check with clearance (a fresh process)"
  timeout 600 "$native_bench" --scene "$scene" --route "$out/route-$route.json" --first-call \
    >>"$results" 2>"$out/route-last-stderr.log" ||
    say "route bench: the first-call run failed on route-$route: $(tail -c 300 "$out/route-last-stderr.log")"
done
if [ -f build/wasm/hullkit_core.wasm ]; then
  for route in $routes; do
    say "route bench: wasm RouteChecker, 20 legs of route-$route (Node $(node --version))"
    timeout 600 node bench/route_wasm_bench.mjs --scene "$(scene_of "$route")" --route "$out/route-$route.json" --legs 20 \
      >>"$results" 2>"$out/route-last-stderr.log" ||
      say "route bench: the wasm run failed on route-$route: $(tail -c 300 "$out/route-last-stderr.log")"
  done
fi
rm -f "$out/route-last-stderr.log"
if [ "${HULLKIT_BENCH_NO_THREADS:-0}" != 1 ]; then
  threads_step || say "route bench: the threads step failed"
fi

# ---- 5. report
elapsed=$(($(date +%s) - started))
say "route bench: done in ${elapsed} s"
node bench/route_report.mjs --elapsed "$elapsed" "$out/route-meta.json" "$results"
