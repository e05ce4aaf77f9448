#!/usr/bin/env bash
# The route-checking benchmark, side by side in one run:
#   1. builds hullkit_route_bench (hullkit vs FCL 0.7) in build/bench;
#   2. writes the scene and routes (bench/make_route_scene.mjs: ~1e5 obstacle triangles, a
#      1.5e3-vertex traverse, a mostly-hitting and a mostly-clear route of 100 legs);
#   3. runs hullkit_route_bench on each route (hullkit; FCL collide at 100 poses per leg;
#      FCL continuousCollide; FCL at 2000 poses per leg as the reference), one process at a time,
#      and the wasm RouteChecker's 20-leg re-check in Node (one fresh process per route);
#   4. bench/route_report.mjs writes bench/results-route.md and prints the targets summary.
# Environment:
#   HULLKIT_BENCH_QUICK=1       smoke test: 20 legs, 9 bunnies, 1 run each; the report goes to
#                               bench/out/results-route.md, never over bench/results-route.md
#   HULLKIT_BENCH_NO_BUILD=1    use the build as it is
#   HULLKIT_BENCH_BUILD_DIR=D   where hullkit_route_bench is built (default build/bench)
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
[ -f build/wasm/hullkit_core.wasm ] || say "route bench: build/wasm/hullkit_core.wasm is missing: the wasm rows will be empty"

# ---- 2. inputs
if [ "$quick" = 1 ]; then
  node bench/make_route_scene.mjs --quick
  runs=1
else
  node bench/make_route_scene.mjs
  runs=5
fi

# ---- 3. runs (never two at once: the machine has 2 cores)
results=$out/route-results.jsonl
: >"$results"
node bench/route_report.mjs --meta "$quick" >"$out/route-meta.json"
for route in hit clear; do
  say "route bench: native, route-$route (hullkit, FCL 100 poses, FCL continuousCollide, FCL 2000-pose reference)"
  if ! timeout 1200 "$native_bench" --scene "$out/route-scene.json" --route "$out/route-$route.json" --runs "$runs" \
      >>"$results" 2>"$out/route-last-stderr.log"; then
    say "route bench: hullkit_route_bench failed on route-$route: $(tail -c 300 "$out/route-last-stderr.log")"
  fi
done
if [ -f build/wasm/hullkit_core.wasm ]; then
  for route in hit clear; do
    say "route bench: wasm RouteChecker, 20 legs of route-$route (Node $(node --version))"
    timeout 600 node bench/route_wasm_bench.mjs --scene "$out/route-scene.json" --route "$out/route-$route.json" --legs 20 \
      >>"$results" 2>"$out/route-last-stderr.log" ||
      say "route bench: the wasm run failed on route-$route: $(tail -c 300 "$out/route-last-stderr.log")"
  done
fi
rm -f "$out/route-last-stderr.log"

# ---- 4. report
elapsed=$(($(date +%s) - started))
say "route bench: done in ${elapsed} s"
node bench/route_report.mjs --elapsed "$elapsed" "$out/route-meta.json" "$results"
