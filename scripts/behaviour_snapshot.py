#!/usr/bin/env python3
"""Record what lpvid and lpvid-verify do on a fixed corpus of runs, and compare two records.

A refactoring that should not change behaviour is checked by running the
corpus with the binaries before it and with those after it, then comparing
the two records: exit codes, standard output and every file the runs write
must be equal byte for byte, apart from the fields that measure wall-clock
time and the paths of the record's own folder (rules below).

    python3 scripts/behaviour_snapshot.py run --bin DIR --out OUTDIR [--data DATA_DIR] [--only NAME,...]
    python3 scripts/behaviour_snapshot.py compare OUTDIR_A OUTDIR_B [--only NAME,...]
    python3 scripts/behaviour_snapshot.py list

`run` runs each case with DIR/lpvid and DIR/lpvid-verify in a fresh folder
OUTDIR/<case>/ (the working directory of its commands, so the files they
write stay inside it), with OPENBLAS_NUM_THREADS=1, OMP_NUM_THREADS=1 and
LC_ALL=C. Each command k of a case leaves OUTDIR/<case>/_cmd/k.json (its
arguments, exit code, run time), k.stdout and k.stderr. Standard error holds
the progress lines (with elapsed times), so it is kept but only compared for
the error cases, where the message is the behaviour. The measured data
(cascaded-tanks/dataBenchmark.csv, dryer/dryer.dat) is read from --data,
else $LPVID_DATA, else ../shared/data beside the repository; a case that
needs a missing file is skipped, saying so, and the record notes it.
OUTDIR/manifest.json lists the cases with their status, run time and the
folders (binaries, data, repository) to map back when comparing. `--only`
reruns some cases and keeps the others already in OUTDIR.

`compare` compares the cases of two records one by one and prints, per case,
"same" or the first difference (file, JSON path or line, both values); it
exits 1 if any case differs (or is recorded in one record only), else 0.

Comparison rules (each one narrow; every other byte counts):
  paths     in every compared text, the run's own case folder becomes <case>,
            OUTDIR <out>, the binaries' folder <bin>, the data folder <data>
            and the repository <repo> (each only as a whole path component).
  JSON      (every *.json: reports, models, certificates, plans, plot
            descriptions, the _cmd records) compared as values after leaving
            out each key ending in "seconds" or named "elapsed" or "time"
            (the rule of tests/cli/reproducibility_test.py; lpvid writes wall
            time only under such keys: certification.*_seconds, iterates[].
            seconds, class_interval.seconds, select-basis steps' seconds,
            tradeoff points' seconds, oracle's seconds/outside_seconds/
            lpvid_seconds); numbers are compared as written, not as parsed.
            When the values agree, the text is compared too, with the numbers
            of those keys masked, so key order and formatting count.
  PNG       ignored (gnuplot's rendering; the figure's data is compared in
            its .csv, .plot.json and .svg files).
  stdout    byte for byte after these masks of printed wall-clock times,
            each matching only the line the source prints it on:
            V1 lpvid-verify certificate: "checked in exact rational arithmetic in <t> s"
            V2 lpvid-verify psd:         "  time: read <t> s, decide <t> s"
            I1 identify:                 "(solver values, <t> s)" after each solve
            I2 class interval:           "(<n> leaves, <t> s)" / "(1 leaf, <t> s)"
            T1 tradeoff table:           the 8th column (time[s]) of the rows under the header "lambda delta dmax verified ..."
            S1 select-basis table:       the time[s] column, the 5th cell after the step's verdict
            O1 oracle table:             the "outside s" and "lpvid s" cells after each case's verdict
            O2 oracle:                   "time <t> s; each refutation ..."
  JUnit     (*.xml, oracle --junit) the time="..." attributes masked.
  other     (CSV, SVG, SDPA files, logs) byte for byte after the path map
            (the plot CSVs' time_s column is the record's sample time, not
            a wall clock: compared).
  stderr    ignored, except for the steps recorded with stderr_compared
            (the error cases): byte for byte after the path map.

Cases (each independent: its data generated with fixed seeds or read from
the data folder, its outputs inside its folder):"""
import argparse
import fnmatch
import json
import os
import re
import shutil
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # leave no __pycache__ in the repository's tests/cli
sys.path.insert(0, os.path.join(REPO, "tests", "cli"))
from reproducibility_test import TIMING_KEYS, first_difference  # noqa: E402

COMMAND_TIMEOUT = 1800  # seconds one command may take before it is recorded as "timeout" (a hung binary)


# --------------------------------------------------------------------------------------------------
# Running a case
# --------------------------------------------------------------------------------------------------

