# Builds hullkit's Python extension (hullkit._core) with the project's CMake: the repository is
# configured with -DHULLKIT_PYTHON=ON (python/CMakeLists.txt: pybind11_add_module linking the
# hullkit static libraries) and that one target is built, so `pip install --no-build-isolation
# ./python` needs nothing from the network: cmake, a C++17 compiler, pybind11 and numpy come from
# the system (Debian: cmake, g++, pybind11-dev, python3-pybind11, python3-numpy, python3-dev).
# The metadata is in pyproject.toml.
import os
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

here = os.path.dirname(os.path.abspath(__file__))
repository = os.path.dirname(here)


class cmake_build(build_ext):
    """Builds each extension with CMake instead of setuptools' compiler calls."""

    def build_extension(self, extension):
        if not os.path.isfile(os.path.join(repository, "CMakeLists.txt")):
            raise SystemExit(f"hullkit: no CMakeLists.txt at {repository}; build from the hullkit repository")
        target = os.path.abspath(self.get_ext_fullpath(extension.name))
        build = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        os.makedirs(build, exist_ok=True)
        jobs = os.environ.get("HULLKIT_BUILD_JOBS") or str(os.cpu_count() or 1)
        configure = [
            "cmake", "-S", repository, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
            "-DHULLKIT_PYTHON=ON", "-DHULLKIT_TESTS=OFF", "-DHULLKIT_BENCH=OFF", "-DHULLKIT_CLI=OFF",
            "-DHULLKIT_INSTALL=OFF", f"-DPython_EXECUTABLE={sys.executable}",
            f"-DHULLKIT_PYTHON_OUTPUT_DIR={os.path.dirname(target)}",
        ]
        subprocess.run(configure, check=True)
        subprocess.run(["cmake", "--build", build, "--target", "hullkit_python", "-j", jobs], check=True)
        if not os.path.exists(target):
            raise SystemExit(f"hullkit: CMake did not produce {target}")


setup(ext_modules=[Extension("hullkit._core", sources=[])], cmdclass={"build_ext": cmake_build})
