"""Builds the module swn._swn with the project's CMake (python/pyproject.toml names this file's backend).

The repository's CMake project is configured with only the Python module on (no tests, examples or tool)
in a build directory of its own, the target _swn is built, and `cmake --install --component python`
puts the package (swn/__init__.py and the compiled module) where setuptools collects it. Nothing is
downloaded: CGAL, Eigen, Boost, pybind11, ... come from the system (Debian packages, scripts/install-deps).

Environment: CMAKE_ARGS (more arguments for the configure step, e.g. -DCMAKE_CXX_COMPILER_LAUNCHER=ccache),
CMAKE_BUILD_PARALLEL_LEVEL (jobs, default 2), SWN_CMAKE_BUILD_DIR (an existing build directory of the
project, configured with -DCGAL_SWN_BUILD_PYTHON=ON for this Python: it is built and installed from
instead of configuring a new one).
"""

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(\S+\s+VERSION\s+([0-9.]+)", text).group(1)


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        destination = Path(self.get_ext_fullpath(ext.name)).resolve().parents[1]   # above swn/
        build = os.environ.get("SWN_CMAKE_BUILD_DIR")
        if build is None:
            build = str(Path(self.build_temp).resolve() / "cmake")
            subprocess.run(["cmake", "-S", str(ROOT), "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                            "-DCGAL_SWN_BUILD_PYTHON=ON", "-DCGAL_SWN_BUILD_TESTS=OFF",
                            "-DCGAL_SWN_BUILD_EXAMPLES=OFF", "-DCGAL_SWN_BUILD_TOOL=OFF",
                            f"-DPython_EXECUTABLE={sys.executable}",
                            *shlex.split(os.environ.get("CMAKE_ARGS", ""))], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
        subprocess.run(["cmake", "--build", build, "--target", "_swn", "-j", jobs], check=True)
        subprocess.run(["cmake", "--install", build, "--component", "python", "--prefix", str(destination)],
                       check=True)


setup(version=project_version(), packages=["swn"], ext_modules=[CMakeExtension("swn._swn")],
      cmdclass={"build_ext": CMakeBuild}, zip_safe=False)
