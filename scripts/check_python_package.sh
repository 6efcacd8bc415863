#!/usr/bin/env bash
# Installs the checkout as the Python package lpvid with pip, offline, into a
# fresh virtual environment that sees Debian's packages (numpy, matplotlib,
# pandas, setuptools), reusing the already-built CMake tree `build` (no second
# C++ build), then imports the installed package from outside the checkout.
# Run after scripts/test.sh (which builds `build`). docs/python_install.md.
set -euo pipefail
cd "$(dirname "$0")/.."
export OPENBLAS_NUM_THREADS=1
checkout=$PWD
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Runs the package's example scripts with the venv's interpreter ($1), from a
# folder outside the checkout, with the figures drawn into it: each script
# exits non-zero when a step does not give its expected answer.
run_python_examples() {
  local python=$1 script
  for script in "$checkout"/examples/python/*.py; do
    echo "example: ${script#$checkout/}"
    "$python" "$script" --ctrl-c "$work/figures"
  done
}

/usr/bin/python3 -m venv --system-site-packages "$work/venv"
python="$work/venv/bin/python"
start=$(date +%s)
# --no-index: everything comes from Debian (the proof that no index is needed);
# --no-build-isolation: the build uses Debian's setuptools and wheel.
LPVID_CMAKE_BUILD_DIR="$checkout/build" \
  "$python" -m pip install --no-index --no-build-isolation "$checkout" > "$work/pip.log" 2>&1 \
  || { cat "$work/pip.log"; exit 1; }
echo "pip install (reusing build/): $(( $(date +%s) - start )) s"
"$python" -m pip show lpvid
cd "$work"
"$python" -c "import lpvid, os; print('lpvid', lpvid.__version__, 'from', os.path.dirname(lpvid.__file__))"
"$python" -c "import lpvid; assert not lpvid.__file__.startswith('$checkout'), lpvid.__file__"
run_python_examples "$python"
echo "python package: OK"
