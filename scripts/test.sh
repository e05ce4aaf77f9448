#!/usr/bin/env bash
# Runs every suite against what `scripts/build.sh native wasm asan` built: ctest (release and
# sanitized), node:test (the wasm module), and the browser test of the page.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== C++ tests (ctest)"
ctest --test-dir build/native --output-on-failure -j "$(nproc)"

echo "== C++ tests under AddressSanitizer + UndefinedBehaviorSanitizer (ctest)"
ctest --test-dir build/asan --output-on-failure -j "$(nproc)"

echo "== JavaScript tests (node:test)"
node --test tests/js/

echo "== Browser tests (node:test + playwright-core + chromium)"
node --test tests/browser/
