"""Builds the Python package lpvid: the pure-Python files of python/lpvid/
and the extension lpvid._lpvid, built by CMake (target lpvid_python) for the
interpreter running this build. Metadata is in pyproject.toml; the version is
CMakeLists.txt's `project(lpvid VERSION x.y.z)`, read here.

    pip install --no-build-isolation .        # docs/python_install.md

Environment:
    LPVID_CMAKE_BUILD_DIR  an already configured CMake build tree to reuse
                           (only lpvid_python is built there, no configure);
                           default: a fresh tree under setuptools' build_temp.
"""

import os
import re
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, find_namespace_packages, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
TARGET = "lpvid_python"


def cmake_project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    m = re.search(r"project\(\s*lpvid\s+VERSION\s+([0-9][0-9.]*)", text)
    if not m:
        sys.exit("setup.py: no `project(lpvid VERSION x.y.z)` in CMakeLists.txt")
    return m.group(1)


def run(cmd, **kw):
    print("+ " + " ".join(str(c) for c in cmd), flush=True)
    subprocess.run([str(c) for c in cmd], check=True, **kw)


def cached_value(build_dir, name):
    for line in (build_dir / "CMakeCache.txt").read_text().splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1]
    return None


class CMakeBuild(build_ext):
    """build_ext that builds lpvid._lpvid with the repository's CMake."""

    def build_extension(self, ext):
        reuse = os.environ.get("LPVID_CMAKE_BUILD_DIR")
        build_dir = Path(reuse).resolve() if reuse else Path(self.build_temp).resolve() / "cmake"
        if reuse:
            self.check_reused_tree(build_dir)
        else:
            self.configure(build_dir)
        jobs = os.cpu_count() or 1
        run(["cmake", "--build", build_dir, "--target", TARGET, "-j", jobs])
        built = build_dir / "python" / "lpvid" / ("_lpvid" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.is_file():
            sys.exit(f"setup.py: CMake built no {built.name} in {built.parent} "
                     f"(the tree was configured for another Python? {sys.executable} needs this name)")
        dest = Path(self.get_ext_fullpath(ext.name))
        dest.parent.mkdir(parents=True, exist_ok=True)
        print(f"copying {built} -> {dest}", flush=True)
        shutil.copyfile(built, dest)

    def configure(self, build_dir):
        build_dir.mkdir(parents=True, exist_ok=True)
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        run(["cmake", "-S", ROOT, "-B", build_dir, *generator,
             "-DCMAKE_BUILD_TYPE=Release",
             f"-DPython3_EXECUTABLE={sys.executable}",
             "-DLPVID_BUILD_PYTHON=ON", "-DLPVID_BUILD_TESTS=OFF", "-DLPVID_BUILD_BENCH=OFF"])

    def check_reused_tree(self, build_dir):
        if not (build_dir / "CMakeCache.txt").is_file():
            sys.exit(f"setup.py: LPVID_CMAKE_BUILD_DIR={build_dir} is not a configured CMake build tree "
                     "(no CMakeCache.txt)")
        if cached_value(build_dir, "LPVID_BUILD_PYTHON") != "ON":
            sys.exit(f"setup.py: LPVID_CMAKE_BUILD_DIR={build_dir} does not build the Python module "
                     "(LPVID_BUILD_PYTHON is not ON in its CMakeCache.txt)")
        python = cached_value(build_dir, "_Python3_EXECUTABLE")
        print(f"reusing the CMake build tree {build_dir} (LPVID_CMAKE_BUILD_DIR), "
              f"configured for the Python {python}", flush=True)


setup(
    version=cmake_project_version(),
    package_dir={"": "python"},
    packages=find_namespace_packages(where="python", include=["lpvid", "lpvid.*"], exclude=["*.__pycache__"]),
    # py.typed: the package's type hints are for type checkers too (PEP 561)
    package_data={"lpvid": ["py.typed"]},
    ext_modules=[Extension("lpvid._lpvid", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
    # setuptools' own build folder (default build/, the CMake tree of
    # scripts/test.sh) kept apart; ignored by git like every /build*/
    options={"build": {"build_base": str(ROOT / "build-python")}},
)
