#!/usr/bin/env bash
# Fuzzes the readers, the hull, the Delaunay triangulation and tetrahedralization with clang's libFuzzer (Debian
# clang), each target for SECONDS (default 60), as many at once as there are cores
# (HULLKIT_FUZZ_JOBS):
#   bash scripts/fuzz.sh [SECONDS]
# Targets (tests/fuzz/*.cpp):
#   fuzz_points    parse_points and the chunked file reader (xyz, rbox, OBJ, OFF), which must agree
#   fuzz_off_mesh  read_off_mesh (the OFF reader of `hullkit verify`)
#   fuzz_mesh      every mesh reader (OBJ, OFF, PLY ascii/binary, STL ascii/binary) and read_mesh's
#                  format detection; meshes must be consistent and read back from OFF unchanged
#   fuzz_gltf      read_gltf_mesh (glTF 2.0 .glb / .gltf through tinygltf; every buffer URI gets the
#                  input itself); meshes must be consistent and read back from write_glb's .glb
#                  with float-rounded positions; read_mesh must agree
#   fuzz_points2d  parse_points_2d (xy, xyz, rbox 2D); points must be on the lines they name
#   fuzz_scene     parse_scene (route scene JSON; bytes after the first NUL are the mesh a "mesh"
#                  entry loads, in memory); scenes must write back and read again unchanged
#   fuzz_hull      hull() on bytes read as doubles, checked by verify() and against gift wrapping
#   fuzz_delaunay  delaunay() on bytes read as doubles or small integers, checked by
#                  verify_delaunay(), against gift wrapping and merge_cocircular, and by
#                  nearest-point queries and point location (delaunay_locate)
#   fuzz_delaunay3 delaunay3() on bytes read as doubles or small integers, checked by
#                  verify_delaunay3() (ties included), neighbours and hull faces, the reversed input,
#                  and point location and nearest points at the input points
#   fuzz_hull_nd   hull_nd, delaunay_nd and locate_nd in 2 to 6 dimensions on bytes read as doubles
#                  or small integers: every facet checked against every point by orient_nd,
#                  neighbours, oriented simplices, hull faces that support the hull, point location
# A failed check aborts. Each target is built in build/fuzz with -fsanitize=fuzzer,address,undefined
# and linked with every library source (native/src/{exact,hull,io,delaunay,delaunay3,route}/; objects in
# build/fuzz/obj named FOLDER_FILE.o, rebuilt when the source or any
# header is newer; a target is relinked when its source, an object or a public header is newer). The
# seed corpus is tests/data/ and all its subfolders (libFuzzer reads directories recursively; every
# file is read as the target's input); what libFuzzer adds goes to build/fuzz/corpus/TARGET.
# A crash, a hang (> 10 s for one input) or a leak stops that target and leaves the input in
# build/fuzz/artifacts/; the script then exits 1 once the other targets ran. Make every such input
# a regression file in tests/data/fuzz/ with a test.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
out=build/fuzz
mkdir -p "$out/obj" "$out/artifacts"
cxx=${CXX_FUZZ:-clang++}
command -v "$cxx" >/dev/null || { echo "fuzz: $cxx not found (apt-get install clang)" >&2; exit 2; }
# nlohmann/json and fast_float are header-only in /usr/include, as CMakeLists.txt finds them.
# Line tables only (the sanitizers' reports name file and line): a fifth less compile time than -g,
# most of this script's time in npm test.
flags=(-std=c++17 -O1 -gline-tables-only -ffp-contract=off -fno-omit-frame-pointer -fsanitize=address,undefined
       -fno-sanitize-recover=undefined -Inative/include -Inative/src)

# Up to HULLKIT_FUZZ_JOBS (default: the number of cores) compilers, and then fuzzers, at once.
jobs=${HULLKIT_FUZZ_JOBS:-$(nproc)}
pool() { while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done; }
rm -f "$out/compile-failed"

# Every library source, rebuilt when it or any header is newer than its object.
objects=()
for src in native/src/*/*.cpp; do
  obj="$out/obj/$(basename "$(dirname "$src")")_$(basename "${src%.cpp}").o"
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ -n "$(find native/include native/src -name '*.hpp' -newer "$obj" | head -n 1)" ]; then
    echo "fuzz: compiling $src" >&2
    pool
    { "$cxx" "${flags[@]}" -fsanitize=fuzzer-no-link -c "$src" -o "$obj" || { rm -f "$obj"; touch "$out/compile-failed"; }; } &
  fi
  objects+=("$obj")
done
wait
[ -f "$out/compile-failed" ] && { echo "fuzz: compiling the library failed" >&2; exit 2; }

targets=()
for src in tests/fuzz/fuzz_*.cpp; do
  name=$(basename "${src%.cpp}")
  targets+=("$name")
  newer=$(find "$src" "${objects[@]}" native/include -newer "$out/$name" 2>/dev/null | head -n 1 || true)
  if [ ! -f "$out/$name" ] || [ -n "$newer" ]; then
    echo "fuzz: building $name" >&2
    pool
    { "$cxx" "${flags[@]}" -fsanitize=fuzzer "$src" "${objects[@]}" -o "$out/$name" || { rm -f "$out/$name"; touch "$out/compile-failed"; }; } &
  fi
done
wait
[ -f "$out/compile-failed" ] && { echo "fuzz: building a fuzz target failed" >&2; exit 2; }

# One fuzzer per core at a time; each writes its log and, when it fails, a .failed marker.
for name in "${targets[@]}"; do
  mkdir -p "$out/corpus/$name"
  rm -f "$out/$name.failed"
  echo "fuzz: $name for ${seconds} s" >&2
  pool
  {
    "$out/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
      -print_final_stats=1 -artifact_prefix="$out/artifacts/$name-" \
      "$out/corpus/$name" tests/data >"$out/$name.log" 2>&1 || touch "$out/$name.failed"
  } &
done
wait

status=0
for name in "${targets[@]}"; do
  if [ -f "$out/$name.failed" ]; then
    echo "fuzz: $name FAILED, see $out/$name.log; the input is in $out/artifacts/:" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "$out/$name.log" | head -n 5 >&2 || true
    status=1
  else
    grep -E "stat::number_of_executed_units" "$out/$name.log" | sed "s/^/fuzz: $name /" >&2 || true
  fi
done
[ "$status" = 0 ] && echo "fuzz: all targets ran ${seconds} s without a failure" >&2
exit "$status"
