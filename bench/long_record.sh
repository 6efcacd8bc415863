#!/usr/bin/env bash
# A long record past one machine: `lpvid jobs plan` cuts it into windows,
# any batch engine runs one `lpvid invalidate` per window (here xargs -P),
# `lpvid jobs merge` re-checks every certificate and assembles the report.
#
# Usage: bench/long_record.sh [samples=100000] [parallel=2] [windows_to_run=all] [lpvid=build/lpvid]
# The record: the SISO LPV system of fixtures/example2/true_model.json without
# its offset (x+ = [0 1; -(0.24+0.1 rho) 0.9-0.4 rho] x + [0; 1] u,
# y = (1 + 0.5 rho) x1), rho a slow sweep of [0.05, 0.95], u random +-0.5
# pulses, white output noise of standard deviation 0.1; simulated in double
# by the python3 below and written with 10 decimals. Each window is certified
# for that model at delta = 0.1 (min d_max, both ends of the interval).
# windows_to_run < all runs only the first ones (then merge reports the rest
# as missing) to measure a window and extrapolate.
set -euo pipefail
N=${1:-100000}
P=${2:-2}
RUN=${3:-all}
LPVID=${4:-build/lpvid}
W=$(mktemp -d /tmp/lpvid_long_record.XXXXXX)
echo "work folder $W" >&2

python3 - "$N" "$W/record.csv" <<'EOF'
import math, random, sys
n, path = int(sys.argv[1]), sys.argv[2]
rng = random.Random(1)
x1 = x2 = 0.0
u, hold = 0.0, 0
with open(path, "w") as f:
    f.write("u1,y1,rho1\n")
    for k in range(n):
        if hold == 0:
            u, hold = rng.choice((-0.5, 0.5)), rng.randint(1, 5)
        hold -= 1
        rho = round(0.5 - 0.45 * math.cos(2 * math.pi * k / 2000.0), 4)
        y = (1 + 0.5 * rho) * x1 + rng.gauss(0.0, 0.1)
        f.write(f"{u},{y:.10f},{rho}\n")
        x1, x2 = x2, -(0.24 + 0.1 * rho) * x1 + (0.9 - 0.4 * rho) * x2 + u
EOF
cat > "$W/model.json" <<'EOF'
{
  "format": "lpvid-model/1",
  "states": 2, "inputs": 1, "outputs": 1,
  "scheduling": ["rho1"],
  "columns": {"u": ["u1"], "y": ["y1"], "rho": ["rho1"]},
  "initial": {
    "A": [{"basis": "1", "value": [[0, 1], ["-0.24", "0.9"]]}, {"basis": "rho1", "value": [[0, 0], ["-0.1", "-0.4"]]}],
    "B": [{"basis": "1", "value": [[0], [1]]}],
    "C": [{"basis": "1", "value": [[1, 0]]}, {"basis": "rho1", "value": [["0.5", 0]]}],
    "D": []
  },
  "uncertainty": {"structure": "multiplicative", "weight": "0.01"}
}
EOF

t0=$(date +%s.%N)
"$LPVID" jobs plan --data "$W/record.csv" --model "$W/model.json" --delta 0.1 --dir "$W/jobs" > "$W/plan.txt"
t1=$(date +%s.%N)
JOBS="$W/jobs/jobs.txt"
[ "$RUN" = all ] || { head -n "$RUN" "$JOBS" > "$W/jobs/some.txt"; JOBS="$W/jobs/some.txt"; }
echo "running $(wc -l < "$JOBS") of $(wc -l < "$W/jobs/jobs.txt") jobs, $P at a time" >&2
# xargs stops nothing on a failing job; merge is the judge
xargs -P "$P" -d '\n' -n 1 sh -c < "$JOBS" > "$W/jobs.log" 2>&1 || true
t2=$(date +%s.%N)
"$LPVID" jobs merge --dir "$W/jobs" --quiet > "$W/merge.txt" || true
t3=$(date +%s.%N)
tail -n 6 "$W/merge.txt"
awk -v a="$t0" -v b="$t1" -v c="$t2" -v d="$t3" -v jobs="$(wc -l < "$JOBS")" -v all="$(wc -l < "$W/jobs/jobs.txt")" -v p="$P" 'BEGIN {
  printf "samples %d, windows %d (ran %d, %d at a time)\n", '"$N"', all, jobs, p;
  printf "plan %.1f s, jobs %.1f s (%.2f s per window per process), merge %.1f s (%.3f s per window)\n",
         b - a, c - b, (c - b) * p / jobs, d - c, (d - c) / jobs }'
du -sh "$W/jobs" | awk '{print "job folder " $1}'
