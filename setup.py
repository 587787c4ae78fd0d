"""Builds the Python module `radiosity` with the project's CMake build (python/CMakeLists.txt):
`pip install --no-build-isolation .` from the repository root (docs/guide/python.md).

Only the module's target is built, for the interpreter running pip, in build/pip/; the package's
pure-Python part is python/src/radiosity/. CMAKE_BUILD_PARALLEL_LEVEL sets the compile jobs
(default 2)."""

import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(ROOT, "CMakeLists.txt")) as f:
    VERSION = re.search(r"project\(radiosity VERSION ([0-9.]+)", f.read()).group(1)  # the version, written once


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # RADIOSITY_BUILD_DIR: a build of this repository that has built the module for this
        # interpreter (scripts/setup.sh's build/): the module is installed from there as it is,
        # with no second build and no change to that tree (the test python_pip_install uses it).
        build = os.environ.get("RADIOSITY_BUILD_DIR")
        if build:
            build = os.path.abspath(build)
        else:
            build = os.path.join(ROOT, "build", "pip", "cmake")
            subprocess.check_call(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                                   "-DRADIOSITY_PYTHON=ON", "-DRADIOSITY_BUILD_TESTS=OFF",
                                   "-DPython_EXECUTABLE=" + sys.executable])
            jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")
            subprocess.check_call(["cmake", "--build", build, "--target", "_radiosity", "-j", jobs])
        built = [f for f in os.listdir(os.path.join(build, "python", "radiosity")) if f.startswith("_radiosity")]
        if len(built) != 1:
            sys.exit("setup.py: expected one _radiosity module in %s, found %s" % (build, built))
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(build, "python", "radiosity", built[0]), target)


setup(
    version=VERSION,
    package_dir={"": "python/src"},
    packages=["radiosity"],
    ext_modules=[Extension("radiosity._radiosity", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": os.path.join("build", "pip")}},
)