class Run:
    """One case's folder and its commands: each command is recorded under _cmd/ as it runs."""

    def __init__(self, case_dir, bin_dir, data_dir, env):
        self.dir, self.bin, self.data_dir, self.env = case_dir, bin_dir, data_dir, env
        self.steps = []  # (label, exit code, expected exit code)
        os.makedirs(os.path.join(case_dir, "_cmd"))

    def lpvid(self, *args, expect=0, stderr=False):
        """lpvid ARGS; stderr=True: its standard error is behaviour too (error messages)."""
        return self.command([os.path.join(self.bin, "lpvid"), *args], expect, stderr=stderr)

    def verify(self, *args, expect=0, stderr=False):
        return self.command([os.path.join(self.bin, "lpvid-verify"), *args], expect, stderr=stderr)

    def command(self, argv, expect=0, stdout=True, stderr=False):
        """Runs argv in the case folder; stdout=False: its standard output is kept but not compared.
        A command still running after COMMAND_TIMEOUT seconds is killed and recorded with exit code "timeout"."""
        k = len(self.steps) + 1
        base = os.path.join(self.dir, "_cmd", f"{k:02d}")
        started = time.monotonic()
        with open(base + ".stdout", "wb") as out, open(base + ".stderr", "wb") as err:
            try:
                code = subprocess.run(argv, cwd=self.dir, env=self.env, stdin=subprocess.DEVNULL, stdout=out,
                                      stderr=err, timeout=COMMAND_TIMEOUT).returncode
            except subprocess.TimeoutExpired:
                code = "timeout"
        record = {"argv": argv, "exit_code": code, "stdout_compared": stdout, "stderr_compared": stderr,
                  "seconds": round(time.monotonic() - started, 3)}
        with open(base + ".json", "w") as f:
            json.dump(record, f, indent=1)
            f.write("\n")
        label = " ".join([os.path.basename(argv[0])] + argv[1:])
        self.steps.append((label if len(label) < 100 else label[:97] + "...", code, expect))
        return code

    def glob(self, pattern):
        """Files of the case folder (relative paths, sorted) that match pattern (fnmatch: * also crosses /)."""
        found = []
        for root, dirs, files in os.walk(self.dir):
            dirs[:] = [d for d in dirs if d != "_cmd"]
            for name in files:
                rel = os.path.relpath(os.path.join(root, name), self.dir)
                if fnmatch.fnmatch(rel, pattern):
                    found.append(rel)
        return sorted(found)

    def copy(self, repo_path, name=None):
        """A repository file copied into the case folder (the case then reads its own copy)."""
        name = name or os.path.basename(repo_path)
        shutil.copyfile(os.path.join(REPO, repo_path), os.path.join(self.dir, name))
        return name

    def write(self, name, text):
        with open(os.path.join(self.dir, name), "w") as f:
            f.write(text)
        return name

    def read(self, name):
        with open(os.path.join(self.dir, name)) as f:
            return f.read()

    def data(self, rel):
        return os.path.join(self.data_dir, rel)


CASES = []  # (name, data files needed, function, one line of description), in run order


def case(name, doc, needs=()):
    def register(fn):
        CASES.append((name, tuple(needs), fn, doc))
        return fn
    return register


TANKS = "cascaded-tanks/dataBenchmark.csv"
DRYER = "dryer/dryer.dat"


@case("demo-generated", "scripts/demo.sh without measured data: generate, diagnose (2 effects), verify the 'after' certificates")
def demo_generated(r):
    r.lpvid("generate", "effect-case", "--effect", "output_polynomial", "--n", "400", "--seed", "3", "--out",
            "gen_est.csv", "--validation-out", "gen_test.csv", "--model-out", "gen_declared.json")
    r.lpvid("diagnose", "--data", "gen_est.csv", "--model", "gen_declared.json", "--test", "gen_test.csv",
            "--warmup", "10", "--max-effects", "2", "--model-out", "gen_after.json", "--report", "gen.report.json")
    for c in r.glob("gen.report.cert*.after.json"):
        r.verify("certificate", c)


@case("demo-tanks", "scripts/demo.sh on the measured cascaded tanks: fit-linear, diagnose with plots, verify", needs=[TANKS])
def demo_tanks(r):
    tanks = r.data(TANKS)
    r.lpvid("fit-linear", "--data", tanks, "--u", "uEst", "--y", "yEst", "--rows", "0:716", "--order", "auto",
            "--offset", "--validation-rows", "716:1024", "--sample-time", "4", "--unit", "uEst=V", "--unit", "yEst=V",
            "--model-out", "tanks_linear.json")
    r.lpvid("diagnose", "--data", tanks, "--model", "tanks_linear.json", "--benchmark", "cascaded-tanks",
            "--test-columns", "uVal,yVal", "--degree", "3", "--plots", "tanks_plots", "--model-out", "tanks_after.json",
            "--report", "tanks.report.json")
    for c in r.glob("tanks.report.cert.w*.after.json"):
        r.verify("certificate", c)


