#!/usr/bin/env bash
# Builds the native library, CLI and tests (build/native) and the wasm module (build/wasm).
# `scripts/build.sh native` or `scripts/build.sh wasm` builds one of them.
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
jobs=$(nproc)

if [ "$what" = all ] || [ "$what" = native ]; then
  cmake -S . -B build/native -DCMAKE_BUILD_TYPE=Release -DHULLKIT_BENCH=OFF >/dev/null
  cmake --build build/native -j "$jobs"
fi

if [ "$what" = all ] || [ "$what" = wasm ]; then
  # Debian's emscripten runs acorn from /usr/share/nodejs, which this Node does not search.
  export NODE_PATH=/usr/share/nodejs${NODE_PATH:+:$NODE_PATH}
  emcmake cmake -S . -B build/wasm -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build/wasm -j "$jobs"
fi
