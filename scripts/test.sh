#!/usr/bin/env bash
# Runs every suite against what `scripts/build.sh native wasm site asan tsan` built: ctest (release
# and sanitized), the threaded tests under ThreadSanitizer, a short libFuzzer run of every fuzz
# target (one shared time budget, see below), node:test (the wasm module), the TypeScript
# type test, the installed CMake package's consumers, the Python package's pytest suite (with
# Dask), and the browser tests of the page, served from the checkout and from build/site.
set -euo pipefail
cd "$(dirname "$0")/.."
step_started=$SECONDS
# Prints how long the step before took (the whole of `npm test` must stay under 40 minutes in CI,
# set-up and builds included).
took() { echo "   (${1}: $((SECONDS - step_started)) s)"; step_started=$SECONDS; }

echo "== C++ tests (ctest)"
ctest --test-dir build/native --output-on-failure -j "$(nproc)"
took "ctest"

echo "== C++ tests under AddressSanitizer + UndefinedBehaviorSanitizer (ctest)"
ctest --test-dir build/asan --output-on-failure -j "$(nproc)"
took "ctest under sanitizers"

echo "== Threaded tests under ThreadSanitizer (the \"[threads]\" tests, ctest in build/tsan)"
# One executable of the sources with [threads] tests (tests/CMakeLists.txt), each test its own ctest
# entry, as many at once as there are cores; halt_on_error (set there): the first data race fails
# its test, with both stacks. [heavy] cases repeat the light ones on large inputs, too slow under
# the sanitizer.
ctest --test-dir build/tsan --output-on-failure -j "$(nproc)"
took "ThreadSanitizer"

# One fuzzing budget shared by every target (HULLKIT_FUZZ_BUDGET seconds of wall time, default 90;
# the targets run as many at once as there are cores), so that a new target does not lengthen the
# suite. HULLKIT_FUZZ_SECONDS sets the time per target instead.
fuzz_targets=$(ls tests/fuzz/fuzz_*.cpp | wc -l)
fuzz_seconds=${HULLKIT_FUZZ_SECONDS:-$(( ${HULLKIT_FUZZ_BUDGET:-90} * $(nproc) / fuzz_targets ))}
echo "== Fuzzing, ${fuzz_seconds} s per target, ${fuzz_targets} targets (scripts/fuzz.sh)"
bash scripts/fuzz.sh "$fuzz_seconds"
took "fuzzing"

echo "== JavaScript tests (node:test)"
node --test tests/js/
took "node:test"

echo "== TypeScript types of the npm package (scripts/type_test.sh)"
bash scripts/type_test.sh
took "type test"

echo "== The C++ library installed as a CMake package, and its consumers (scripts/consumer_test.sh)"
bash scripts/consumer_test.sh
took "consumer test"

echo "== Python package: pip install into a fresh virtual environment, then pytest and the Dask tests"
bash scripts/python_test.sh
took "python"

echo "== Browser tests (node:test + playwright-core + chromium)"
# The page and view tests two at a time; the heavy-work test (a million points, whose main-thread
# responsiveness it measures) alone afterwards, so that no other browser competes for the cores.
mapfile -t light < <(ls tests/browser/*.test.js | grep -v '/work\.test\.js$')
node --test --test-concurrency=2 "${light[@]}"
node --test tests/browser/work.test.js
took "browser tests"