@case("dryer", "the dryer record (docs/benchmarks.md): fit-linear as documented, a small diagnose with a test part",
      needs=[DRYER])
def dryer(r):
    d = r.data(DRYER)
    r.lpvid("fit-linear", "--data", d, "--names", "u,y", "--rows", "0:500", "--validation-rows", "500:1000", "--order",
            "auto", "--offset", "--model-out", "dryer_linear.json")
    r.lpvid("diagnose", "--data", d, "--names", "u,y", "--rows", "0:300", "--model", "dryer_linear.json", "--test", d,
            "--test-names", "u,y", "--test-rows", "500:700", "--warmup", "10", "--max-effects", "1", "--max-windows",
            "1", "--window-length", "150", "--state-degree", "0", "--max-input-delay", "3", "--degree", "1",
            "--report", "dryer.report.json", "--model-out", "dryer_after.json")
    for c in r.glob("dryer.report.cert*after*.json"):
        r.verify("certificate", c)


def effect_case(r, effect, seed, extra):
    """A generated case with one undeclared effect, diagnosed with one effect at most (and extra options);
    every certificate of the report checked."""
    r.lpvid("generate", "effect-case", "--effect", effect, "--n", "250", "--seed", str(seed), "--out", "est.csv",
            "--validation-out", "test.csv", "--model-out", "declared.json", "--truth-out", "truth.json")
    r.lpvid("diagnose", "--data", "est.csv", "--model", "declared.json", "--test", "test.csv", "--warmup", "10",
            "--max-effects", "1", "--report", "r.report.json", "--model-out", "after.json", *extra)
    for c in r.glob("r.report.cert*.json"):
        r.verify("certificate", c)


@case("effect-input-saturation", "generated input_saturation case (n 250), diagnose with --lower-ends")
def effect_input_saturation(r):
    effect_case(r, "input_saturation", 7, ["--lower-ends"])


@case("effect-input-delay", "generated input_delay case (n 250), diagnose with --folds 1 (hold-out) and --plots")
def effect_input_delay(r):
    effect_case(r, "input_delay", 7, ["--folds", "1", "--holdout", "0.3", "--plots", "plots"])


@case("effect-scheduled-offset", "generated scheduled_offset case (n 250), diagnose with --window-length 125 --threads 1")
def effect_scheduled_offset(r):
    effect_case(r, "scheduled_offset", 7, ["--window-length", "125", "--threads", "1"])


@case("invalidate", "Example 1 data: invalidate at fixed delta, fixed dmax, both, the default lambda; an invalidated "
      "model; an outside solver's solution through certify; lpvid-verify of every certificate")
def invalidate(r):
    r.lpvid("generate", "example1", "--n", "60", "--noise-std", "0.1", "--seed", "5", "--out", "d.csv", "--model-out",
            "init.json", "--truth-out", "true.json")
    for name, bounds in [("delta", ["--delta", "0.1"]), ("dmax", ["--dmax", "0.3"]),
                         ("both", ["--delta", "0.1", "--dmax", "0.3"]), ("lambda", [])]:
        r.lpvid("invalidate", "--data", "d.csv", "--model", "true.json", *bounds, "--report", name + ".report.json",
                "--certificate", name + ".cert.json")
    r.lpvid("invalidate", "--data", "d.csv", "--model", "init.json", "--delta", "0.1", "--dmax", "0.3", "--report",
            "invalidated.report.json", "--certificate", "invalidated.cert.json", expect=1)
    r.lpvid("invalidate", "--data", "d.csv", "--model", "init.json", "--lambda", "0.3", "--rows", "10:50",
            "--delta-norm", "kyp", "--max-taps", "8", "--report", "kyp.report.json", "--certificate", "kyp.cert.json")
    # The Theorem 2.1 program solved outside (the csdp program), then certified by lpvid certify.
    r.lpvid("invalidate", "--data", "d.csv", "--model", "true.json", "--delta", "0.1", "--write-sdpa", "P.dat-s",
            "--report", "sdpa.report.json")
    if shutil.which("csdp"):
        code = r.command(["csdp", "P.dat-s", "P.sol"], stdout=False)  # csdp prints its own timings
        r.lpvid("certify", "--data", "d.csv", "--model", "true.json", "--delta", "0.1", "--program", "P.dat-s",
                "--solution", "P.sol", "--solver-exit-code", str(code), "--certificate", "certify.cert.json",
                "--report", "certify.report.json")
    else:
        r.write("csdp-not-found.txt", "the csdp program is not installed: lpvid certify not run\n")
    for c in r.glob("*.cert*.json"):
        r.verify("certificate", c)  # exit 0 for the invalidation certificate too: its claim holds


