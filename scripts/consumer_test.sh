#!/usr/bin/env bash
# Checks that other projects can use hullkit's C++ libraries: installs hullkit (build/native, or a
# Release build of its own in build/consumer/hullkit when there is none) into a temporary prefix with
# `cmake --install`, then builds and runs tests/consumer/ (a hull, a Delaunay triangulation and a
# route check, compared with known answers) three ways:
#   find_package   tests/consumer against the installed CMake package (hullkit::core, ...)
#   add_subdirectory  tests/consumer with this source tree (-DHULLKIT_SOURCE_DIR), in
#                  build/consumer/subdirectory
#   pkg-config     g++ on tests/consumer/main.cpp with `pkg-config --cflags --libs hullkit`
# and runs the installed `hullkit --version` and `--help`. One line per check; exit 1 if any fails.
#   bash scripts/consumer_test.sh
# HULLKIT_CONSUMER_JOBS sets the build's parallelism (default: every core).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
jobs=${HULLKIT_CONSUMER_JOBS:-$(nproc)}
cxx=${CXX:-g++}
build=build/consumer
tmp=$(mktemp -d "${TMPDIR:-/tmp}/hullkit-consumer.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
failed=0
count=0

# check NAME COMMAND...: runs COMMAND with its output in a log; prints "ok" or "FAIL" and, on
# failure, the end of the log. COMMAND fails at the first command in it that fails.
check() {
  local name=$1
  shift
  count=$((count + 1))
  local log=$tmp/check-$count.log status started=$SECONDS
  # A subshell outside any `if`, so that set -e stops the check at its first failing command.
  set +e
  (set -e; "$@") >"$log" 2>&1
  status=$?
  set -e
  if ((status == 0)); then
    echo "ok   $name ($((SECONDS - started)) s)"
  else
    echo "FAIL $name ($((SECONDS - started)) s)"
    tail -n 40 "$log" | sed 's/^/     | /'
    failed=$((failed + 1))
  fi
}

# The Release build that `npm test` made (build/native) is installed as it is, when there is one:
# building a second copy doubled this check's time; otherwise a build of its own.
build_and_install() {
  local from=$build/hullkit
  if [ -f build/native/CMakeCache.txt ] && [ -x build/native/hullkit ]; then
    from=build/native
    cmake --build "$from" -j "$jobs" --target hullkit_core hullkit_delaunay hullkit_route hullkit
  else
    cmake -S . -B "$from" -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=OFF
    cmake --build "$from" -j "$jobs"
  fi
  cmake --install "$from" --prefix "$prefix"
}

installed_files() {
  local missing=0 file
  for file in include/hullkit/hull.hpp include/hullkit/delaunay.hpp include/hullkit/route.hpp \
      include/hullkit/delaunay3.hpp "$libdir/libhullkit_core.a" "$libdir/libhullkit_delaunay.a" "$libdir/libhullkit_route.a" \
      "$libdir/cmake/hullkit/hullkitConfig.cmake" "$libdir/cmake/hullkit/hullkitConfigVersion.cmake" \
      "$libdir/cmake/hullkit/hullkitTargets.cmake" "$libdir/pkgconfig/hullkit.pc" bin/hullkit \
      share/doc/hullkit/LICENSE; do
    [ -e "$prefix/$file" ] || { echo "missing: $file"; missing=1; }
  done
  # Nothing else is a program: no tests, no benchmarks.
  local programs
  programs=$(ls "$prefix/bin")
  [ "$programs" = hullkit ] || { echo "bin/ holds: $programs"; missing=1; }
  return "$missing"
}

# The exported targets must not point into this tree or at the libraries' private dependencies.
package_self_contained() {
  if grep -n -e "$root" -e /usr/include -e glm -e nlohmann -e fast_float -e tiny_gltf "$prefix/$libdir"/cmake/hullkit/*.cmake \
      "$prefix/$libdir/pkgconfig/hullkit.pc"; then
    return 1
  fi
}

installed_cli() {
  "$prefix/bin/hullkit" --version | grep -E '^hullkit [0-9]+\.[0-9]+\.[0-9]+$'
  "$prefix/bin/hullkit" --help | grep -q 'hull'
}

consumer_find_package() {
  cmake -S tests/consumer -B "$tmp/find-package" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix"
  cmake --build "$tmp/find-package" -j "$jobs"
  "$tmp/find-package/consumer"
}

# No build type here (no optimisation: this second build of the libraries only has to link and
# give the same answers, and quickly); hullkit must leave the parent's empty build type alone.
consumer_add_subdirectory() {
  cmake -S tests/consumer -B "$build/subdirectory" -DCMAKE_BUILD_TYPE= -DHULLKIT_SOURCE_DIR="$root"
  grep -qx 'CMAKE_BUILD_TYPE:STRING=' "$build/subdirectory/CMakeCache.txt"
  cmake --build "$build/subdirectory" -j "$jobs"
  "$build/subdirectory/consumer"
}

consumer_pkg_config() {
  command -v pkg-config >/dev/null || { echo "pkg-config not found (bash scripts/setup.sh installs it)"; return 1; }
  export PKG_CONFIG_PATH=$prefix/$libdir/pkgconfig
  pkg-config --modversion hullkit
  local flags
  flags=$(pkg-config --cflags --libs hullkit)
  echo "pkg-config --cflags --libs hullkit: $flags"
  # shellcheck disable=SC2086  # the flags are words
  "$cxx" -std=c++17 -O2 tests/consumer/main.cpp $flags -o "$tmp/consumer-pkg-config"
  "$tmp/consumer-pkg-config"
}

check "build and install hullkit (Release) into a temporary prefix" build_and_install
if ((failed)); then
  echo "consumer_test: hullkit did not build or install; nothing else checked" >&2
  exit 1
fi
# lib, or lib/<multiarch> when GNUInstallDirs chose that.
libdir=$(cd "$prefix" && dirname "$(find . -name libhullkit_core.a | head -n 1)")
libdir=${libdir#./}

check "installed files: headers, 3 libraries, CMake package, hullkit.pc, LICENSE, bin/hullkit only" installed_files
check "installed package names no source-tree path and no private dependency" package_self_contained
check "installed hullkit --version and --help run" installed_cli
check "consumer via find_package(hullkit CONFIG) on the install" consumer_find_package
check "consumer via add_subdirectory(source tree)" consumer_add_subdirectory
check "consumer via pkg-config --cflags --libs hullkit and $cxx" consumer_pkg_config

if ((failed)); then
  echo "consumer_test: $failed of $count checks failed" >&2
  exit 1
fi
echo "consumer_test: all $count checks passed"
