#!/usr/bin/env python3
"""Regenerates the measured result figures of README.md, docs/benchmarks.md, docs/oracle.md and bench/README.md
and prints each beside the documented one.

    python3 scripts/regenerate_figures.py --list              # the runs and what they measure
    python3 scripts/regenerate_figures.py --only tanks        # one run (comma-separated names)
    python3 scripts/regenerate_figures.py --max-cost medium   # every cheap and medium run
    python3 scripts/regenerate_figures.py --all               # everything (about 40 min on 2 cores)
    python3 scripts/regenerate_figures.py --build B --max-cost medium  # what ctest Figures runs

Each run is one command (the documented one, from the
repository root, with the build in build/); each figure is extracted from
that run's output or report and compared with the documented value within a
stated tolerance:

  - result figures (RMS, fit %, bounds, counts, chosen effects) are
    deterministic for a build: the ranking and the fits do not depend on
    --threads or on the machine's load. Their tolerance covers the rounding
    of the documented text (half a unit in its last printed digit, rounded
    up to one unit) and nothing else: a figure outside it is a change of
    the result that the documentation must follow.
  - timings are listed as "measured now vs documented" for information
    (marked "timing"); they depend on the machine and its load.

Each line of the table: run, figure, documented (stated), measured now
(regenerated), status. Progress (which run, its elapsed time) goes to stderr,
the table to stdout.
Exit code: 0 when every result figure agrees, 1 when one differs, 2 on a
failed run or bad options. The measured data is read from $LPVID_DATA or
../shared/data (the runs that need it are skipped, saying so, without it).
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COSTS = ["cheap", "medium", "long"]


def data_dir():
    return os.environ.get("LPVID_DATA", os.path.join(ROOT, "..", "shared", "data"))


# ---------------------------------------------------------------------------
# Extractors: each takes the run's context (stdout+stderr text, files) and
# returns the measured value (float or str), or None when it is not there.

def rx(pattern, group=1, cast=float):
    """The first match of `pattern` in the run's output."""
    def get(ctx):
        m = re.search(pattern, ctx["out"], re.M)
        return cast(m.group(group)) if m else None
    get.how = "regex " + pattern
    return get


def js(path, *keys):
    """A field of a JSON file the run wrote (path relative to the root)."""
    def get(ctx):
        full = os.path.join(ROOT, path.replace("$TMP", ctx["tmp"]))
        if not os.path.exists(full):
            return None
        v = json.load(open(full))
        for k in keys:
            if callable(k):
                v = k(v)
            elif isinstance(v, dict) and k in v:
                v = v[k]
            elif isinstance(v, list) and isinstance(k, int) and k < len(v):
                v = v[k]
            else:
                return None
        return v
    get.how = "json " + path + " " + "/".join(k if isinstance(k, str) else str(k) for k in keys if not callable(k))
    return get


def wall(ctx):
    return ctx["seconds"]


wall.how = "wall time of the run"


def effect_labels(report):
    """The chosen effects' labels; "none" when no effect was added (the report then lists the kind "none")."""
    return "; ".join(e.get("label", "?") for e in report.get("effects", []) if e.get("kind") != "none") or "none"


# A figure: (name, extractor, documented value, tolerance, where documented).
# Tolerance: absolute for numbers; None for text (must be equal; for a
# documented text ending in "...", the measured text must start with it);
# "timing" for timings (never a disagreement).
def F(name, get, documented, tol, where):
    return {"name": name, "get": get, "documented": documented, "tol": tol, "where": where}


TANKS = "$DATA/cascaded-tanks/dataBenchmark.csv"
DRYER = "$DATA/dryer/dryer.dat"
TANKS_REPORT = "$TMP/tanks.report.json"
GEN_REPORT = "$TMP/gen.report.json"
# The measured tanks demo as README.md and docs/benchmarks.md state it (the same on
# every machine and for the data moved by one ulp: ctest LastBit).
TANKS_EFFECTS = ("store cascade: two stores x1 -> x2 (A = I), outflow e*sqrt(max(x_i - c_i, 0)) and overflow "
                 "e*max(x_i - o_i, 0) from each, levels fitted; replaces the linear part (27 starts); "
                 "output_polynomial degree 3")
TANKS_AFTER_RMS, TANKS_AFTER_FIT, TANKS_AFTER_HELD_OUT = 0.2922, 86.22, 0.2616