@case("identify", "Example 1 (n 30): identify by one relaxation with a class interval, iterated, alternating; verify")
def identify(r):
    r.lpvid("generate", "example1", "--n", "30", "--noise-std", "0.05", "--seed", "2", "--out", "ex30.csv",
            "--model-out", "init30.json")
    r.lpvid("identify", "--data", "ex30.csv", "--model", "init30.json", "--basis", "1,rho1", "--class-leaves", "3",
            "--certificate", "relax.cert.json", "--report", "relax.report.json", "--model-out", "relax.model.json")
    r.lpvid("identify", "--data", "ex30.csv", "--model", "init30.json", "--basis", "1,rho2", "--iterate",
            "--max-iterations", "3", "--class-leaves", "3", "--certificate", "iter.cert.json", "--report",
            "iter.report.json", "--model-out", "iter.model.json")
    r.lpvid("identify", "--data", "ex30.csv", "--model", "init30.json", "--basis", "1,rho1,rho2", "--method",
            "alternating", "--max-iterations", "3", "--delta", "0.05", "--no-class-bound", "--certificate",
            "alt.cert.json", "--report", "alt.report.json")
    for c in r.glob("*.cert*.json"):
        r.verify("certificate", c)


@case("select-basis", "Example 1 (n 60): select-basis that finds a basis, and one that cannot (exit 5); verify")
def select_basis(r):
    r.copy("fixtures/example1/initial_model.json")
    r.lpvid("generate", "example1", "--n", "60", "--seed", "1", "--out", "ex1.csv")
    r.lpvid("select-basis", "--data", "ex1.csv", "--model", "initial_model.json", "--delta", "0.3", "--dmax", "0.5",
            "--report", "sel.json", "--certificate", "sel.cert.json")
    r.lpvid("generate", "example1", "--n", "60", "--seed", "1", "--noise-std", "0.05", "--out", "ex1n.csv")
    r.lpvid("select-basis", "--data", "ex1n.csv", "--model", "initial_model.json", "--delta", "0.1", "--dmax", "0.06",
            "--degree", "1", "--report", "sel2.json", "--certificate", "sel2.cert.json", expect=5)
    for c in r.glob("*.json"):
        if ".step" in c or ".cert" in c:
            r.verify("certificate", c)


@case("tradeoff", "Example 1 (n 40): tradeoff on two lambdas with CSV, plots, report and certificates")
def tradeoff(r):
    r.copy("fixtures/example1/initial_model.json")
    r.lpvid("generate", "example1", "--n", "40", "--seed", "1", "--noise-std", "0.05", "--out", "ex1n.csv")
    r.lpvid("tradeoff", "--data", "ex1n.csv", "--model", "initial_model.json", "--basis", "1,rho2", "--lambdas",
            "0.2,0.8", "--csv", "to.csv", "--plots", "to_plots", "--report", "to.json", "--certificate", "to.cert.json")
    for c in r.glob("to.lambda*.cert*.json"):
        r.verify("certificate", c)


@case("simulate-compare", "effect case (n 300): simulate, fit-linear, compare (free run, warm-up, plots; k-step)")
def simulate_compare(r):
    r.lpvid("generate", "effect-case", "--effect", "output_polynomial", "--n", "300", "--seed", "3", "--out",
            "est.csv", "--validation-out", "test.csv", "--model-out", "declared.json", "--truth-out", "truth.json")
    r.lpvid("simulate", "--data", "est.csv", "--model", "declared.json", "--out", "sim.csv")
    r.lpvid("simulate", "--data", "est.csv", "--model", "truth.json")  # the CSV on standard output
    r.lpvid("fit-linear", "--data", "est.csv", "--u", "u1", "--y", "y1", "--rows", "0:200", "--validation-rows",
            "200:300", "--order", "auto", "--offset", "--model-out", "linear.json", "--report", "fit.json")
    r.lpvid("compare", "--data", "test.csv", "--model", "declared.json", "--model", "linear.json", "--model",
            "truth.json", "--warmup", "10", "--out", "cmp.csv", "--plots", "cmp_plots", "--report", "cmp.json")
    r.lpvid("compare", "--data", "test.csv", "--model", "linear.json", "--x0", "fit", "--predict", "3", "--model-out",
            "linear_x0.json", "--report", "cmp_predict.json")


@case("jobs", "Example 1 (n 160): jobs plan (2 windows and the joint claim), run jobs.txt, jobs merge")
def jobs(r):
    r.lpvid("generate", "example1", "--n", "160", "--noise-std", "0.1", "--seed", "4", "--out", "d.csv", "--truth-out",
            "true.json")
    r.lpvid("jobs", "plan", "--data", "d.csv", "--model", "true.json", "--delta", "0.05", "--window-length", "80",
            "--joint", "--dir", "J")
    r.command(["bash", "J/jobs.txt"])  # one lpvid invalidate per line, run here one after the other
    r.lpvid("jobs", "merge", "--dir", "J")


