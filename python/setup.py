# Builds hullkit's Python extension (hullkit._core) from the C++ sources in ../native with
# pybind11, so that `pip install --no-build-isolation ./python` needs nothing from the network:
# setuptools, pybind11 and numpy come from the system (Debian: python3-setuptools,
# python3-pybind11, python3-numpy). The metadata is in pyproject.toml.
import glob
import os

from pybind11.setup_helpers import ParallelCompile, Pybind11Extension, build_ext
from setuptools import setup

here = os.path.dirname(os.path.abspath(__file__))
native = os.path.normpath(os.path.join(here, "..", "native"))


class build_core(build_ext):
    """Adds the core's C++ sources (outside this folder, which setuptools' file lists refuse to
    name) when the extension is compiled."""

    def build_extensions(self):
        if not os.path.isdir(os.path.join(native, "src")):
            raise SystemExit(f"hullkit: the C++ sources are not at {native}; build from the hullkit repository")
        # The core, Delaunay and route checking, in a stable order.
        sources = sorted(
            path for folder in ("", "io", "delaunay", "route") for path in glob.glob(os.path.join(native, "src", folder, "*.cpp")))
        for extension in self.extensions:
            extension.sources = [s for s in extension.sources if s not in sources] + sources
        super().build_extensions()


core = Pybind11Extension(
    "hullkit._core",
    [os.path.join("src", "core.cpp")],
    include_dirs=[os.path.join(native, "include")],
    cxx_std=17,
    # As the native and wasm builds: no FMA contraction, so every platform gives the same bits.
    extra_compile_args=["-O3", "-ffp-contract=off"],
)

# Compile the sources on every core (HULLKIT_BUILD_JOBS overrides).
ParallelCompile("HULLKIT_BUILD_JOBS", default=0).install()

setup(ext_modules=[core], cmdclass={"build_ext": build_core})