RUNS = [
    {
        "name": "fit-linear-tanks", "cost": "cheap", "data": True,
        "cmd": "$BUILD/lpvid fit-linear --data " + TANKS + " --u uEst --y yEst --rows 0:716 "
               "--validation-rows 716:1024 --order auto --offset --model-out $TMP/tanks_linear.json",
        "figures": [
            F("order chosen", rx(r"^\s+(\d+)\s+\S+\s+\S+\s+<- chosen", cast=int), 2, 0, "docs/benchmarks.md Linear starts and diagnoses"),
            F("rms_estimation (order 2)", rx(r"^\s+2\s+(\S+)\s+\S+"), 0.4562, 1e-4, "docs/benchmarks.md Linear starts and diagnoses"),
            F("rms on rows 716:1024 (order 2)", rx(r"^\s+2\s+\S+\s+(\S+)"), 0.7870, 1e-4, "docs/benchmarks.md Linear starts and diagnoses"),
            F("order 5 score on 716:1024", rx(r"^\s+5\s+\S+\s+(\S+)"), 1.239, 1e-3, "docs/benchmarks.md Linear starts and diagnoses"),
        ],
    },
    {
        "name": "fit-linear-dryer", "cost": "cheap", "data": True,
        "cmd": "$BUILD/lpvid fit-linear --data " + DRYER + " --names u,y --rows 0:500 --validation-rows 500:1000 "
               "--order auto --offset --model-out $TMP/dryer_linear.json",
        "figures": [
            F("order chosen", rx(r"^\s+(\d+)\s+\S+\s+\S+\s+<- chosen", cast=int), 3, 0, "docs/benchmarks.md Linear starts and diagnoses"),
            F("rms_estimation (order 3)", rx(r"^\s+3\s+(\S+)\s+\S+"), 0.0909, 1e-4, "docs/benchmarks.md Linear starts and diagnoses"),
            F("rms_validation (order 3)", rx(r"^\s+3\s+\S+\s+(\S+)"), 0.1184, 1e-4, "docs/benchmarks.md Linear starts and diagnoses"),
        ],
    },
    {
        "name": "generated-demo", "cost": "medium", "data": False,
        # scripts/demo.sh without measured data, its commands run directly
        "cmd": "$BUILD/lpvid generate effect-case --effect output_polynomial --n 400 --seed 3 --out $TMP/gen_est.csv "
               "--validation-out $TMP/gen_test.csv --model-out $TMP/gen_declared.json && "
               "$BUILD/lpvid diagnose --data $TMP/gen_est.csv --model $TMP/gen_declared.json --test $TMP/gen_test.csv "
               "--warmup 10 --max-effects 2 --model-out $TMP/gen_after.json --report $TMP/gen.report.json && "
               "for c in $TMP/gen.report.cert*.after.json; do echo \"$c: $($BUILD/lpvid-verify certificate $c)\"; done",
        "figures": [
            F("effect chosen first", js(GEN_REPORT, "effects", 0, "kind"), "output_polynomial", None, "README.md What the demo shows"),
            F("test RMS before", js(GEN_REPORT, "test", "rms_before"), 7.882, 0.001, "README.md What the demo shows"),
            F("test RMS after", js(GEN_REPORT, "test", "rms_after"), 0.07182, 1e-5, "README.md What the demo shows"),
            F("'after' certificates consistent", rx(r"(\d+) of \d+ after checks consistent", cast=int), 2, 0,
              "docs/benchmarks.md The cascaded tanks demo"),
            F("time", wall, 0, "timing", "not documented"),
        ],
        # one line per certificate; count the consistent ones
        "post": lambda out: out + "\n%d of %d after checks consistent\n" % (
            len(re.findall(r"gen\.report\.cert.*after\.json: .*consistent", out)),
            len(re.findall(r"gen\.report\.cert.*after\.json:", out))),
    },
    {
        "name": "tanks", "cost": "long", "data": True,
        # scripts/demo.sh on the measured record, its two commands run directly
        "cmd": "$BUILD/lpvid fit-linear --data " + TANKS + " --u uEst --y yEst --rows 0:716 --order auto --offset "
               "--validation-rows 716:1024 --sample-time 4 --unit uEst=V --unit yEst=V --model-out $TMP/tanks_linear.json && "
               "$BUILD/lpvid diagnose --data " + TANKS + " --model $TMP/tanks_linear.json --benchmark cascaded-tanks "
               "--test-columns uVal,yVal --degree 3 --model-out $TMP/tanks_after.json --report $TMP/tanks.report.json",
        "figures": [
            F("effects chosen", js(TANKS_REPORT, effect_labels), TANKS_EFFECTS, None,
              "README.md What the demo shows; docs/benchmarks.md The cascaded tanks demo"),
            F("test RMS before [V]", js(TANKS_REPORT, "test", "rms_before"), 0.6936, 1e-4, "README.md; docs/benchmarks.md tanks table"),
            F("test fit % before", js(TANKS_REPORT, "test", "fit_percent_before"), 67.28, 0.01, "README.md; docs/benchmarks.md tanks table"),
            F("test RMS after [V]", js(TANKS_REPORT, "test", "rms_after"), TANKS_AFTER_RMS, 1e-4, "README.md; docs/benchmarks.md tanks table"),
            F("test fit % after", js(TANKS_REPORT, "test", "fit_percent_after"), TANKS_AFTER_FIT, 0.01, "README.md; docs/benchmarks.md tanks table"),
            F("held-out RMS before (fold 1)", rx(r"held-out RMS per fold: before ([\d.]+)"), 1.13, 0.01,
              "docs/benchmarks.md tanks table (fold 1)"),
            F("held-out RMS after (pooled)", js(TANKS_REPORT, "after", "rms_validation"), TANKS_AFTER_HELD_OUT, 1e-4,
              "docs/benchmarks.md tanks table"),
            F("window bounds not verified", rx(r"^(\d+) window bounds NOT verified", cast=int), 0, 0,
              "docs/benchmarks.md The cascaded tanks demo"),
            F("time", wall, 0, "timing", "not documented"),
        ],
        # diagnose's progress (merged into the output) names each window bound it could not verify
        "post": lambda out: out + "\n%d window bounds NOT verified\n" % len(
            re.findall(r"bounds \(Theorem 2\.1\), \d+ of \d+: window \d+ \w+: NOT verified", out)),
    },
    {
        "name": "quick-start", "cost": "medium", "data": False,
        # README.md "Quick start on your own CSV", steps 1-4 on the generated record it names
        "cmd": "$BUILD/lpvid generate effect-case --effect input_saturation --n 400 --seed 2 --out $TMP/my.csv "
               "--validation-out $TMP/my_val.csv --model-out $TMP/my_declared.json && "
               "$BUILD/lpvid fit-linear --data $TMP/my.csv --u u1 --y y1 --rows 0:300 --validation-rows 300:400 "
               "--order auto --model-out $TMP/start.json && "
               "$BUILD/lpvid invalidate --data $TMP/my.csv --rows 0:300 --model $TMP/start.json --lambda 0.5 "
               "--report $TMP/bounds.json --certificate $TMP/bounds.cert.json && "
               "$BUILD/lpvid-verify certificate $TMP/bounds.cert.json && "
               "$BUILD/lpvid diagnose --data $TMP/my.csv --rows 0:300 --model $TMP/start.json --test $TMP/my.csv "
               "--test-rows 300:400 --warmup 10 --report $TMP/diag.json --model-out $TMP/after.json",
        "figures": [
            F("test RMS before", js("$TMP/diag.json", "test", "rms_before"), 0.6588, 1e-4, "README.md Quick start"),
            F("test RMS after", js("$TMP/diag.json", "test", "rms_after"), 0.4332, 1e-4, "README.md Quick start"),
            F("step 3 verdict", rx(r"^(consistent)\b", cast=str), "consistent", None, "README.md Quick start"),
        ],
    },
    {
        "name": "tutorial", "cost": "medium", "data": False,
        # docs/tutorial.md sections 1, 3 and "Diagnose", as written there
        "cmd": "$BUILD/lpvid generate effect-case --effect output_polynomial --n 300 --seed 3 --out $TMP/est.csv "
               "--validation-out $TMP/test.csv --model-out $TMP/declared.json --truth-out $TMP/truth.json && "
               "$BUILD/lpvid fit-linear --data $TMP/est.csv --u u1 --y y1 --rows 0:200 --validation-rows 200:300 "
               "--order auto --offset --model-out $TMP/linear.json && "
               "$BUILD/lpvid diagnose --data $TMP/est.csv --model $TMP/declared.json --test $TMP/test.csv --warmup 10 "
               "--max-effects 2 --model-out $TMP/tut_after.json --report $TMP/tut_diag.json",
        "figures": [
            F("fit-linear: order chosen", rx(r"^order (\d+)", cast=int), 1, 0, "docs/tutorial.md 3."),
            F("fit-linear: rms_estimation", rx(r"^rms_estimation (\S+)"), 7.80059, 1e-5, "docs/tutorial.md 3."),
            F("fit-linear: order 1 held-out", rx(r"^\s+1\s+\S+\s+(\S+)\s+<- chosen"), 7.05487, 1e-5, "docs/tutorial.md 3."),
            F("diagnose: effect", js("$TMP/tut_diag.json", effect_labels), "output_polynomial degree 3", None,
              "docs/tutorial.md Diagnose"),
            F("diagnose: held-out before", js("$TMP/tut_diag.json", "before", "rms_validation"), 6.789, 1e-3,
              "docs/tutorial.md Diagnose"),
            F("diagnose: held-out after", js("$TMP/tut_diag.json", "after", "rms_validation"), 0.3108, 1e-4,
              "docs/tutorial.md Diagnose"),
            F("diagnose: test RMS before", js("$TMP/tut_diag.json", "test", "rms_before"), 5.392, 1e-3,
              "docs/tutorial.md Diagnose"),
            F("diagnose: test RMS after", js("$TMP/tut_diag.json", "test", "rms_after"), 0.04678, 1e-5,
              "docs/tutorial.md Diagnose"),
        ],
    },
    {
        "name": "python-first-example", "cost": "medium", "data": False, "python": True,
        # docs/python.md's first example, as printed there (from the build tree)
        "cmd": "PYTHONPATH=$BUILD/python " + shlex.quote(sys.executable) + " -c " + shlex.quote("""
import numpy as np, lpvid
rng = np.random.default_rng(1)
n = 200; u = rng.standard_normal(n); rho = np.sin(0.1 * np.arange(n)); y = np.zeros(n)
for k in range(n - 1):
    y[k + 1] = (0.5 + 0.2 * rho[k]) * y[k] + u[k]
y += 0.01 * rng.standard_normal(n)
model = {"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": ["rho"],
         "columns": {"u": ["u"], "y": ["y"]},
         "initial": {"A": [{"basis": "1", "value": [[0.5]]}, {"basis": "rho", "value": [[0.2]]}],
                     "B": [{"basis": "1", "value": [[1]]}], "C": [{"basis": "1", "value": [[1]]}]}}
z = lpvid.invalidate(model, u=u, y=y, rho=rho, delta=0)
print("dmax", z.dmax, z.interval.relative_gap)
print("solver", z.report["solver"])
print("verified", lpvid.verify(z.interval.lower_certificate).ok)
"""),
        "figures": [
            F("dmax at delta = 0", rx(r"^dmax (\S+)"), 0.008999240858984386, 1e-15, "docs/python.md delta = 0 example"),
            F("relative gap at delta = 0", rx(r"^dmax \S+ (\S+)"), 0.0, 0.0, "docs/python.md delta = 0 example"),
            F("solver", rx(r"^solver (.+)$", cast=str), "closed form (delta = 0)", None,
              "docs/python.md delta = 0 example"),
            F("verify(...).ok", rx(r"^verified (\S+)", cast=str), "True", None, "docs/python.md delta = 0 example"),
        ],
    },
    {
        "name": "dryer-split", "cost": "medium", "data": True,
        "cmd": "$BUILD/lpvid fit-linear --data " + DRYER + " --names u,y --rows 0:500 --validation-rows 500:1000 "
               "--order auto --offset --model-out $TMP/dryer_linear.json > /dev/null && "
               "$BUILD/lpvid diagnose --data " + DRYER + " --names u,y --rows 0:500 --model $TMP/dryer_linear.json "
               "--validation " + DRYER + " --validation-names u,y --validation-rows 500:1000 --report $TMP/dryer.json",
        "figures": [
            F("effects chosen", js("$TMP/dryer.json", effect_labels), "input_delay...", None, "docs/benchmarks.md Linear starts and diagnoses"),
            F("validation RMS after", js("$TMP/dryer.json", "after", "rms_validation"), 0.0692, 1e-4,
              "docs/benchmarks.md Linear starts and diagnoses"),
        ],
    },
    {
        "name": "dryer-folds", "cost": "medium", "data": True,
        "cmd": "$BUILD/lpvid fit-linear --data " + DRYER + " --names u,y --rows 0:500 --validation-rows 500:1000 "
               "--order auto --offset --model-out $TMP/d.json > /dev/null && "
               "$BUILD/lpvid diagnose --data " + DRYER + " --names u,y --rows 0:500 --model $TMP/d.json --test "
               + DRYER + " --test-names u,y --test-rows 500:1000 --warmup 10 --report $TMP/dryer_folds.json",
        "figures": [
            F("effects chosen", js("$TMP/dryer_folds.json", effect_labels), "none", None, "bench/README shared records"),
            F("test RMS", js("$TMP/dryer_folds.json", "test", "rms_after"), 0.1195, 1e-4,
              "bench/README shared records"),
            F("test fit %", js("$TMP/dryer_folds.json", "test", "fit_percent_after"), 85.4, 0.1,
              "bench/README shared records"),
            F("time", wall, 83, "timing", "bench/README (1 min 23 s)"),
        ],
    },
    {
        "name": "interval-siso-100", "cost": "cheap", "data": False,
        "cmd": "$BUILD/bench/interval_bench 100 \"\"",
        "figures": [
            F("SISO 100 relative gap", rx(r"^SISO\s+100\s+100\s+\|\s+\S+\s+\S+\s+\S+\s+\S+\s+\S+\s+(\S+)"), 5.47e-05,
              0.01e-05, "bench/README interval_bench (re-measured 2026-11-30, the Frobenius rebuild class)"),
            F("SISO 100 verdict", rx(r"^SISO\s+100\s+100\s+\|(?:\s+\S+){6}\s+\|\s+\S+\s+(\S+)", cast=str), "invalidated",
              None, "bench/README interval_bench"),
            F("SISO 100 interval time [s]", rx(r"^SISO\s+100\s+100\s+\|\s+(\S+)"), 0.35, "timing",
              "bench/README interval_bench"),
        ],
    },
    {
        "name": "oracle", "cost": "medium", "data": False,
        "cmd": "bash bench/oracle_run.sh $BUILD 100 --siso --max-n 200",
        "figures": [
            F("cases confirmed", rx(r"^\d+ cases: (\d+) confirmed", cast=int), 100, 0, "docs/oracle.md Measured"),
            F("time", wall, 66.5, "timing", "docs/oracle.md Measured (66.5 s)"),
        ],
    },
    {
        "name": "analogues", "cost": "long", "data": False,
        "cmd": "$BUILD/bench/diagnose_analogues 1000",
        "figures": [
            F("abs_sensor test RMS after", rx(r"abs_sensor.*?→ ([\d.]+)|abs_sensor.*?-> ([\d.]+)"), 0.0015, 1e-4,
              "bench/README diagnose_analogues"),
            F("duffing test RMS after", rx(r"duffing.*?(?:→|->) ([\d.]+)"), 0.0044, 1e-4,
              "bench/README diagnose_analogues"),
            F("linear test RMS after", rx(r"^\|?\s*linear.*?(?:→|->) ([\d.]+)"), 0.0019, 1e-4,
              "bench/README diagnose_analogues"),
            F("tanks analogue test RMS after", rx(r"tanks.*?(?:→|->) ([\d.]+)"), 0.1852, 1e-4,
              "bench/README diagnose_analogues"),
        ],
    },
]


