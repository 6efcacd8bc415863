"""The pip package's metadata, as pip builds it (setuptools' PEP 517 hook,
the one `pip install --no-build-isolation .` calls), against what CMake and
the repository say: version = CMake's PROJECT_VERSION (argument 2, CMake's
own reading of CMakeLists.txt), license = LICENSE's first line, a setuptools
backend, numpy required, extras plot (matplotlib) and pandas.

    package_metadata_test.py <source dir> <CMake PROJECT_VERSION> <work dir>
"""

import email
import os
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

source, cmake_version, work = Path(sys.argv[1]), sys.argv[2], Path(sys.argv[3])
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


pyproject = tomllib.loads((source / "pyproject.toml").read_text())
check(pyproject["build-system"]["build-backend"] == "setuptools.build_meta", "backend setuptools.build_meta")
check(pyproject["project"]["dynamic"] == ["version"], "version is dynamic (from CMakeLists.txt)")

shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
hook = ("import sys, setuptools.build_meta as b; "
        "print(b.prepare_metadata_for_build_wheel(sys.argv[1]))")
out = subprocess.run([sys.executable, "-c", hook, str(work)], cwd=source, check=True,
                     capture_output=True, text=True).stdout.split()[-1]
meta = email.message_from_string((work / out / "METADATA").read_text())
check(meta["Name"] == "lpvid", f"Name: {meta['Name']}")
check(meta["Version"] == cmake_version, f"Version: {meta['Version']} (CMake: {cmake_version})")
license_name = (source / "LICENSE").read_text().split()[0]
check(meta["License"] == license_name, f"License: {meta['License']} (LICENSE: {license_name})")
requires = meta.get_all("Requires-Dist")
check("numpy" in requires, "Requires-Dist: numpy")
check(sorted(meta.get_all("Provides-Extra")) == ["pandas", "plot"], "extras pandas, plot")
check("matplotlib ; extra == 'plot'" in requires, "plot -> matplotlib")
check("pandas ; extra == 'pandas'" in requires, "pandas -> pandas")
check(meta["Requires-Python"] is not None, f"Requires-Python: {meta['Requires-Python']}")
shutil.rmtree(work)
sys.exit(1 if failures else 0)
