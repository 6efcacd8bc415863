#!/usr/bin/env python3
"""What the Python package costs on top of the lpvid program: the same
diagnose (and invalidate) on the same files, run by the program and by the
package's function, alternately, several times; a table of wall and CPU
seconds (medians) and the package's ratio to the program.

The CPU time of the package's call is the Python process's own (the C++ code
runs in it); the program's is its child's. Both runs use one thread
(--threads 1, OPENBLAS_NUM_THREADS=1), so CPU time is comparable under load.

    PYTHONPATH=build/python python3 bench/python_overhead.py build/lpvid /tmp/overhead [--repeats 3] [--n 400]
"""

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time


def child_run(program, words):
    """(wall, cpu) seconds of `program words` as a child process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    done = subprocess.run([program, *words], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode not in (0, 1):
        sys.exit(f"{program} {' '.join(words)}: exit {done.returncode}\n{done.stderr}")
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def own_run(call):
    """(wall, cpu) seconds of a call in this process."""
    before = resource.getrusage(resource.RUSAGE_SELF)
    t0 = time.perf_counter()
    call()
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_SELF)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def cases(folder, program, n):
    import lpvid
    data, val, model = (os.path.join(folder, f) for f in ("data.csv", "val.csv", "model.json"))
    subprocess.run([program, "generate", "effect-case", "--n", str(n), "--out", data, "--validation-out", val,
                    "--model-out", model, "--truth-out", os.path.join(folder, "truth.json")],
                   check=True, capture_output=True)
    return [
        ("diagnose", ["diagnose", "--data", data, "--model", model, "--test", val, "--threads", "1", "--quiet",
                      "--report", os.path.join(folder, "cli.json")],
         lambda: lpvid.diagnose(model, data=data, test=val, threads=1, quiet=True, figures=False)),
        ("invalidate --dmax 1/10", ["invalidate", "--data", data, "--model", model, "--dmax", "1/10",
                                    "--report", os.path.join(folder, "inv.json")],
         lambda: lpvid.invalidate(model, data=data, dmax="1/10")),
    ]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("program")
    parser.add_argument("folder")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--n", type=int, default=400)
    a = parser.parse_args()
    os.environ["OPENBLAS_NUM_THREADS"] = "1"
    os.makedirs(a.folder, exist_ok=True)
    print(f"{'call':24} {'program wall':>12} {'package wall':>12} {'ratio':>6} "
          f"{'program CPU':>11} {'package CPU':>11} {'ratio':>6}")
    for name, words, call in cases(a.folder, a.program, a.n):
        prog, pack = [], []
        for k in range(a.repeats):
            print(f"[python_overhead] {name}: round {k + 1} of {a.repeats}", file=sys.stderr, flush=True)
            prog.append(child_run(a.program, words))
            pack.append(own_run(call))
        pw, pc = (statistics.median(v[i] for v in prog) for i in (0, 1))
        kw, kc = (statistics.median(v[i] for v in pack) for i in (0, 1))
        print(f"{name:24} {pw:12.2f} {kw:12.2f} {kw / pw:6.3f} {pc:11.2f} {kc:11.2f} {kc / pc:6.3f}")


if __name__ == "__main__":
    main()