# ---------------------------------------------------------------------------

BUILD = os.path.join(ROOT, "build")


def expand(text, tmp):
    return text.replace("$DATA", data_dir()).replace("$TMP", tmp).replace("$BUILD", BUILD)


def compare(fig, measured):
    doc, tol = fig["documented"], fig["tol"]
    if measured is None:
        return "MISSING"
    if tol == "timing":
        return "timing"
    if tol is None:
        doc_s, got = str(doc), str(measured)
        if doc_s.endswith("..."):
            return "agrees" if got.startswith(doc_s[:-3]) else "DIFFERS"
        return "agrees" if got == doc_s else "DIFFERS"
    return "agrees" if abs(float(measured) - float(doc)) <= tol else "DIFFERS"


def show(v):
    if isinstance(v, float):
        return "%.6g" % v
    return str(v)


def run_one(run, tmp, log):
    cmd = expand(run["cmd"], tmp)
    print("[regenerate] %s: %s" % (run["name"], cmd), file=sys.stderr, flush=True)
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", LPVID_DATA=data_dir())
    if "LPVID_DATA=/nonexistent" in cmd:
        env.pop("LPVID_DATA")
    t0 = time.time()
    with open(log, "w") as f:
        p = subprocess.Popen(cmd, shell=True, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             text=True)
        out = []
        last = t0
        for line in p.stdout:
            out.append(line)
            f.write(line)
            if time.time() - last > 30:  # a progress line every 30 s
                last = time.time()
                print("[regenerate] %s: %.0f s, %s" % (run["name"], last - t0, line.strip()[:120]),
                      file=sys.stderr, flush=True)
        code = p.wait()
    seconds = time.time() - t0
    text = "".join(out)
    if "post" in run:
        text = run["post"](text)
    print("[regenerate] %s: done in %.0f s (exit %d; output in %s)" % (run["name"], seconds, code, log),
          file=sys.stderr, flush=True)
    return {"out": text, "seconds": seconds, "code": code, "tmp": tmp}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", help="comma-separated run names (see --list)")
    ap.add_argument("--max-cost", choices=COSTS, default="long", help="skip runs above this cost")
    ap.add_argument("--list", action="store_true", help="list the runs and their figures, run nothing")
    ap.add_argument("--all", action="store_true", help="every run (the default when neither --only nor --max-cost is given)")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="the build folder holding lpvid (default build/)")
    ap.add_argument("--work", default=None, help="logs and scratch files (default: BUILD/figures)")
    a = ap.parse_args()
    global BUILD
    BUILD = os.path.abspath(a.build)
    if a.all:
        a.max_cost = "long"
    a.work = os.path.abspath(a.work or os.path.join(BUILD, "figures"))
    names = [r["name"] for r in RUNS]
    only = a.only.split(",") if a.only else None
    for n in only or []:
        if n not in names:
            print("regenerate_figures: unknown run '%s' (known: %s)" % (n, ", ".join(names)), file=sys.stderr)
            return 2
    if a.list:
        for r in RUNS:
            print("%-18s %-6s %s" % (r["name"], r["cost"], r["cmd"]))
            for f in r["figures"]:
                print("    %-34s documented %-12s tolerance %-8s %s  [%s]" % (
                    f["name"], show(f["documented"])[:40], show(f["tol"]), f["where"], f["get"].how[:60]))
        return 0
    os.makedirs(a.work, exist_ok=True)
    rows, differs, failed = [], False, False
    for r in RUNS:
        if only and r["name"] not in only:
            continue
        if not only and COSTS.index(r["cost"]) > COSTS.index(a.max_cost):
            continue
        if r.get("python") and not os.path.isdir(os.path.join(BUILD, "python")):
            print("[regenerate] %s: skipped: no Python module in %s/python" % (r["name"], BUILD), file=sys.stderr)
            continue
        if r["data"] and not os.path.isdir(data_dir()):
            print("[regenerate] %s: skipped: no measured data in %s (set LPVID_DATA)" % (r["name"], data_dir()),
                  file=sys.stderr)
            continue
        ctx = run_one(r, a.work, os.path.join(a.work, r["name"] + ".log"))
        if ctx["code"] not in (0, 4):  # 4: bounds computed but not all verified; the figures still stand
            failed = True
        for f in r["figures"]:
            try:
                measured = f["get"](ctx)
            except (OSError, ValueError, KeyError, TypeError):
                measured = None
            status = compare(f, measured)
            differs |= status in ("DIFFERS", "MISSING")
            rows.append((r["name"], f["name"], show(f["documented"]), show(measured), status, f["where"]))
    if not rows:
        print("regenerate_figures: nothing ran", file=sys.stderr)
        return 2
    w = [max(len(x[i]) for x in rows + [("run", "figure", "documented", "measured now", "status", "where")])
         for i in range(6)]
    w = [min(x, 60) for x in w]
    fmt = "  ".join("%%-%ds" % x for x in w)
    print(fmt % ("run", "figure", "documented", "measured now", "status", "where"))
    for row in rows:
        print(fmt % tuple(c[:60] for c in row))
    return 2 if failed else 1 if differs else 0


if __name__ == "__main__":
    sys.exit(main())
