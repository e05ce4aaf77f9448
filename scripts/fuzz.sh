#!/usr/bin/env bash
# Fuzzes the readers and the hull with clang's libFuzzer (Debian clang), one target after the
# other, each for SECONDS (default 60):
#   bash scripts/fuzz.sh [SECONDS]
# Targets (tests/fuzz/*.cpp): fuzz_points (parse_points and the chunked file reader: xyz, rbox,
# OBJ, OFF), fuzz_off_mesh (read_off_mesh), fuzz_hull (hull() on bytes read as doubles, checked
# by verify() and against gift wrapping). Each is built in build/fuzz with
# -fsanitize=fuzzer,address,undefined against the core sources. The seed corpus is tests/data/
# (every file, read as the target's input); what libFuzzer adds goes to build/fuzz/corpus/TARGET.
# A crash, a hang (> 10 s for one input) or a leak stops that target and leaves the input in
# build/fuzz/artifacts/; the script then exits 1 after the other targets ran. Make every such input
# a regression file in tests/data/ with a test.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
out=build/fuzz
mkdir -p "$out/obj" "$out/artifacts"
cxx=${CXX_FUZZ:-clang++}
command -v "$cxx" >/dev/null || { echo "fuzz: $cxx not found (apt-get install clang)" >&2; exit 2; }
flags=(-std=c++17 -O1 -g -ffp-contract=off -fno-omit-frame-pointer -fsanitize=address,undefined
       -fno-sanitize-recover=undefined -Inative/include -Inative/src)

# The core library: every native/src/*.cpp (not the delaunay/route subfolders), rebuilt when newer.
objects=()
for src in native/src/*.cpp; do
  obj="$out/obj/$(basename "${src%.cpp}").o"
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ -n "$(find native/include native/src -maxdepth 1 -name '*.hpp' -newer "$obj" | head -n 1)" ]; then
    "$cxx" "${flags[@]}" -fsanitize=fuzzer-no-link -c "$src" -o "$obj"
  fi
  objects+=("$obj")
done

status=0
for src in tests/fuzz/fuzz_*.cpp; do
  name=$(basename "${src%.cpp}")
  "$cxx" "${flags[@]}" -fsanitize=fuzzer "$src" "${objects[@]}" -o "$out/$name"
  mkdir -p "$out/corpus/$name"
  echo "fuzz: $name for ${seconds} s" >&2
  if ! "$out/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
      -print_final_stats=1 -artifact_prefix="$out/artifacts/$name-" \
      "$out/corpus/$name" tests/data tests/data/degenerate >"$out/$name.log" 2>&1; then
    echo "fuzz: $name FAILED, see $out/$name.log; the input is in $out/artifacts/:" >&2
    grep -E "ERROR|SUMMARY|Test unit written" "$out/$name.log" | head -n 5 >&2 || true
    status=1
  else
    grep -E "stat::number_of_executed_units" "$out/$name.log" | sed "s/^/fuzz: $name /" >&2 || true
  fi
done
[ "$status" = 0 ] && echo "fuzz: all targets ran ${seconds} s without a failure" >&2
exit "$status"
