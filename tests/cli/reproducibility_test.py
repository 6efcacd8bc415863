#!/usr/bin/env python3
"""The same answer under any load and any thread count (ctest Reproducibility).

`lpvid diagnose` runs twice on one generated case (`lpvid generate
effect-case`, as scripts/demo.sh does without the measured data):
  1. quiet: --threads 1;
  2. loaded: the default thread count, beside one busy-loop process per core
     (started here, killed at the end whatever happens).
The two reports must be equal once the fields that measure time are left
out (their names end in "seconds" or are "elapsed"/"time"; the file names of
run 2 are mapped back onto run 1's folder), and every certificate file must
be byte for byte the same. Every bound must be verified in both runs. No
wall clock may decide a result (solvers/watchdog_child.h, core/deadline.h),
and --threads only changes how fast the same jobs finish.

    python3 reproducibility_test.py LPVID_EXE WORK_DIR
"""
import filecmp
import glob
import json
import os
import shutil
import subprocess
import sys
import time

TIMING_KEYS = ("elapsed", "time")


def strip_timing(value, run_dir):
    """The report without its timing fields, with run_dir's paths made relative."""
    if isinstance(value, dict):
        return {k: strip_timing(v, run_dir) for k, v in value.items()
                if not (k.endswith("seconds") or k in TIMING_KEYS)}
    if isinstance(value, list):
        return [strip_timing(v, run_dir) for v in value]
    if isinstance(value, str):
        return value.replace(run_dir, "<run>")
    return value


def first_difference(a, b, path="report"):
    """The path of the first field where a and b differ, with both values."""
    if type(a) is not type(b):
        return f"{path}: {a!r} != {b!r}"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{path}.{k}: only in one report"
            d = first_difference(a[k], b[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path}: lengths {len(a)} != {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{path}: {a!r} != {b!r}"


def run(cmd, env):
    started = time.monotonic()
    p = subprocess.run(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return p, time.monotonic() - started


def generate_case(exe, work, env, n):
    """A fresh folder work holding the generated demo's case (output_polynomial, seed 3, n samples) in
    work/case; returns that folder."""
    shutil.rmtree(work, ignore_errors=True)
    case = work + "/case"
    os.makedirs(case)
    p, _ = run([exe, "generate", "effect-case", "--effect", "output_polynomial", "--n", str(n), "--seed", "3",
                "--out", case + "/est.csv", "--validation-out", case + "/test.csv",
                "--model-out", case + "/declared.json"], env)
    if p.returncode != 0:
        sys.exit(f"FAIL: generate exited {p.returncode}\n{p.stderr}")
    return case


def diagnose(exe, case, run_dir, threads, env):
    os.makedirs(run_dir, exist_ok=True)
    cmd = [exe, "diagnose", "--data", case + "/est.csv", "--model", case + "/declared.json",
           "--test", case + "/test.csv", "--warmup", "10", "--max-effects", "1", "--window-length", "100",
           "--report", run_dir + "/r.report.json", "--model-out", run_dir + "/after.json"]
    if threads:
        cmd += ["--threads", str(threads)]
    p, seconds = run(cmd, env)
    if p.returncode != 0:
        sys.exit(f"FAIL: diagnose ({'--threads ' + str(threads) if threads else 'default threads'}) "
                 f"exited {p.returncode}\n{p.stderr[-3000:]}")
    return seconds


def main():
    exe, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    case = generate_case(exe, work, env, 200)

    quiet = diagnose(exe, case, work + "/quiet", 1, env)
    cores = os.cpu_count() or 1
    busy = [subprocess.Popen(["sh", "-c", "while :; do :; done"]) for _ in range(cores)]
    try:
        loaded = diagnose(exe, case, work + "/loaded", 0, env)
    finally:
        for b in busy:
            b.kill()
        for b in busy:
            b.wait()
    print(f"quiet (--threads 1): {quiet:.1f} s; loaded (default threads, {cores} busy loops): {loaded:.1f} s")

    reports = []
    for name in ("quiet", "loaded"):
        with open(f"{work}/{name}/r.report.json") as f:
            reports.append(strip_timing(json.load(f), f"{work}/{name}"))
    diff = first_difference(reports[0], reports[1])
    if diff:
        sys.exit("FAIL: the reports differ (timing fields left out): " + diff)
    verified = [w.get("verified") for side in ("before", "after") for w in reports[0].get(side, {}).get("windows", [])]
    certs = sorted(os.path.basename(c) for c in glob.glob(f"{work}/quiet/*.cert*.json"))
    if not certs or not verified or not all(verified):
        sys.exit(f"FAIL: expected every bound verified with a certificate; verified {verified}, files {certs}")
    loaded_certs = sorted(os.path.basename(c) for c in glob.glob(f"{work}/loaded/*.cert*.json"))
    if certs != loaded_certs:
        sys.exit(f"FAIL: certificate files differ: {certs} vs {loaded_certs}")
    for c in certs + ["after.json"]:
        if not filecmp.cmp(f"{work}/quiet/{c}", f"{work}/loaded/{c}", shallow=False):
            sys.exit(f"FAIL: {c} differs between the quiet and the loaded run")
    print(f"PASS: reports equal without timing fields; {len(certs)} certificates and the model byte for byte equal; "
          f"{len(verified)} bounds verified")


if __name__ == "__main__":
    main()
