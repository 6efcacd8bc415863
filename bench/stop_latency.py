#!/usr/bin/env python3
"""How soon a running call stops after request_stop() (the cooperative
Ctrl-C of the Python module, src/core/stop_request.h).

For each command a generated case is run in a Python thread through
lpvid._lpvid; after WAIT seconds the main thread calls request_stop() and
measures the time until the call returns (its exit code must be 130, and its
outputs must be gone). A call that ends before the request is reported as
"finished first" with its run time.

    PYTHONPATH=build/python python3 bench/stop_latency.py [build=build] [wait=2]
"""
import os
import random
import subprocess
import sys
import tempfile
import threading
import time

BUILD = sys.argv[1] if len(sys.argv) > 1 else "build"
WAIT = float(sys.argv[2]) if len(sys.argv) > 2 else 2.0
sys.path.insert(0, os.path.join(BUILD, "python"))
from lpvid import _lpvid  # noqa: E402

LPVID = os.path.join(BUILD, "lpvid")


def lpvid(*args):
    subprocess.run([LPVID, *args], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def write_matrix(path, n):
    """A dense symmetric diagonally dominant (hence PD) matrix of 12-digit
    rationals: its exact LDL^T takes seconds."""
    rng = random.Random(7)
    a = [[0] * n for _ in range(n)]
    for i in range(n):
        for j in range(i, n):
            a[i][j] = a[j][i] = rng.randint(-10**12, 10**12)
    with open(path, "w") as out:
        for i in range(n):
            a[i][i] = n * 10**12 + 1
            out.write(" ".join(f"{v}/7" for v in a[i]) + "\n")


def stop_after(run, args, outputs):
    """Runs `run(args)` in a thread, asks it to stop after WAIT seconds;
    returns (exit code, seconds from the request to the return, leftovers)."""
    result = {}

    def body():
        result["code"] = run(args)
        result["end"] = time.monotonic()

    start = time.monotonic()
    t = threading.Thread(target=body)
    t.start()
    t.join(WAIT)
    requested = time.monotonic()
    _lpvid.request_stop()
    t.join()
    _lpvid.clear_stop()
    left = [p for p in outputs if os.path.exists(p)]
    if result["end"] < requested:
        return result["code"], None, result["end"] - start, left
    return result["code"], result["end"] - requested, None, left


def main():
    d = tempfile.mkdtemp(prefix="lpvid_stop_latency.")
    f = lambda name: os.path.join(d, name)  # noqa: E731
    lpvid("generate", "effect-case", "--effect", "output_polynomial", "--n", "2000", "--seed", "5",
          "--out", f("long.csv"), "--validation-out", f("long_test.csv"), "--model-out", f("long.json"))
    lpvid("generate", "effect-case", "--effect", "output_polynomial", "--n", "400", "--seed", "3",
          "--out", f("est.csv"), "--validation-out", f("test.csv"), "--model-out", f("declared.json"))
    write_matrix(f("m.txt"), 700)
    cases = [
        ("invalidate n=2000", _lpvid.run_lpvid,
         ["invalidate", "--data", f("long.csv"), "--model", f("long.json"), "--delta", "0.5", "--quiet",
          "--certificate", f("c.json"), "--report", f("r.json")], [f("c.json"), f("r.json")]),
        ("identify n=2000", _lpvid.run_lpvid,
         ["identify", "--data", f("long.csv"), "--model", f("long.json"), "--quiet", "--iterate",
          "--certificate", f("ic.json"), "--model-out", f("im.json")], [f("ic.json"), f("im.json")]),
        ("diagnose n=400", _lpvid.run_lpvid,
         ["diagnose", "--data", f("est.csv"), "--model", f("declared.json"), "--test", f("test.csv"),
          "--warmup", "10", "--threads", "1", "--report", f("d.json"), "--model-out", f("after.json")],
         [f("d.json"), f("after.json")]),
        ("verify psd 700x700 exact", _lpvid.run_lpvid_verify, ["--max-exact-work", "1e13", "--max-total-work", "1e13", "psd", "--exact-only", "--threads", "1", f("m.txt")], []),
    ]
    print(f"wait before request_stop: {WAIT} s")
    for name, run, args, outputs in cases:
        code, latency, finished, left = stop_after(run, args, outputs)
        if latency is None:
            print(f"{name:28s} finished first after {finished:.2f} s (exit {code})")
        else:
            print(f"{name:28s} exit {code}, stopped {latency * 1000:.0f} ms after request_stop, left: {left or 'nothing'}")


if __name__ == "__main__":
    main()
