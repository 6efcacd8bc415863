#!/usr/bin/env bash
# Times hostile and mistaken inputs against the built binaries and prints a
# table: case, exit code, wall seconds, first line of the message. Every case
# must end within 10 s with its documented exit code (docs/exit_codes.md).
#   bash bench/hostile_inputs.sh [build-dir]      (default: build)
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
lpvid=$build/lpvid
verify=$build/lpvid-verify
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
data=fixtures/example1/noise_free_n40.csv
model=fixtures/example1/true_model.json

cp "$data" "$work/data.csv"
"$lpvid" invalidate --data "$work/data.csv" --model "$model" --certificate "$work/c.json" >/dev/null 2>&1 \
  || { echo "could not make the base certificate"; exit 1; }
# A field of the certificate replaced (the value of "delta2" is a JSON string).
tamper() { sed -E "s|\"delta2\": \"[^\"]*\"|\"delta2\": \"$1\"|" "$work/c.json" >"$2"; }
tamper "1/1$(printf '0%.0s' $(seq 1 100000))" "$work/denominator.json"
tamper "1e4000" "$work/exp4000.json"
tamper "1/1$(printf '0%.0s' $(seq 1 5000))" "$work/tiny5000.json"
# A static output polynomial of degree 2000.
coeffs="0, 1$(printf ', 0%.0s' $(seq 1 1999))"
sed '$ d' "$model" >"$work/degree2000.json"
printf ',\n  "static": {"output": {"kind": "polynomial", "coefficients": [%s]}}\n}\n' "$coeffs" >>"$work/degree2000.json"
# M = v v^T - 1e-50 I, n = 2000, v_i = (i mod 17) + 1: indefinite by 1e-50.
awk -v n=2000 'BEGIN {
  nines = ""; for (k = 0; k < 50; ++k) nines = nines "9";
  for (i = 0; i < n; ++i) {
    line = "";
    for (j = 0; j < n; ++j) {
      p = ((i % 17) + 1) * ((j % 17) + 1);
      line = line (j ? " " : "") (i == j ? (p - 1) "." nines : p);
    }
    print line;
  }
}' >"$work/rank1.txt"

printf '%-52s %5s %8s  %s\n' "case" "exit" "seconds" "message"
run() {
  local name=$1; shift
  local start end code
  start=$(date +%s.%N)
  timeout 60 "$@" >"$work/out.txt" 2>&1
  code=$?
  end=$(date +%s.%N)
  printf '%-52s %5s %8.2f  %s\n' "$name" "$code" "$(awk -v a="$start" -v b="$end" 'BEGIN { print b - a }')" \
    "$(grep -m1 -E '^(lpvid:|lpvid-verify|NOT_PSD|PSD|PD|consistent|invalid)' "$work/out.txt" | cut -c1-90)"
}
run "lpvid invalidate --data /dev/zero" "$lpvid" invalidate --data /dev/zero --model "$model"
run "lpvid-verify psd /dev/zero" "$verify" psd /dev/zero
run "lpvid-verify certificate /dev/zero" "$verify" certificate /dev/zero
run "certificate with a 10^5-digit denominator" "$verify" certificate "$work/denominator.json"
run "certificate with delta2 = 1e4000" "$verify" certificate "$work/exp4000.json"
run "certificate with delta2 = 1/10^5000" "$verify" certificate "$work/tiny5000.json"
run "model with a degree-2000 polynomial map" "$lpvid" invalidate --data "$data" --model "$work/degree2000.json"
run "psd of 2000x2000 v v^T - 1e-50 I" "$verify" psd "$work/rank1.txt"
run "report to a missing directory" "$lpvid" invalidate --data "$data" --model "$model" \
  --certificate "$work/left.json" --report "$work/missing/r.json"
run "simulate --out to a missing directory" "$lpvid" simulate --data "$data" --model "$model" --out /nonexistent/x.csv
[ -e "$work/left.json" ] && echo "FAIL: the failed run left its certificate behind" && exit 1
exit 0
