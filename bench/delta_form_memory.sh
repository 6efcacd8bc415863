#!/usr/bin/env bash
# Peak memory and time of `lpvid-verify certificate` on a Δ-form certificate
# with a long horizon (n = 3000 certificates were reported to need 3.2 GB).
# The SDP of `lpvid invalidate` does not reach n = 3000 on this machine (CSDP
# used 10 GB and > 20 min before it was stopped), so the certificate is
# written directly: Example 1 data from `lpvid generate example1 --n N`, the
# true model, K = 64 random taps (entries k/10^7, |k| < 1000, seed 3), δ² =
# (Σ_t Σ_ij |Δ_t(i,j)|)² ≥ ‖T_Δ‖² (a true claim) and d_max² = 10^6 (true).
#   bash bench/delta_form_memory.sh [build-dir] [n]        (default: build 3000)
# VERIFIERS="old/lpvid-verify build/lpvid-verify" compares builds.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
n=${2:-3000}
verifiers=${VERIFIERS:-$build/lpvid-verify}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/lpvid" generate example1 --n "$n" --noise-std 0.31622776601683794 --out "$work/d.csv" --truth-out "$work/t.json" \
  >/dev/null || { echo "generate failed"; exit 1; }
python3 - "$work" "$n" <<'PY'
import hashlib, json, random, sys
from fractions import Fraction
work, n = sys.argv[1], int(sys.argv[2])
random.seed(3)
taps = [[Fraction(random.randint(-999, 999), 10**7) for _ in range(4)] for _ in range(64)]
bound = sum(sum(abs(x) for x in row) for row in taps)  # ||T|| <= sum_t ||D_t||_F <= this
text = lambda q: f"{q.numerator}/{q.denominator}" if q.denominator != 1 else str(q.numerator)
cert = {"format": "lpvid-certificate/1", "claim": "consistent",
        "data": {"file": "d.csv", "sha256": hashlib.sha256(open(f"{work}/d.csv", "rb").read()).hexdigest()},
        "model": json.load(open(f"{work}/t.json")), "toeplitz_mode": "signal", "noise_normalisation": "rms",
        "delta2": text(bound * bound), "dmax2": "1000000", "form": "delta",
        "delta_taps": [[text(x) for x in row] for row in taps], "delta_horizon": n,
        "info": {"tool": "bench/delta_form_memory.sh"}}
json.dump(cert, open(f"{work}/c.json", "w"))
PY
printf '%6s  %-40s %5s %9s %9s  %s\n' "n" "verifier" "exit" "seconds" "RSS_MB" "(C1) matrix size"
for v in $verifiers; do
  /usr/bin/time -v "$v" certificate "$work/c.json" >"$work/out.txt" 2>"$work/time.txt"
  code=$?
  secs=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + t[i]; print s }' "$work/time.txt")
  rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$work/time.txt")
  printf '%6s  %-40s %5s %9s %9s  %s\n' "$n" "$v" "$code" "${secs:--}" "${rss:--}" "$(grep -o '(size [0-9]*)' "$work/out.txt" | tail -1)"
done
