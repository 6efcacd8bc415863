#!/usr/bin/env bash
# Times `lpvid oracle` on N random cases against docs/oracle.md's ten-line outside
# implementation (examples/oracle/my_impl.py, which itself runs lpvid), and
# prints the oracle's table and the wall time. Target (lpvid as the
# oracle): 100 SISO cases with n <= 200 within 5 minutes on 2 cores.
#
#   bash bench/oracle_run.sh [BUILD_DIR] [CASES] [extra oracle flags...]
#   bash bench/oracle_run.sh build 100 --siso --max-n 200
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:-build}" && pwd)"
cases="${2:-100}"
shift $(( $# > 2 ? 2 : $# ))
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
start=$(date +%s.%N)
set +e
LPVID="$build/lpvid" "$build/lpvid" oracle --cases "$cases" --seed 1 --work "$work/cases" \
  --command "python3 $root/examples/oracle/my_impl.py {data} {model} {task} {out}" \
  --report "$work/report.json" "$@"
code=$?
set -e
end=$(date +%s.%N)
python3 - "$work/report.json" "$start" "$end" "$code" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
cases = r["cases"]
outside = sum(c["outside_seconds"] for c in cases)
lpvid = sum(c["lpvid_seconds"] for c in cases)
n = max(c["n"] for c in cases)
print(f"\n{len(cases)} cases (n <= {n}): wall {float(sys.argv[3]) - float(sys.argv[2]):.1f} s, exit {sys.argv[4]}; "
      f"outside commands {outside:.1f} s, lpvid's own certification {lpvid:.1f} s (they overlap); totals {r['totals']}")
PY
