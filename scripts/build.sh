#!/usr/bin/env bash
# Builds hullkit. With no arguments: the native library, CLI and tests (build/native), the wasm
# module (build/wasm) and the page as a static site (build/site). Arguments pick among: native,
# cli (the library and the hullkit command alone, in build/native), wasm, site (build/site from
# the wasm build and three.js: scripts/build-site.js, docs/page.md; after wasm), asan (the C++
# tests under AddressSanitizer + UndefinedBehaviorSanitizer, in build/asan), tsan (the test sources
# with "[threads]" tests in one executable under ThreadSanitizer, build/tsan/tests/
# hullkit_threads_tests; scripts/test.sh runs those tests).
set -euo pipefail
cd "$(dirname "$0")/.."
targets=("$@")
((${#targets[@]})) || targets=(native wasm site)
jobs=$(nproc)

for target in "${targets[@]}"; do
  case "$target" in
    native | cli)
      cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DHULLKIT_BENCH=OFF >/dev/null
      if [ "$target" = cli ]; then
        cmake --build build/native -j "$jobs" --target hullkit
      else
        cmake --build build/native -j "$jobs"
      fi
      ;;
    wasm)
      # Debian's emscripten runs acorn from /usr/share/nodejs, which this Node does not search.
      export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
      emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release >/dev/null
      cmake --build build/wasm -j "$jobs"
      ;;
    site)
      node scripts/build-site.js build/site
      ;;
    asan)
      # Built with clang (installed for the fuzzers) at -O1 with line tables only: GCC took about
      # 13 minutes of the suite's 30 for this build, clang a fraction of that, and the sanitizers'
      # reports still name file and line.
      sanitize="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
      asan_cxx=g++ asan_debug=-g1
      command -v clang++ >/dev/null && asan_cxx=clang++ asan_debug=-gline-tables-only
      cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHULLKIT_BENCH=OFF -DHULLKIT_CGAL_TESTS=OFF \
        -DCMAKE_CXX_COMPILER="$asan_cxx" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 $asan_debug -DNDEBUG" \
        -DCMAKE_CXX_FLAGS="$sanitize" -DCMAKE_EXE_LINKER_FLAGS="$sanitize" >/dev/null
      cmake --build build/asan -j "$jobs"
      ;;
    tsan)
      # clang's ThreadSanitizer on one executable of the test sources that hold [threads] tests.
      tsan="-fsanitize=thread -fno-omit-frame-pointer"
      cmake -S . -B build/tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHULLKIT_BENCH=OFF -DHULLKIT_CGAL_TESTS=OFF \
        -DHULLKIT_THREADS_TESTS=ON \
        -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
        -DCMAKE_CXX_FLAGS="$tsan" -DCMAKE_EXE_LINKER_FLAGS="$tsan" >/dev/null
      cmake --build build/tsan -j "$jobs" --target hullkit_threads_tests
      ;;
    *)
      echo "build.sh: unknown target \"$target\" (known: native, cli, wasm, site, asan, tsan)" >&2
      exit 2
      ;;
  esac
done
