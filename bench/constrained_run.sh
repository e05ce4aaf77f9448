#!/usr/bin/env bash
# The constrained Delaunay benchmark (issue 31), side by side in one go, and its report:
#   1. builds, in build/bench, hullkit_constrained_cgal_bench (CGAL alone: must build) and
#      hullkit_constrained_bench (CGAL + hullkit's core: when it does not build, e.g. while the core's
#      constrained_delaunay is being written, hullkit's native rows say "not available" and the rest
#      runs); rebuilds the wasm module when the core changed since (scripts/build.sh wasm; a failure
#      leaves the module as it was);
#   2. writes the inputs to bench/out/constrained/ (bench/constrained_inputs.mjs): polygons with holes
#      (lakes, building footprints, repeated vertices, a spiky star, a grid of holes) and a planar
#      straight-line graph (1e6 points, 1e5 segments);
#   3. runs every implementation x input, one process each (the targets' pairs in more, taking turns:
#      HULLKIT_BENCH_FRESH_ROUNDS below), one after the other (never two at once: the machine has 2
#      cores), collecting JSON lines in bench/out/constrained/results.jsonl:
#        native  hullkit (triangulate_polygon / constrained_delaunay), cgal-cdt (CGAL's CDT + nesting
#                levels); on the graph also hullkit with --threads 1 (kind native-1thread); on the
#                polygons the quality meshes with CGAL's angle bound (B = 0.125, about 20.7 degrees):
#                cgal-mesh (Delaunay_mesher_2: time, triangles, smallest angle; not checked) and
#                hullkit-mesh (triangulate_polygon with quality.min_angle), side by side, and the
#                same refinement of a mesh that exists (Triangle's -r): cgal-refine and
#                hullkit-refine (refine_mesh), the triangulation untimed; not on star-1e4 (its 4968
#                needle spikes need about 3.8e7 triangles at that bound)
#        js      hullkit (wasm triangulatePolygon / constrainedDelaunay), earcut, constrainautor
#                (delaunator + @kninnug/constrainautor), cdt2d, poly2tri (bench/constrained_js_bench.mjs)
#      Every triangulation is checked after its timed runs (bench/constrained_common.mjs: exactly the
#      polygon covered once, or the graph's hull with every segment): the JS processes check their
#      own first result; the native ones dump it (--dump) for bench/constrained_check.mjs (hullkit-mesh's and -refine's
#      with --mesh: clockwise, boundary on the rings, area, angles but at small input angles). Each row
#      gets a verdict: ok, wrong (with the reason), exception (a call threw / returned an error),
#      timeout, crash, not available (hullkit's binding or core is not there yet), skipped (a mesh not
#      run, with the reason);
#   4. bench/constrained_report.mjs writes bench/results-constrained.md (quick mode:
#      bench/out/constrained/results-constrained.md) and prints the targets summary.
# Environment:
#   HULLKIT_BENCH_QUICK=1     smoke test: no lake-1e5, graph of 1e4 points / 1e3 segments, 3 runs each,
#                             20 s per process at most (about 2-4 minutes)
#   HULLKIT_BENCH_NO_BUILD=1  use the built binaries and wasm module as they are
#   HULLKIT_BENCH_NO_WASM_BUILD=1  build the native programs but use the wasm module as it is
#   HULLKIT_BENCH_BUILD=DIR   the native build directory (default build/bench)
#   HULLKIT_BENCH_TIMEOUT=S   stop a process after S seconds (default 600; quick 20); the meshes get
#                             a fifth of it, at least 10 s (refinement can run away on tiny input angles)
#   HULLKIT_BENCH_FRESH_ROUNDS=K  fresh processes per quality mesh and refinement, CGAL and hullkit
#                             taking turns, and per polygon of 10^4 vertices and more for the wasm
#                             triangulatePolygon and earcut, taking turns; their headline is the median
#                             of the K first calls (default 7; quick mode 1 unless set). The first
#                             process also gives the warm runs and the checked result. (Seven, not
#                             three: a 10^3-vertex mesh takes a millisecond, and one process in three
#                             meeting a slow moment of this machine moved its ratio from 0.45x to 0.6x.)
set -euo pipefail
cd "$(dirname "$0")/.."
out=bench/out/constrained
mkdir -p "$out"
quick=${HULLKIT_BENCH_QUICK:-0}
build=${HULLKIT_BENCH_BUILD:-build/bench}
if [ "$quick" = 1 ]; then timeout_s=${HULLKIT_BENCH_TIMEOUT:-20}; else timeout_s=${HULLKIT_BENCH_TIMEOUT:-600}; fi
mesh_timeout_s=$((timeout_s / 5 > 10 ? timeout_s / 5 : 10))
fresh_rounds=${HULLKIT_BENCH_FRESH_ROUNDS:-}
if [ -z "$fresh_rounds" ]; then if [ "$quick" = 1 ]; then fresh_rounds=1; else fresh_rounds=7; fi; fi
started=$(date +%s)
load=$(cut -d " " -f 1 /proc/loadavg 2>/dev/null || echo "")
say() { printf '%s\n' "$*" >&2; }
case $build in /*) ;; *) build=$PWD/$build ;; esac
cgal_bench=$build/hullkit_constrained_cgal_bench
hullkit_bench=$build/hullkit_constrained_bench
hullkit_native_missing=""   # why hullkit's native rows are not available, when they are not

# ---- 1. build
if [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ]; then
  say "constrained bench: building $build"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=ON >"$out/build.log" 2>&1 ||
    { tail -n 30 "$out/build.log" >&2; exit 1; }
  cmake --build "$build" -j 2 --target hullkit_constrained_cgal_bench >>"$out/build.log" 2>&1 ||
    { tail -n 30 "$out/build.log" >&2; say "constrained bench: hullkit_constrained_cgal_bench does not build"; exit 1; }
  if [ ! -f native/include/hullkit/constrained.hpp ]; then
    hullkit_native_missing="native/include/hullkit/constrained.hpp is not there yet"
  elif ! cmake --build "$build" -j 2 --target hullkit_constrained_bench >"$out/build-hullkit.log" 2>&1; then
    hullkit_native_missing="hullkit_constrained_bench does not build (hullkit's core): $(grep -m 1 -E 'error|undefined reference' "$out/build-hullkit.log" | cut -c1-200)"
    say "constrained bench: $hullkit_native_missing (log: $out/build-hullkit.log)"
  fi
  wasm=build/wasm/hullkit_core.wasm
  if [ "${HULLKIT_BENCH_NO_WASM_BUILD:-0}" = 1 ]; then
    :
  elif [ ! -f "$wasm" ] || [ -n "$(find native/src native/include wasm CMakeLists.txt -newer "$wasm" -type f 2>/dev/null | head -n 1)" ]; then
    say "constrained bench: the core changed since the wasm build: bash scripts/build.sh wasm"
    bash scripts/build.sh wasm >"$out/build-wasm.log" 2>&1 ||
      say "constrained bench: the wasm build failed (log: $out/build-wasm.log); the wasm rows use the module as it was"
  fi
fi
[ -x "$cgal_bench" ] || { say "constrained bench: $cgal_bench is missing (unset HULLKIT_BENCH_NO_BUILD)"; exit 1; }
if [ -z "$hullkit_native_missing" ] && [ ! -x "$hullkit_bench" ]; then
  hullkit_native_missing="$hullkit_bench is not built"
fi

# ---- 2. inputs
if [ "$quick" = 1 ]; then
  node bench/constrained_inputs.mjs --quick
  list=$out/inputs-quick.json
  results=$out/results-quick.jsonl
else
  node bench/constrained_inputs.mjs
  list=$out/inputs.json
  results=$out/results.jsonl
fi
mapfile -t polygons < <(node -e 'for (const i of JSON.parse(require("fs").readFileSync(process.argv[1]))) if (i.kind === "polygon") console.log(i.name)' "$list")
mapfile -t graphs < <(node -e 'for (const i of JSON.parse(require("fs").readFileSync(process.argv[1]))) if (i.kind === "graph") console.log(i.name)' "$list")
: >"$results"

# runs_for INPUT [mesh|js]: 3 in quick mode; 5 at 1e5/1e6 (3 for the JS graph and meshes), 7 at 1e4, 21 at 1e3.
runs_for() {
  if [ "$quick" = 1 ]; then echo 3; return; fi
  case $1 in
    graph-*) [ "${2:-}" = js ] && echo 3 || echo 5 ;;
    *-1e5) [ "${2:-}" = mesh ] && echo 3 || echo 5 ;;
    *-1e4) [ "${2:-}" = mesh ] && echo 3 || echo 7 ;;
    *) echo 21 ;;
  esac
}

# Quality meshes not run, with the reason the report shows. star-1e4: hullkit meshed it once in 133 s and
# 8.7 GB (about 3.8e7 triangles); CGAL did not finish in 300 s.
declare -A mesh_skip=(
  [star-1e4]="needs ~3.8e7 triangles at this bound"
)

# record KIND LINE: tags a result line with its kind, appends it and prints a progress line.
record() {
  local line
  line=$(node -e 'const r = JSON.parse(process.argv[1]); r.kind_of_run = process.argv[2]; console.log(JSON.stringify(r))' "$2" "$1")
  printf '%s\n' "$line" >>"$results"
  node -e '
    const r = JSON.parse(process.argv[1]);
    const f = (s) => (s == null ? "-" : s < 0.1 ? `${(s * 1000).toPrecision(3)} ms` : `${s.toPrecision(3)} s`);
    const what = r.first == null ? "" : `first ${f(r.first)}, warm ${f(r.warm)}, ${r.triangles ?? "?"} triangles, `;
    console.error(`constrained bench: ${r.kind_of_run} ${r.impl} ${r.input}: ${what}${r.verdict}` +
      (r.t_junctions ? ` with ${r.t_junctions} T-junction line(s)` : "") +
      (r.reason ? ` (${r.reason.slice(0, 120)})` : r.error ? ` (${r.error.slice(0, 120)})` : ""));
  ' "$line"
}

# failure_line IMPL INPUT VERDICT ERROR: a result line for a run that printed none.
failure_line() {
  node -e 'const [impl, input, verdict, error] = process.argv.slice(1); console.log(JSON.stringify({ impl, input, verdict, error }))' "$@"
}

# run_line IMPL INPUT SECONDS CMD...: runs one process (stopped after SECONDS) and prints its JSON line,
# or a failure line (timeout / crash) when it printed none.
run_line() {
  local impl=$1 input=$2 limit=$3 line status=0
  shift 3
  line=$(timeout "$limit" "$@" 2>"$out/last_stderr.log") || status=$?
  line=$(printf '%s\n' "$line" | grep '^{' | tail -n 1 || true)
  if [ -z "$line" ]; then
    if [ "$status" = 124 ]; then
      failure_line "$impl" "$input" timeout "stopped after $limit s"
    else
      failure_line "$impl" "$input" crash "exit status $status: $(tail -c 300 "$out/last_stderr.log" | tr '\n' ' ')"
    fi
    return
  fi
  printf '%s\n' "$line"
}

# native_line IMPL INPUT BINARY [ARGS...]: a native run with --dump, then the check of the dump merged in.
native_line() {
  local impl=$1 input=$2 binary=$3 line check
  shift 3
  local dump=$out/dump-$impl-$input
  rm -f "$dump.tri" "$dump.xy"
  line=$(run_line "$impl" "$input" "$timeout_s" "$binary" --impl "$impl" --input "$out/$input.json" --runs "$(runs_for "$input")" --budget 60 --dump "$dump" "$@")
  if [ -f "$dump.tri" ] && node -e 'process.exit(JSON.parse(process.argv[1]).error ? 1 : 0)' "$line"; then
    check=$(node bench/constrained_check.mjs --input "$out/$input.json" --dump "$dump" 2>/dev/null || echo '{"verdict":"wrong","reason":"the check failed"}')
  else
    check='{}'
  fi
  rm -f "$dump.tri" "$dump.xy"
  node -e '
    const r = JSON.parse(process.argv[1]), c = JSON.parse(process.argv[2]);
    if (r.error && !r.verdict) r.verdict = r.error.startsWith("not available") ? "not available" : "exception";
    if (!r.error) Object.assign(r, { verdict: c.verdict, reason: c.reason, area_error: c.area_error, t_junctions: c.t_junctions });
    console.log(JSON.stringify(r));
  ' "$line" "$check"
}

# mesh_line IMPL INPUT: a quality mesh of a polygon (cgal-mesh from the CGAL-only build, hullkit-mesh),
# one process with the meshes' runs and time limit. hullkit-mesh dumps its first mesh and gets the mesh
# check (bench/constrained_check.mjs --mesh, against the bound its line states); CGAL's mesh is not
# dumped (its verdict "unchecked" when it ran).
mesh_line() {
  local impl=$1 input=$2 line check='{}'
  local dump=$out/dump-$impl-$input
  rm -f "$dump.tri" "$dump.xy"
  if [ "$impl" = cgal-mesh ] || [ "$impl" = cgal-refine ]; then
    line=$(run_line "$impl" "$input" "$mesh_timeout_s" "$cgal_bench" --impl "$impl" --input "$out/$input.json" --runs "$(runs_for "$input" mesh)" --budget 30)
  else
    line=$(run_line "$impl" "$input" "$mesh_timeout_s" "$hullkit_bench" --impl "$impl" --input "$out/$input.json" --runs "$(runs_for "$input" mesh)" --budget 30 --dump "$dump")
    if [ -f "$dump.tri" ] && node -e 'const r = JSON.parse(process.argv[1]); process.exit(r.error || r.min_angle_bound_deg == null ? 1 : 0)' "$line"; then
      check=$(node bench/constrained_check.mjs --input "$out/$input.json" --dump "$dump" \
        --mesh "$(node -p 'JSON.parse(process.argv[1]).min_angle_bound_deg' "$line")" 2>/dev/null ||
        echo '{"verdict":"wrong","reason":"the check failed"}')
    fi
  fi
  rm -f "$dump.tri" "$dump.xy"
  node -e '
    const r = JSON.parse(process.argv[1]), c = JSON.parse(process.argv[2]);
    if (r.error && !r.verdict) r.verdict = r.error.startsWith("not available") ? "not available" : "exception";
    if (!r.error && r.impl.startsWith("cgal-")) r.verdict = "unchecked";
    else if (!r.error) {
      Object.assign(r, { verdict: c.verdict ?? "wrong", reason: c.verdict ? c.reason : "no dump to check", area_error: c.area_error,
        length_error: c.length_error, below_bound: c.below_bound, excused_input_angle: c.excused_input_angle, excused_shells: c.excused_shells });
    }
    console.log(JSON.stringify(r));
  ' "$line" "$check"
}

# first_of IMPL INPUT BINARY: the first call of one more fresh process of a mesh (nothing dumped or
# checked), or nothing when it gave none.
first_of() {
  local line
  line=$(run_line "$1" "$2" "$mesh_timeout_s" "$3" --impl "$1" --input "$out/$2.json" --runs 1 --budget 30)
  first_in "$line"
}

# first_in LINE: the line's first call, or nothing when it has none.
first_in() {
  node -e 'const r = JSON.parse(process.argv[1]); if (!r.error && r.first != null) console.log(r.first)' "$1"
}

# js_line IMPL INPUT RUNS [ARGS...]: one JavaScript process (run_line's line).
js_line() {
  local impl=$1 input=$2 runs=$3
  shift 3
  run_line "$impl" "$input" "$timeout_s" node --expose-gc --max-old-space-size=8192 bench/constrained_js_bench.mjs \
    --impl "$impl" --input "$out/$input.json" --runs "$runs" --budget 60 "$@"
}

# with_median_first LINE [FIRST...]: LINE with first_each (its own first call, then the FIRSTs) and,
# when there are several, first = their median.
with_median_first() {
  node -e '
    const r = JSON.parse(process.argv[1]);
    const more = process.argv.slice(2).filter((s) => s !== "").map(Number);
    if (!r.error && r.first != null && more.length) {
      r.first_each = [r.first, ...more];
      const s = [...r.first_each].sort((a, b) => a - b), m = s.length >> 1;
      r.first = s.length % 2 ? s[m] : (s[m - 1] + s[m]) / 2;
    }
    console.log(JSON.stringify(r));
  ' "$@"
}

say "constrained bench: native runs (one process each, the meshes $fresh_rounds; at most $timeout_s s, the meshes $mesh_timeout_s s)"
for input in "${polygons[@]}" "${graphs[@]}"; do
  record native "$(native_line cgal-cdt "$input" "$cgal_bench")"
  if [ -n "$hullkit_native_missing" ]; then
    record native "$(failure_line hullkit "$input" "not available" "$hullkit_native_missing")"
    case $input in graph-*) record native-1thread "$(failure_line hullkit "$input" "not available" "$hullkit_native_missing")" ;; esac
  else
    record native "$(native_line hullkit "$input" "$hullkit_bench")"
  fi
  case $input in
    graph-*)
      if [ -z "$hullkit_native_missing" ]; then
        record native-1thread "$(native_line hullkit "$input" "$hullkit_bench" --threads 1)"
      fi ;;
    *)
      if [ -n "${mesh_skip[$input]:-}" ]; then
        for impl in cgal-mesh hullkit-mesh cgal-refine hullkit-refine; do
          record native "$(failure_line "$impl" "$input" skipped "${mesh_skip[$input]}")"
        done
      else
        for pair in "cgal-mesh hullkit-mesh" "cgal-refine hullkit-refine"; do
          read -r cgal_impl hullkit_impl <<<"$pair"
          cgal_line=$(mesh_line "$cgal_impl" "$input")
          if [ -n "$hullkit_native_missing" ]; then
            hullkit_line=$(failure_line "$hullkit_impl" "$input" "not available" "$hullkit_native_missing")
          else
            hullkit_line=$(mesh_line "$hullkit_impl" "$input")
          fi
          # More fresh processes, the two taking turns (the machine's speed drifts within minutes).
          cgal_firsts=() hullkit_firsts=()
          for ((round = 1; round < fresh_rounds; round++)); do
            cgal_firsts+=("$(first_of "$cgal_impl" "$input" "$cgal_bench")")
            if [ -z "$hullkit_native_missing" ]; then hullkit_firsts+=("$(first_of "$hullkit_impl" "$input" "$hullkit_bench")"); fi
          done
          record native "$(with_median_first "$cgal_line" "${cgal_firsts[@]}")"
          record native "$(with_median_first "$hullkit_line" "${hullkit_firsts[@]}")"
        done
      fi ;;
  esac
done

say "constrained bench: JavaScript runs (Node $(node --version))"
for input in "${polygons[@]}" "${graphs[@]}"; do
  case $input in graph-*) impls=(hullkit constrainautor cdt2d) ;; *) impls=(hullkit earcut constrainautor cdt2d poly2tri) ;; esac
  # The target's pair on the large polygons: more fresh processes, taking turns (FRESH_ROUNDS).
  case $input in graph-*) paired=0 ;; *-1e4 | *-1e5) paired=1 ;; *) paired=0 ;; esac
  hullkit_js="" earcut_js=""
  for impl in "${impls[@]}"; do
    line=$(js_line "$impl" "$input" "$(runs_for "$input" js)")
    case "$paired:$impl" in
      1:hullkit) hullkit_js=$line ;;
      1:earcut) earcut_js=$line ;;
      *) record js "$line" ;;
    esac
  done
  if [ "$paired" = 1 ]; then
    hullkit_firsts=() earcut_firsts=()
    for ((round = 1; round < fresh_rounds; round++)); do
      earcut_firsts+=("$(first_in "$(js_line earcut "$input" 1 --no-check)")")
      hullkit_firsts+=("$(first_in "$(js_line hullkit "$input" 1 --no-check)")")
    done
    record js "$(with_median_first "$hullkit_js" "${hullkit_firsts[@]}")"
    record js "$(with_median_first "$earcut_js" "${earcut_firsts[@]}")"
  fi
done
rm -f "$out/last_stderr.log"

elapsed=$(($(date +%s) - started))
say "constrained bench: all runs done in ${elapsed} s"
node bench/constrained_report.mjs --quick "$quick" --elapsed "$elapsed" --load "$load" --inputs "$list" "$results"
