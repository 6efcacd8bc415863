#!/usr/bin/env bash
# Peak memory and time of `lpvid-verify certificate` on paper-mode (form "w")
# certificates of the paper's Example 1 for growing n.
# For each n: `lpvid generate example1 --n N`, then `lpvid invalidate
# --toeplitz paper` with the true model writes the certificate (the SDP takes
# most of the time: ~30 s at n = 100), then every verifier given is run under
# /usr/bin/time -v. Prints: n, verifier, exit code, wall seconds, maximum
# resident set size (MB), and the (C1) matrix that was decided.
#   bash bench/wform_memory.sh [build-dir] [n ...]        (default: build, 40 100 200)
# VERIFIERS="old/lpvid-verify build/lpvid-verify" compares builds (default:
# the build's own); TIMEOUT (seconds, default 900) ends a run (exit 124).
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(40 100 200)
verifiers=${VERIFIERS:-$build/lpvid-verify}
limit=${TIMEOUT:-900}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%6s  %-40s %5s %9s %9s  %s\n' "n" "verifier" "exit" "seconds" "RSS_MB" "(C1) decided on"
for n in "${sizes[@]}"; do
  dir=$work/n$n
  mkdir -p "$dir"
  "$build/lpvid" generate example1 --n "$n" --out "$dir/data.csv" --truth-out "$dir/truth.json" >/dev/null ||
    { echo "generate failed for n = $n"; exit 1; }
  "$build/lpvid" invalidate --data "$dir/data.csv" --model "$dir/truth.json" --toeplitz paper \
    --certificate "$dir/c.json" >"$dir/invalidate.txt" 2>&1 ||
    { echo "no certificate for n = $n:"; tail -3 "$dir/invalidate.txt"; continue; }
  for v in $verifiers; do
    timeout "$limit" /usr/bin/time -v "$v" certificate "$dir/c.json" >"$dir/out.txt" 2>"$dir/time.txt"
    code=$?
    secs=$(awk -F': ' '/Elapsed \(wall clock\)/ { n = split($2, t, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + t[i]; print s }' "$dir/time.txt")
    rss=$(awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$dir/time.txt")
    what=$(grep -o '(C1) [a-z]*: [^(]*([^)]*)* *(size [0-9]*)\|(C1) [a-z]*: [^(]*' "$dir/out.txt" | head -1 | cut -c1-60)
    size=$(grep -o '(size [0-9]*)' "$dir/out.txt" | tail -1)
    printf '%6s  %-40s %5s %9s %9s  %s %s\n' "$n" "$v" "$code" "${secs:--}" "${rss:--}" "$what" "$size"
  done
done
