"""`pip install .`: the package dgwarp (python/dgwarp) and its C++ module
dgwarp._core, built by the project's CMake (docs/PYTHON.md, "Set-up").

The module is configured and built in setuptools' temporary folder (under
build-pip/, not the project's build/) for the interpreter that runs pip, in
Release, without the tests, benchmarks and examples. DGWARP_CMAKE_BUILD_DIR
names an already configured build folder to build the module in instead (the
project's own tests use it, so that they do not compile everything twice);
its interpreter must be the one running pip. DGWARP_BUILD_JOBS: the parallel
build jobs (default: the processors).
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    """The version of project(dgwarp VERSION ...) in CMakeLists.txt: one source."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(\s*dgwarp\s+VERSION\s+([0-9][0-9.]*)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(dgwarp VERSION x.y.z'")
    return match.group(1)


def run(command):
    print("dgwarp:", " ".join(command), flush=True)
    subprocess.run(command, check=True)


class CMakeBuild(build_ext):
    """Builds the CMake target dgwarp_python and copies its module in place."""

    def build_extension(self, ext):
        # The interpreter itself, not a venv's link to it: the module's ABI is its.
        python = os.path.realpath(sys.executable)
        given = os.environ.get("DGWARP_CMAKE_BUILD_DIR")
        build = Path(given).resolve() if given else Path(self.build_temp).resolve() / "cmake"
        if not (build / "CMakeCache.txt").exists():
            if given:
                raise RuntimeError(f"DGWARP_CMAKE_BUILD_DIR={given}: not a configured CMake build folder")
            run(["cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
                 "-DDGWARP_BUILD_TESTS=OFF", "-DDGWARP_BUILD_BENCH=OFF", "-DDGWARP_BUILD_EXAMPLES=OFF",
                 "-DDGWARP_BUILD_PYTHON=ON", f"-DPYTHON_EXECUTABLE={python}"])
        jobs = os.environ.get("DGWARP_BUILD_JOBS", str(os.cpu_count() or 2))
        run(["cmake", "--build", str(build), "--target", "dgwarp_python", "-j", jobs])
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        built = build / "python" / "dgwarp" / f"_core{suffix}"
        if not built.exists():
            found = sorted(p.name for p in (build / "python" / "dgwarp").glob("_core*"))
            raise RuntimeError(f"{built}: not built (found {found or 'nothing'}): the build folder's "
                               f"Python is not {python}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built, target)


def require_debian_packages():
    """NumPy and wheel for the Python running pip: offline they cannot come from PyPI, and Debian's
    are for Debian's Python (a pyenv or conda python3 first on PATH is another one)."""
    missing = []
    for name in ("numpy", "wheel"):
        try:
            __import__(name)
        except ImportError:
            missing.append(name)
    if missing:
        raise RuntimeError(
            f"dgwarp: this Python ({sys.executable} -> {os.path.realpath(sys.executable)}) has no "
            f"{' and no '.join(missing)}. Debian's python3-numpy and python3-wheel are for Debian's Python: "
            "make the venv with /usr/bin/python3 -m venv --system-site-packages (scripts/install-deps.sh "
            "installs them)")


require_debian_packages()

setup(
    version=project_version(),
    packages=["dgwarp"],
    package_dir={"dgwarp": "python/dgwarp"},
    package_data={"dgwarp": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("dgwarp._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": "build-pip"}},
    zip_safe=False,
)
