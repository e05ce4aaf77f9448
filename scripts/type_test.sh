#!/usr/bin/env bash
# Type test of the npm package: packs the repository (`npm pack`), installs the tarball offline into
# a throw-away consumer project ("type": "module"), and compiles tests/types/*.ts against it with
# the repository's TypeScript, --strict and never skipLibCheck, so wasm/hullkit.d.ts is checked as
# a consumer sees it:
#   - consumer.ts under --module nodenext with targets es2020, es2022, esnext (default libs), with
#     --lib es2020 (no DOM, no Symbol.dispose), with extra strictness flags, and under
#     --module esnext --moduleResolution bundler;
#   - consumer.ts + using.ts (`using checker = new hullkit.RouteChecker(...)`) with
#     --lib es2022,esnext.disposable and with --lib esnext;
#   - negative.ts, which must fail with exactly one error on each line marked "// error";
#   - consumer.ts and using.ts compiled to JavaScript and run with node.
# Prints one line per configuration; exits non-zero if any fails. Needs the wasm build
# (bash scripts/build.sh wasm) and the npm dependencies (npm ci).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tsc="$root/node_modules/.bin/tsc"

if [[ ! -x "$tsc" ]]; then
  echo "type_test: $tsc is missing: install the npm dependencies first (npm ci, or bash scripts/setup.sh)" >&2
  exit 1
fi
for file in build/wasm/hullkit_core.mjs build/wasm/hullkit_core.wasm; do
  if [[ ! -f "$root/$file" ]]; then
    echo "type_test: $file is missing: the package includes it; build it first with: bash scripts/build.sh wasm" >&2
    exit 1
  fi
done

work="$(mktemp -d "${TMPDIR:-/tmp}/hullkit-type-test.XXXXXX")"
trap 'rm -rf "$work"' EXIT
trap 'exit 1' INT TERM

# The package exactly as it would be published ("files" in package.json), installed offline:
# hullkit has no runtime dependencies, so nothing is fetched.
(cd "$root" && npm pack --silent --pack-destination "$work" >/dev/null)
tarballs=("$work"/hullkit-*.tgz)
if [[ ${#tarballs[@]} -ne 1 || ! -f "${tarballs[0]}" ]]; then
  echo "type_test: npm pack did not leave one hullkit-*.tgz in $work" >&2
  exit 1
fi
consumer="$work/consumer"
mkdir "$consumer"
printf '{ "name": "hullkit-type-consumer", "version": "0.0.0", "private": true, "type": "module" }\n' >"$consumer/package.json"
(cd "$consumer" && npm install --offline --no-audit --no-fund --loglevel=error "${tarballs[0]}" >/dev/null)
cp "$root"/tests/types/*.ts "$consumer/"
cd "$consumer"

failures=0
output="$work/tsc-output.txt"

# compile LABEL FLAGS... FILES...: one type check; prints the compiler's messages on failure.
compile() {
  local label="$1"
  shift
  if "$tsc" --strict --noEmit "$@" >"$output" 2>&1; then
    echo "type_test: ok    $label"
  else
    echo "type_test: FAIL  $label"
    sed 's/^/    /' "$output"
    failures=$((failures + 1))
  fi
}

nodenext=(--module nodenext --moduleResolution nodenext)
compile "--target es2020 --module nodenext" "${nodenext[@]}" --target es2020 consumer.ts
compile "--target es2022 --module nodenext" "${nodenext[@]}" --target es2022 consumer.ts
compile "--target esnext --module nodenext" "${nodenext[@]}" --target esnext consumer.ts
compile "--target es2020 --lib es2020 --module nodenext (no DOM, no Symbol.dispose)" \
  "${nodenext[@]}" --target es2020 --lib es2020 consumer.ts
compile "--target es2022 --lib es2022,esnext.disposable --module nodenext + using" \
  "${nodenext[@]}" --target es2022 --lib es2022,esnext.disposable consumer.ts using.ts
compile "--target esnext --lib esnext --module nodenext + using" \
  "${nodenext[@]}" --target esnext --lib esnext consumer.ts using.ts
compile "--target es2022 --module nodenext --exactOptionalPropertyTypes --noUncheckedIndexedAccess --verbatimModuleSyntax" \
  "${nodenext[@]}" --target es2022 --exactOptionalPropertyTypes --noUncheckedIndexedAccess --verbatimModuleSyntax consumer.ts
compile "--target es2022 --module esnext --moduleResolution bundler" \
  --module esnext --moduleResolution bundler --target es2022 consumer.ts

# The types have teeth: negative.ts must fail, with errors on exactly the lines marked "// error".
label="negative.ts fails on each of its $(grep -c '// error$' negative.ts) marked lines (--target es2022 --module nodenext)"
expected="$(grep -n '// error$' negative.ts | cut -d: -f1 | sort -n | tr '\n' ' ')"
if "$tsc" --strict --noEmit "${nodenext[@]}" --target es2022 negative.ts >"$output" 2>&1; then
  echo "type_test: FAIL  $label: it compiled"
  failures=$((failures + 1))
else
  # Error lines (one per error, repeats kept: two errors on one line is a mismatch too), and any
  # error outside negative.ts (e.g. in the package's .d.ts) as a line that never matches.
  actual="$(sed -n 's/^negative\.ts(\([0-9]*\),[0-9]*): error .*/\1/p; /^negative\.ts(/!{/error TS/s/.*/outside/p}' "$output" | sort -n | tr '\n' ' ')"
  if [[ "$actual" == "$expected" ]]; then
    echo "type_test: ok    $label"
  else
    echo "type_test: FAIL  $label: errors on lines [${actual}], expected [${expected}]"
    sed 's/^/    /' "$output"
    failures=$((failures + 1))
  fi
fi

# The compiled consumer really runs against the packed module (Node 20 has Symbol.dispose).
label="consumer.ts and using.ts compiled (--target es2022 --lib es2022,esnext.disposable) and run with node"
if ! "$tsc" --strict "${nodenext[@]}" --target es2022 --lib es2022,esnext.disposable --outDir out consumer.ts using.ts >"$output" 2>&1; then
  echo "type_test: FAIL  $label: compiling"
  sed 's/^/    /' "$output"
  failures=$((failures + 1))
elif ! { node out/consumer.js && node out/using.js; } >"$output" 2>&1; then
  echo "type_test: FAIL  $label: running"
  sed 's/^/    /' "$output"
  failures=$((failures + 1))
else
  echo "type_test: ok    $label"
fi

if ((failures > 0)); then
  echo "type_test: $failures configuration(s) failed" >&2
  exit 1
fi
