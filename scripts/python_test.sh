#!/usr/bin/env bash
# The Python package's tests: installs hullkit from ./python into a fresh virtual environment,
# the way the README tells a user to (offline: pip builds the extension from the C++ sources with
# the system's setuptools, pybind11 and numpy), then runs pytest on tests/python.
#
# The interpreter is Debian's /usr/bin/python3, chosen on purpose: the `python3` first on PATH
# may be another installation that does not see Debian's numpy, scipy and pytest. The virtual
# environment sees them (--system-site-packages) and holds hullkit alone. Debian's mypy checks the
# installed type stubs (tests/python/test_stubs.py); without it the script stops before building.
set -euo pipefail
cd "$(dirname "$0")/.."
python=/usr/bin/python3
venv=build/python-venv
[ -x "$python" ] || { echo "python_test: $python is missing (scripts/setup.sh installs python3)" >&2; exit 1; }
"$python" -c "import mypy.stubtest" 2>/dev/null ||
  { echo "python_test: mypy is missing for $python (scripts/setup.sh installs python3-mypy)" >&2; exit 1; }
rm -rf "$venv" python/build python/hullkit.egg-info
"$python" -m venv --system-site-packages "$venv"
HULLKIT_BUILD_JOBS=$(nproc) "$venv/bin/pip" install --quiet --no-build-isolation --no-index ./python
# From outside the source tree, so that `import hullkit` is the installed package; on every core
# with pytest-xdist where it is installed (scripts/setup.sh installs it: the tests are independent
# of each other, and on 2 cores the suite takes about half the time).
workers=()
"$venv/bin/python" -c "import xdist" 2>/dev/null && workers=(-n "$(nproc)")
(cd build && "../$venv/bin/python" -m pytest -q -p no:cacheprovider "${workers[@]}" ../tests/python)
