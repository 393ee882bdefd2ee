"""Builds and installs the `hedge` package, with its native module built by the project's CMake.

Offline on Debian 12 (no PyPI needed), from the repository's root:

    python3 -m venv --system-site-packages venv
    venv/bin/pip install --no-index --no-build-isolation ./bindings/python

The native module (hedge._hedge) is configured and built from the whole project (the library and
the binding core are compiled into it), then copied into the package. Set HEDGE_BUILD_JOBS to
limit the build's parallelism.
"""

import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def project_version():
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(hedge VERSION ([0-9.]+)", f.read()).group(1)


class CMakeExtension(Extension):
    """An extension whose sources CMake knows: setuptools compiles nothing itself."""

    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    """Configures the project with HEDGE_BUILD_PYTHON=ON, builds the module, copies it in place."""

    def build_extension(self, ext):
        build_dir = os.path.abspath(os.path.join(self.build_temp, "cmake"))
        configure = [
            "cmake",
            "-S",
            ROOT,
            "-B",
            build_dir,
            "-DCMAKE_BUILD_TYPE=Release",
            "-DHEDGE_BUILD_PYTHON=ON",
            "-DHEDGE_BUILD_TESTS=OFF",
            "-DHEDGE_BUILD_TOOLS=OFF",
            "-DHEDGE_BUILD_CAPI_TESTS=OFF",
            "-DPython_EXECUTABLE=" + sys.executable,
        ]
        if shutil.which("ninja"):
            configure += ["-G", "Ninja"]
        subprocess.check_call(configure)
        jobs = os.environ.get("HEDGE_BUILD_JOBS", str(os.cpu_count() or 1))
        subprocess.check_call(["cmake", "--build", build_dir, "--target", "hedge_python", "--parallel", jobs])
        built = glob.glob(os.path.join(build_dir, "bindings", "python", "package", "hedge", "_hedge*.so"))
        if len(built) != 1:
            raise RuntimeError("the CMake build made no single hedge/_hedge*.so in " + build_dir)
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    name="hedge",
    version=project_version(),
    description="Half-edge meshes with numpy arrays in and out, zero-copy views and in-place edits",
    license="MIT",
    packages=["hedge"],
    package_data={"hedge": ["*.pyi", "py.typed"]},
    ext_modules=[CMakeExtension("hedge._hedge")],
    cmdclass={"build_ext": CMakeBuild},
    python_requires=">=3.9",
    install_requires=["numpy"],
    zip_safe=False,
)
