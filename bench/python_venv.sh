# Sourced by the Python benchmarks (python_run.sh, spatial_nd_run.sh): sets `venv` to
# build/python-bench-venv and installs hullkit from ./python into it (Debian's /usr/bin/python3, its
# numpy, scipy and dask seen through --system-site-packages), unless HULLKIT_BENCH_NO_BUILD=1 and
# it is there already. Needs `say` from the sourcing script.
venv=build/python-bench-venv
if [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ] || [ ! -x "$venv/bin/python" ]; then
  say "installing hullkit from ./python into $venv (Debian's /usr/bin/python3 and its numpy, scipy, dask)"
  rm -rf "$venv" python/build python/hullkit.egg-info
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  HULLKIT_BUILD_JOBS=$(nproc) "$venv/bin/pip" install --quiet --no-build-isolation --no-index ./python
fi
