#!/usr/bin/env bash
# Runs every suite against what scripts/build.sh built: ctest, node:test (wasm), browser.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== C++ tests (ctest)"
ctest --test-dir build/native --output-on-failure -j "$(nproc)"

echo "== JavaScript tests (node:test)"
node --test tests/js/

echo "== Browser tests (node:test + playwright-core + chromium)"
node --test tests/browser/