@case("records", "two records of one system (effect case, n 300): invalidate and identify with per-record figures, "
      "diagnose with the estimation records' scores; verify")
def records(r):
    r.lpvid("generate", "effect-case", "--effect", "input_saturation", "--n", "300", "--seed", "5", "--out", "est.csv",
            "--validation-out", "test.csv", "--model-out", "declared.json", "--truth-out", "truth.json")
    two = ["--data", "est.csv", "--rows", "0:150", "--data", "est.csv", "--rows", "150:300"]
    r.lpvid("invalidate", *two, "--model", "truth.json", "--delta", "0.05", "--report", "inv.report.json")
    r.lpvid("identify", *two, "--model", "declared.json", "--basis", "1", "--report", "id.report.json")
    r.lpvid("diagnose", *two, "--model", "declared.json", "--test", "test.csv", "--warmup", "10", "--max-effects", "1",
            "--report", "dg.report.json", "--model-out", "after.json")
    for c in r.glob("*.cert*.json"):
        r.verify("certificate", c)


@case("oracle", "lpvid oracle: examples/oracle/my_impl.py (confirmed), a scaled toy (refuted), identify tasks")
def oracle(r):
    lpvid = os.path.join(r.bin, "lpvid")
    toy = os.path.join(REPO, "tests", "oracle", "toy_impls.py")
    r.lpvid("oracle", "--cases", "3", "--seed", "1", "--siso", "--max-n", "40", "--command",
            "python3 " + os.path.join(REPO, "examples", "oracle", "my_impl.py") + " {data} {model} {task} {out}",
            "--work", "work1", "--report", "o1.json", "--junit", "o1.xml")
    r.lpvid("oracle", "--cases", "2", "--seed", "5", "--max-n", "30", "--command",
            f"python3 {toy} scaled {lpvid} {{data}} {{model}} {{task}} {{out}}", "--work", "work2", "--report", "o2.json",
            expect=1)
    r.lpvid("oracle", "--cases", "2", "--seed", "11", "--min-n", "10", "--max-n", "24", "--kinds", "identify",
            "--command", f"python3 {toy} correct {lpvid} {{data}} {{model}} {{task}} {{out}}", "--work", "work3",
            "--report", "o3.json")


@case("generate", "generate: example1, example2, effect-case none, random cases (folders)")
def generate(r):
    r.lpvid("generate", "example1", "--n", "50", "--noise-std", "0.1", "--seed", "2", "--out", "ex1.csv",
            "--model-out", "ex1_init.json", "--truth-out", "ex1_true.json")
    r.lpvid("generate", "example2", "--n", "40", "--seed", "1", "--out", "ex2.csv", "--model-out", "ex2_init.json",
            "--truth-out", "ex2_true.json")
    r.lpvid("generate", "effect-case", "--effect", "none", "--n", "100", "--seed", "9", "--out", "none_est.csv",
            "--validation-out", "none_test.csv", "--model-out", "none_declared.json")
    r.lpvid("generate", "random", "--seed", "3", "--out", "random3")
    r.lpvid("generate", "random", "--seed", "4", "--siso", "--static-blocks", "--kinds", "identify", "--out",
            "random4")


@case("errors", "error cases: malformed CSV, unknown basis function, misspelt/renamed option, missing file, "
      "unknown command, tampered certificate, psd decisions (stderr compared)")
def errors(r):
    r.lpvid("generate", "example1", "--n", "30", "--seed", "1", "--out", "d.csv", "--model-out", "init.json")
    lines = r.read("d.csv").splitlines(keepends=True)
    r.write("bad.csv", "".join(lines[:5]) + "1,2,abc,4,5,6\n" + "".join(lines[6:]))
    r.lpvid("invalidate", "--data", "bad.csv", "--model", "init.json", "--delta", "0.1", expect=2, stderr=True)
    r.lpvid("identify", "--data", "d.csv", "--model", "init.json", "--basis", "1,foo", expect=2, stderr=True)
    r.lpvid("invalidate", "--data", "d.csv", "--model", "init.json", "--detla", "0.1", expect=2, stderr=True)
    r.lpvid("fit-linear", "--data", "d.csv", "--u", "u1", "--y", "y1", "--out", "x.json", expect=2, stderr=True)
    r.lpvid("invalidate", "--data", "missing.csv", "--model", "init.json", expect=2, stderr=True)
    r.lpvid("frobnicate", expect=2, stderr=True)
    r.lpvid("invalidate", "--quiet", "--data", "d.csv", "--model", "init.json", "--delta", "0.1", "--certificate",
            "c.json", stderr=True)
    # a smaller noise bound claimed than certified: the verifier must refuse it (exit 1)
    r.write("tampered.json", re.sub(r'"dmax2": "[^"]*"', '"dmax2": "0.000001"', r.read("c.json"), count=1))
    r.verify("certificate", "tampered.json", expect=1, stderr=True)
    r.verify("certificate", "absent.json", expect=2, stderr=True)
    for name, code in [("hilbert_4", 0), ("indefinite_by_1e-30_4", 1), ("psd_rank15_of_20", 0), ("bad_nan", 2)]:
        r.copy(f"fixtures/psd/{name}.txt")
        r.verify("psd", name + ".txt", expect=code, stderr=True)


