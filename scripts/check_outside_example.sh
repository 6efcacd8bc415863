#!/usr/bin/env bash
# Installs the already-built tree `build` to a temporary prefix, builds
# examples/outside_project against it (find_package(lpvid) with only
# CMAKE_PREFIX_PATH pointing there) and runs it: the package is usable from
# outside. Run after scripts/test.sh (which builds `build`).
set -euo pipefail
cd "$(dirname "$0")/.."
export OPENBLAS_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"

cmake --install build --prefix "$prefix" > "$work/install.log"
echo "installed to $prefix: $(find "$prefix" -type f | wc -l) files"
generator=()
if command -v ninja > /dev/null; then generator=(-G Ninja); fi
cmake -S examples/outside_project -B "$work/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_COMPILE_WARNING_AS_ERROR=ON > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
grep -E '^-- lpvid' "$work/configure.log"
cmake --build "$work/build" -j "$(nproc 2>/dev/null || echo 2)"

echo "=== certify_and_check (lpvid::lib): certify Example 1's true model, check it exactly ==="
"$work/build/certify_and_check" fixtures/example1 "$work/example1.cert.json"
echo "=== exact_check (lpvid::verify only): exact PSD decisions, and the same certificate ==="
"$work/build/exact_check" fixtures/example1 "$work/example1.cert.json"
echo "=== the installed lpvid-verify on the same certificate ==="
"$prefix/bin/lpvid-verify" certificate "$work/example1.cert.json"
echo "outside example: OK"
