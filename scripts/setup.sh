#!/usr/bin/env bash
# Installs what hullkit needs on a Debian machine with Node and npm: the Debian packages that are
# missing, then the npm dependencies. Safe to run again; it does nothing when all is in place.
# `scripts/setup.sh bench` also installs the peer libraries the benchmarks compare against.
set -euo pipefail
cd "$(dirname "$0")/.."

debian_packages=(
  cmake g++ make          # native build
  pkg-config              # scripts/consumer_test.sh checks the installed hullkit.pc with it
  emscripten              # the wasm build (emcc, emcmake)
  catch2 libgmp-dev       # C++ tests (GMP: exact rational checks)
  libcgal-dev libmpfr-dev # the C++ tests' cross-check of delaunay3 against CGAL (header-only)
  voro++                  # the C++ tests' cross-check of delaunay3's Voronoi cell volumes
  libglm-dev              # vector math
  nlohmann-json3-dev      # scene JSON (route checking)
  libcli11-dev            # command-line parsing
  libfast-float-dev       # number parsing in the readers
  libtinygltf-dev         # glTF 2.0 (.gltf, .glb) reading and writing, header-only (images off)
  clang                   # libFuzzer (scripts/fuzz.sh, run briefly by npm test)
  qhull-bin               # rbox/qconvex: test inputs and cross-checks
  chromium                # browser tests (driven by playwright-core)
  # The Python package (python/, built by pip from the C++ sources; scripts/python_test.sh):
  python3-dev python3-venv python3-numpy python3-pybind11 pybind11-dev python3-setuptools
  python3-pip python3-pytest python3-scipy python3-dask python3-distributed
  python3-pytest-xdist    # the Python tests on every core (scripts/python_test.sh)
  python3-mypy            # tests/python/test_stubs.py: stubtest and mypy --strict on the type stubs
  python3-matplotlib      # hullkit.spatial's plot helpers (voronoi_plot_2d, ...) and their tests
)

if [ "${1:-}" = bench ]; then
  debian_packages+=(libqhull-dev libfcl-dev tetgen)
fi

missing=()
for package in "${debian_packages[@]}"; do
  case "$package" in \#*) continue ;; esac
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]})); then
  echo "setup: installing Debian packages: ${missing[*]}"
  sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
    sudo=(sudo)
  fi
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

# npm dependencies, when node_modules is missing or older than the lock file.
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  echo "setup: installing npm dependencies"
  npm ci --no-audit --no-fund --loglevel=error
fi