__doc__ += "".join(f"\n  {name:25s} {doc}" + (" [needs the data folder]" if needs else "")
                   for name, needs, _, doc in CASES) + "\n"


def data_folder(arg):
    if arg:
        return os.path.abspath(arg)
    if os.environ.get("LPVID_DATA"):
        return os.path.abspath(os.environ["LPVID_DATA"])
    return os.path.abspath(os.path.join(REPO, "..", "shared", "data"))


def selected(only):
    names = [c[0] for c in CASES]
    if not only:
        return names
    wanted = [n.strip() for n in only.split(",") if n.strip()]
    unknown = [n for n in wanted if n not in names]
    if unknown:
        sys.exit(f"unknown case(s) {', '.join(unknown)}; the cases: {', '.join(names)}")
    return [n for n in names if n in wanted]


def run_corpus(args):
    bin_dir, out_dir, data_dir = os.path.abspath(args.bin), os.path.abspath(args.out), data_folder(args.data)
    for exe in ("lpvid", "lpvid-verify"):
        if not os.access(os.path.join(bin_dir, exe), os.X_OK):
            sys.exit(f"{os.path.join(bin_dir, exe)}: not an executable")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", LC_ALL="C",
               LPVID=os.path.join(bin_dir, "lpvid"))  # LPVID: the lpvid examples/oracle/my_impl.py asks
    env.pop("LPVID_BLAS_PINNED", None)  # lpvid's own marker that it pinned the BLAS kernels (cpu_variants_test.py)
    os.makedirs(out_dir, exist_ok=True)
    manifest_path = os.path.join(out_dir, "manifest.json")
    manifest = {"format": "lpvid-behaviour-snapshot/1", "cases": {}}
    if os.path.exists(manifest_path):
        with open(manifest_path) as f:
            manifest = json.load(f)
    names = selected(args.only)
    total_started = time.monotonic()
    for i, name in enumerate(names, 1):
        _, needs, fn, _ = next(c for c in CASES if c[0] == name)
        case_dir = os.path.join(out_dir, name)
        shutil.rmtree(case_dir, ignore_errors=True)
        entry = {"bin": bin_dir, "data": data_dir, "repo": REPO}
        missing = [n for n in needs if not os.path.isfile(os.path.join(data_dir, n))]
        print(f"[{i:2d}/{len(names)}] {name:25s} ", end="", file=sys.stderr, flush=True)
        if missing:
            entry.update(status="skipped", reason="missing " + ", ".join(os.path.join(data_dir, n) for n in missing))
            print(f"skipped: {entry['reason']} (set --data or LPVID_DATA)", file=sys.stderr, flush=True)
        else:
            os.makedirs(case_dir)
            started = time.monotonic()
            r = Run(case_dir, bin_dir, data_dir, env)
            fn(r)
            seconds = time.monotonic() - started
            entry.update(status="ran", commands=len(r.steps), seconds=round(seconds, 1))
            codes = " ".join(str(code) for _, code, _ in r.steps)
            print(f"{seconds:6.1f} s  ({len(r.steps)} commands, exit codes {codes})", file=sys.stderr, flush=True)
            for label, code, expect in r.steps:
                if code != expect:
                    print(f"        note: {label} exited {code}, expected {expect}", file=sys.stderr, flush=True)
        manifest["cases"][name] = entry
        manifest["out"] = out_dir
        manifest["cases"] = {n: manifest["cases"][n] for n in [c[0] for c in CASES] if n in manifest["cases"]}
        with open(manifest_path, "w") as f:
            json.dump(manifest, f, indent=1)
            f.write("\n")
    print(f"total {time.monotonic() - total_started:.1f} s; record in {out_dir}", file=sys.stderr)


# --------------------------------------------------------------------------------------------------
# Comparing two records
# --------------------------------------------------------------------------------------------------

class Num(str):
    """A JSON number kept as written, so 1e-05 and 1.0e-05 differ (no float rounding, NaN equals NaN)."""

    def __repr__(self):
        return str.__str__(self)


def is_timing_key(key):
    """The rule of tests/cli/reproducibility_test.py: names ending in "seconds", or "elapsed"/"time"."""
    return key.endswith("seconds") or key in TIMING_KEYS


