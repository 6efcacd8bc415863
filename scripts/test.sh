#!/usr/bin/env bash
# Builds lpvid and runs every test. `--sanitize` builds a separate ASan/UBSan
# tree and runs there the input parsers (CSV, model, number text, matrix,
# certificate: random corruptions included), the exact verifier and PSD
# decision, and the hostile-input tests of both command-line programs.
set -euo pipefail
cd "$(dirname "$0")/.."
export OPENBLAS_NUM_THREADS=1
jobs=$(nproc 2>/dev/null || echo 2)
if [ "${1:-}" = "--sanitize" ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DLPVID_SANITIZE=ON -DLPVID_BUILD_BENCH=OFF
  cmake --build build-asan -j "$jobs" --target lpvid_core_tests lpvid_data_tests lpvid_model_tests lpvid_verify_tests lpvid_cli_tests lpvid_jobs_tests lpvid lpvid-verify 2>/dev/null \
    || cmake --build build-asan -j "$jobs"
  # -E: `lpvid diagnose` end to end (its name says "Verified"), no parser test
  ctest --test-dir build-asan -j "$jobs" --output-on-failure -R 'Parse|Parser|Csv|ModelFile|Monomial|NumberText|Psd|Verif|Static|Hostile' \
    -E 'DiagnoseCommandTest'
else
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
  cmake --build build -j "$jobs"
  ctest --test-dir build -j "$jobs" --output-on-failure
fi
