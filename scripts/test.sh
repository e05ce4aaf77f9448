#!/usr/bin/env bash
# Runs every suite against what `scripts/build.sh native wasm asan` built: ctest (release and
# sanitized), a short libFuzzer run of every fuzz target (HULLKIT_FUZZ_SECONDS each, default 20),
# node:test (the wasm module), and the browser tests of the page.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== C++ tests (ctest)"
ctest --test-dir build/native --output-on-failure -j "$(nproc)"

echo "== C++ tests under AddressSanitizer + UndefinedBehaviorSanitizer (ctest)"
ctest --test-dir build/asan --output-on-failure -j "$(nproc)"

echo "== Fuzzing, ${HULLKIT_FUZZ_SECONDS:-20} s per target (scripts/fuzz.sh)"
bash scripts/fuzz.sh "${HULLKIT_FUZZ_SECONDS:-20}"

echo "== JavaScript tests (node:test)"
node --test tests/js/

echo "== Browser tests (node:test + playwright-core + chromium)"
node --test --test-concurrency=2 tests/browser/