class PathMap:
    """The run's own folders replaced by placeholders, each only as a whole path component."""

    def __init__(self, manifest, out_dir, case):
        entry = manifest["cases"][case]
        roots = [(os.path.join(out, case), "<case>") for out in (manifest["out"], out_dir)]
        roots += [(manifest["out"], "<out>"), (out_dir, "<out>"), (entry["bin"], "<bin>"), (entry["data"], "<data>"),
                  (entry["repo"], "<repo>")]  # out_dir: where the record is now, if it was moved
        pairs = {}
        for path, name in roots:
            for p in (path, os.path.realpath(path)):
                pairs.setdefault(p.rstrip("/"), name)
        self.rules = [(re.compile(re.escape(p) + r"(?![\w.+-])"), name)
                      for p, name in sorted(pairs.items(), key=lambda kv: -len(kv[0])) if p]

    def __call__(self, text):
        for rx, name in self.rules:
            text = rx.sub(name, text)
        return text


def normalise_json(value, paths):
    """value without its timing keys, its strings' paths mapped (cf. strip_timing in reproducibility_test.py)."""
    if isinstance(value, dict):
        return {k: normalise_json(v, paths) for k, v in value.items() if not is_timing_key(k)}
    if isinstance(value, list):
        return [normalise_json(v, paths) for v in value]
    if type(value) is str:
        return paths(value)
    return value


def load_json(text):
    return json.loads(text, parse_float=Num, parse_int=Num, parse_constant=Num)


# The numbers of timing keys in the JSON text (for the text comparison after the values agree).
JSON_TIMING_NUMBER = re.compile(r'("(?:[^"\\]*seconds|elapsed|time)"\s*:\s*)-?\d[\d.eE+-]*')

# Printed wall-clock times in standard output (see the docstring: V1 ... O2). Each entry: rule name,
# pattern, replacement; TABLE_RULES apply only to the rows under their table's header line.
STDOUT_RULES = [
    ("V1", re.compile(r"^(checked in exact rational arithmetic in )\S+( s)", re.M), r"\1<t>\2"),
    ("V2", re.compile(r"^(  time: read )\S+( s, decide )\S+( s)$", re.M), r"\1<t>\2<t>\3"),
    ("I1", re.compile(r"(\(solver values, )\S+( s\))"), r"\1<t>\2"),
    ("I2", re.compile(r"(\(\d+ (?:leaf|leaves), )\S+( s\))"), r"\1<t>\2"),
    ("O1", re.compile(r"^(case-\S+ .*\b(?:confirmed|refuted|bad_witness|suboptimal|undecided|error|tampered) +)"
                      r"\d+\.\d\d +\d+\.\d\d(?: +|$)", re.M), r"\1<t> <t> "),
    ("O2", re.compile(r"^time \S+ s; (each refutation)", re.M), r"time <t> s; \1"),
]
TABLE_RULES = [
    ("T1", re.compile(r"^lambda\s+delta\s+dmax\s+verified\b"), re.compile(r"^(\s*(?:\S+\s+){7})\d+\.\d\d(?=\s|$)"),
     r"\1<t>"),
    ("S1", re.compile(r"^step\s+phase\s+basis\b.*\btime\[s\]"),
     re.compile(r"^(\d+\s.*?\b(?:consistent|cannot_explain|box_invalidated|not_decided|unverified)"
                r"\s+\S+\s+\S+\s+\S+\s+\d+\s+)\d+\.\d\d(?: +|$)"), r"\1<t> "),
]
JUNIT_TIME = re.compile(r'(\stime=")[^"]*(")')


def mask_stdout(text):
    for _, rx, repl in STDOUT_RULES:
        text = rx.sub(repl, text)
    lines = text.split("\n")
    for _, header, row, repl in TABLE_RULES:
        in_table = False
        for i, line in enumerate(lines):
            if header.search(line):
                in_table = True
            elif not line.strip():
                in_table = False  # a table ends at its first empty line
            elif in_table:
                lines[i] = row.sub(repl, line)
    return "\n".join(lines)


def first_line_difference(a, b):
    la, lb = a.split("\n"), b.split("\n")
    for i, (x, y) in enumerate(zip(la, lb), 1):
        if x != y:
            return f"line {i}: {x[:300]!r} != {y[:300]!r}"
    return f"lengths {len(la)} != {len(lb)} lines"


def compare_file(rel, path_a, path_b, map_a, map_b, kind):
    """None when equal under the rules, else the first difference."""
    with open(path_a, "rb") as f:
        ta = map_a(f.read().decode("utf-8", "surrogateescape"))
    with open(path_b, "rb") as f:
        tb = map_b(f.read().decode("utf-8", "surrogateescape"))
    if rel.endswith(".json"):
        try:
            ja, jb = load_json(ta), load_json(tb)
        except ValueError:
            ja = jb = None  # not JSON in one of them: compared as text below
        if ja is not None:
            d = first_difference(normalise_json(ja, map_a), normalise_json(jb, map_b), "$")
            if d:
                return d
            ta, tb = JSON_TIMING_NUMBER.sub(r"\1<t>", ta), JSON_TIMING_NUMBER.sub(r"\1<t>", tb)
            return None if ta == tb else "equal values, different text (key order or number format): " + \
                first_line_difference(ta, tb)
    if kind == "stdout":
        ta, tb = mask_stdout(ta), mask_stdout(tb)
    elif rel.endswith(".xml"):
        ta, tb = JUNIT_TIME.sub(r"\1<t>\2", ta), JUNIT_TIME.sub(r"\1<t>\2", tb)
    return None if ta == tb else first_line_difference(ta, tb)


def compared_files(case_dir):
    """rel path -> kind ("stdout", "stderr", "file") of the files compared; PNGs and uncompared streams left out."""
    files = {}
    for root, _, names in os.walk(case_dir):
        for name in names:
            rel = os.path.relpath(os.path.join(root, name), case_dir)
            if rel.lower().endswith(".png"):
                continue
            kind = "file"
            if rel.startswith("_cmd" + os.sep) and rel.endswith((".stdout", ".stderr")):
                kind = rel.rsplit(".", 1)[1]
                with open(os.path.join(case_dir, rel[:-len(kind)] + "json")) as f:
                    if not json.load(f).get(kind + "_compared"):
                        continue
            files[rel] = kind
    return files


def compare_case(name, dir_a, dir_b, man_a, man_b):
    ea, eb = man_a["cases"].get(name), man_b["cases"].get(name)
    if ea is None or eb is None:
        return f"recorded in {'B' if ea is None else 'A'} only"
    if ea["status"] != eb["status"]:
        return f"status {ea['status']} != {eb['status']}"
    if ea["status"] == "skipped":
        return None
    map_a, map_b = PathMap(man_a, dir_a, name), PathMap(man_b, dir_b, name)
    case_a, case_b = os.path.join(dir_a, name), os.path.join(dir_b, name)
    fa, fb = compared_files(case_a), compared_files(case_b)
    if set(fa) != set(fb):
        only_a, only_b = sorted(set(fa) - set(fb)), sorted(set(fb) - set(fa))
        return f"files differ: only in A {only_a[:5]}, only in B {only_b[:5]}"
    for rel in sorted(fa):
        d = compare_file(rel, os.path.join(case_a, rel), os.path.join(case_b, rel), map_a, map_b, fa[rel])
        if d:
            return f"{rel}: {d}"
    return None


def compare_records(args):
    dir_a, dir_b = os.path.abspath(args.a), os.path.abspath(args.b)
    manifests = []
    for d in (dir_a, dir_b):
        try:
            with open(os.path.join(d, "manifest.json")) as f:
                manifests.append(json.load(f))
        except OSError as e:
            sys.exit(f"{d}: no record ({e})")
    man_a, man_b = manifests
    known = [c[0] for c in CASES]
    names = [n for n in known if n in man_a["cases"] or n in man_b["cases"]]
    names += sorted((set(man_a["cases"]) | set(man_b["cases"])) - set(known))
    if args.only:
        names = [n for n in names if n in selected(args.only)]
    differ = 0
    for name in names:
        d = compare_case(name, dir_a, dir_b, man_a, man_b)
        skipped = man_a["cases"].get(name, {}).get("status") == "skipped" and not d
        print(f"{name:25s} " + ("DIFFERS: " + d if d else "same (skipped in both)" if skipped else "same"))
        differ += d is not None
    print(f"{len(names) - differ} of {len(names)} cases the same" + (f"; {differ} differ" if differ else ""))
    return 1 if differ else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    run = sub.add_parser("run", help="run the corpus with one pair of binaries")
    run.add_argument("--bin", required=True, help="folder holding lpvid and lpvid-verify")
    run.add_argument("--out", required=True, help="folder of the record (one sub-folder per case)")
    run.add_argument("--data", help="measured data folder (default: $LPVID_DATA, else ../shared/data beside the repository)")
    run.add_argument("--only", help="comma-separated case names (the other cases already recorded are kept)")
    cmp = sub.add_parser("compare", help="compare two records case by case")
    cmp.add_argument("a")
    cmp.add_argument("b")
    cmp.add_argument("--only", help="comma-separated case names")
    sub.add_parser("list", help="list the cases")
    args = parser.parse_args()
    if args.command == "run":
        run_corpus(args)
        return 0
    if args.command == "compare":
        return compare_records(args)
    for name, needs, _, doc in CASES:
        print(f"{name:25s} {doc}" + (" [needs the data folder]" if needs else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
