#!/usr/bin/env python3
"""Two exact checkers, one verdict: lpvid-verify against tests/second_checker/exact_checker.py.

Writes small certificates with the built lpvid (fixtures/example1 windows, generated random
cases, two records, paper mode, class certificates of identify, invalidations), then checks
each, and seeded mutations of each (one number of a tap, a dual entry, epsilon, a bound, a
shifted row window, a claim turned into its negation), with both checkers. A verdict where
both decide and disagree fails the test; so does a claim kind that the second checker never
decides (its "unsupported" answers are listed, not failures). Also the crafted case of a
class claim over a free x0 together with an output correction, whose residual is NOT affine
in the unknowns: the second checker must refuse it; lpvid-verify must refuse it too once its
class check tests affinity (until then this part fails and says so).

usage: second_checker_test.py LPVID LPVID_VERIFY SOURCE_DIR WORK_DIR
"""
import concurrent.futures
import copy
import json
import os
import random
import subprocess
import sys
import time
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import exact_checker  # noqa: E402

lpvid, verify, source, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
ex1 = os.path.join(source, "fixtures", "example1")
failures = []
start = time.time()


def note(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what, flush=True)
    if not ok:
        failures.append(what)


def run_lpvid(args, exit_codes=(0, 1)):
    quiet = [] if args[0] in ("generate", "simulate") else ["--quiet"]
    r = subprocess.run([lpvid, *args, *quiet], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode not in exit_codes:
        print(r.stdout[-3000:])
        note(False, f"lpvid {' '.join(args)}: exit {r.returncode}")
    return r.returncode


def verifier(path):
    """'holds' | 'refused' | 'undecided' from lpvid-verify's exit status."""
    r = subprocess.run([verify, "certificate", path], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True)
    first = (r.stdout.strip().splitlines() or [""])[-1][:200]
    if r.returncode == 0:
        return "holds", first
    if r.returncode in (1, 2):
        return "refused", first
    return "undecided", first


# ---------------------------------------------------------------------------------------
# 0. The exact PSD decision on the adversarial matrices of fixtures/psd (both programs)
# ---------------------------------------------------------------------------------------
psd_dir = os.path.join(source, "fixtures", "psd")
for name in sorted(os.listdir(psd_dir)):
    if not name.endswith(".txt") or name.startswith("bad_"):
        continue
    with open(os.path.join(psd_dir, name)) as f:
        rows = [ln.split("#")[0].split() for ln in f]
    m = [[exact_checker.parse_number(x, name) for x in r] for r in rows if r]
    ok, why = exact_checker.is_psd_rational(m)
    mine = ("PD" if why.startswith("PD") else "PSD") if ok else "NOT_PSD"
    r = subprocess.run([verify, "psd", os.path.join(psd_dir, name)], stdout=subprocess.PIPE, text=True)
    theirs = (r.stdout.split() or ["?"])[0]
    note(mine == theirs, f"psd {name}: second checker {mine}, lpvid-verify {theirs}")

# ---------------------------------------------------------------------------------------
# 1. Certificates written by lpvid
# ---------------------------------------------------------------------------------------

certs = []


def want(path):
    if os.path.exists(path):
        certs.append(path)
    else:
        note(False, f"{path} was written")


def out(name):
    return os.path.join(work, name)


def exact_text(q):
    """A terminating fraction as exact decimal text."""
    s = "-" if q < 0 else ""
    q = abs(q)
    digits = 0
    while (q * 10 ** digits).denominator != 1:
        digits += 1
    v = str((q * 10 ** digits).numerator).rjust(digits + 1, "0")
    return s + (v[:-digits] + "." + v[-digits:] if digits else v)


true_m = os.path.join(ex1, "true_model.json")
init_m = os.path.join(ex1, "initial_model.json")
data40 = os.path.join(ex1, "noise_free_n40.csv")

# Example 1 (2x2, two scheduling variables), a window of 16 rows: weighted objective, compact dual.
run_lpvid(["invalidate", "--data", data40, "--rows", "4:20", "--model", true_m, "--certificate", out("ex1.cert.json")])
want(out("ex1.cert.json"))
want(out("ex1.cert.lower.json"))
# The initial model at tight bounds: invalidated (compact and dense dual).
run_lpvid(["invalidate", "--data", data40, "--rows", "0:16", "--model", init_m, "--delta", "0.001", "--dmax", "0.001",
           "--certificate", out("ex1inv.cert.json")])
want(out("ex1inv.cert.json"))
run_lpvid(["invalidate", "--data", data40, "--rows", "0:12", "--model", init_m, "--delta", "0.001", "--dmax", "0.001",
           "--dense-dual", "--certificate", out("ex1invd.cert.json")])
want(out("ex1invd.cert.json"))
# Paper mode: the w form.
run_lpvid(["invalidate", "--data", data40, "--rows", "0:14", "--model", init_m, "--toeplitz", "paper",
           "--certificate", out("ex1paper.cert.json")])
want(out("ex1paper.cert.json"))

# Random SISO cases of the generator (static blocks sometimes), min d_max at fixed delta and
# min delta at fixed d_max, dense dual for one.
for seed in (3, 5, 8):
    case = out(f"rnd{seed}")
    run_lpvid(["generate", "random", "--siso", "--min-n", "20", "--max-n", "30", "--static-blocks",
               "--leading-zeros", "3", "--seed", str(seed), "--out", case], exit_codes=(0,))
    d, m = os.path.join(case, "data.csv"), os.path.join(case, "model.json")
    if not (os.path.exists(d) and os.path.exists(m)):
        note(False, f"generate random wrote {case}/data.csv and model.json")
        continue
    # seed 5: d_max below the least one at delta = 0 (0.0317), so that delta > 0 and a dual point is needed
    opts = {3: ["--delta", "0.2"], 5: ["--dmax", "0.02", "--dense-dual"], 8: ["--lambda", "0.3"]}[seed]
    c = out(f"rnd{seed}.cert.json")
    run_lpvid(["invalidate", "--data", d, "--model", m, "--certificate", c, *opts])
    want(c)
    if os.path.exists(c[:-len(".cert.json")] + ".cert.lower.json"):
        certs.append(c[:-len(".cert.json")] + ".cert.lower.json")
    if seed == 5:  # paper mode through the static input map: T_G12 driven by u'
        run_lpvid(["invalidate", "--data", d, "--model", m, "--toeplitz", "paper", "--certificate", out("rnd5p.cert.json")])
        want(out("rnd5p.cert.json"))
    if seed == 3:
        # identify with its class certificate (the generator's model has a correction basis)
        ci = out("rnd3id.cert.json")
        run_lpvid(["identify", "--data", d, "--model", m, "--class-leaves", "3", "--certificate", ci])
        want(ci)
        if os.path.exists(out("rnd3id.cert.class.json")):
            certs.append(out("rnd3id.cert.class.json"))

# Two records of Example 1 under one Delta.
run_lpvid(["invalidate", "--data", data40, "--rows", "0:10", "--data", data40, "--rows", "20:32", "--x0", "1/10,-1/5",
           "--model", true_m,
           "--certificate", out("two.cert.json")])
want(out("two.cert.json"))
want(out("two.cert.lower.json"))

# identify on Example 1 (multiplicative: a box of theta, branch and bound) and a class
# invalidation (additive LTI model, every theta free, at tight bounds).
run_lpvid(["identify", "--data", data40, "--rows", "0:14", "--model", init_m, "--basis", "1", "--class-leaves", "2",
           "--certificate", out("ex1id.cert.json")])
want(out("ex1id.cert.json"))
want(out("ex1id.cert.class.json"))
want(out("ex1id.cert.lower.json"))

# An LTI SISO model with the additive structure (every correction is free: the convex class
# case) and an unknown output offset, on data made here: the model's output plus 0.3 plus a
# small deterministic disturbance, exact decimals.
lti = os.path.join(source, "fixtures", "models", "lti_siso.json")
with open(lti) as f:
    lti_model = json.load(f)
lti_model["offset"] = {"basis": ["1"]}
lti_path = out("lti_offset.json")
with open(lti_path, "w") as f:
    json.dump(lti_model, f, indent=1)


def lti_data(path, n, seed):
    g = random.Random(seed)
    A = [[Fraction(0), Fraction(1)], [Fraction(-3, 25), Fraction(7, 10)]]
    x = [Fraction(0), Fraction(0)]
    with open(path, "w") as f:
        f.write("u,y\n")
        for k in range(n):
            u = Fraction(g.choice([-2, -1, 1, 2]), 2)
            y = x[0] / 4 + x[1] / 2 + Fraction(3, 10) + Fraction(g.randint(-50, 50), 1000)
            f.write(f"{exact_text(u)},{exact_text(y)}\n")
            x = [A[0][0] * x[0] + A[0][1] * x[1], A[1][0] * x[0] + A[1][1] * x[1] + u]


lti_d = out("lti.csv")
lti_data(lti_d, 24, 7)
run_lpvid(["identify", "--data", lti_d, "--model", lti_path, "--class-leaves", "2", "--certificate", out("ltiid.cert.json")])
want(out("ltiid.cert.class.json"))
# Whole-class invalidation at tight bounds (select-basis: cannot_explain carries a class certificate).
run_lpvid(["select-basis", "--data", lti_d, "--model", lti, "--delta", "0.001", "--dmax", "0.001", "--no-prune",
           "--certificate", out("ltisel.cert.json")], exit_codes=(0, 1, 5))
for name in sorted(os.listdir(work)):
    if name.startswith("ltisel") and name.endswith(".class.json"):
        certs.append(out(name))
# Most model features at once: scheduling on the model's own state ("@abs(x1-c)") beside a
# data column, a state offset, the general uncertainty channel (nz = 2 > ny = 1), an input
# delay, a dead zone before and a piecewise-linear map after the LPV part, x0 and a fixed offset.
feat_model = {
    "format": "lpvid-model/1", "states": 2, "inputs": 1, "outputs": 1, "scheduling": ["s", "p"],
    "columns": {"u": ["u"], "y": ["y"], "rho": ["@abs(x1-0.5)", "p"]},
    "initial": {"A": [{"basis": "1", "value": [["0.5", "0.1"], [0, "0.3"]]},
                      {"basis": "s", "value": [["0.1", 0], [0, 0]]},
                      {"basis": "p", "value": [[0, 0], ["0.05", 0]]}],
                "B": [{"basis": "1", "value": [[1], ["0.5"]]}],
                "C": [{"basis": "1", "value": [[1, "0.5"]]}],
                "D": [{"basis": "s*p", "value": [["0.1"]]}]},
    "uncertainty": {"structure": "general", "C1": [{"basis": "1", "value": [["0.1", 0], [0, "0.1"]]}],
                    "D1": [{"basis": "p", "value": [["0.05"], [0]]}]},
    "state_offset": {"basis": ["1"], "values": [["0.01", 0]]},
    "offset": {"basis": ["1"], "values": [["0.05"]]},
    "static": {"input_delay": 1, "input": {"kind": "dead_zone", "lower": "-0.1", "upper": "0.1"},
               "output": {"kind": "piecewise_linear", "knots": [-1, 0, 1], "values": ["-1.2", 0, "0.9"]}},
    "x0": ["0.2", "-0.1"]}
feat_path = out("features.json")
with open(feat_path, "w") as f:
    json.dump(feat_model, f, indent=1)
feat_d = out("features.csv")
g = random.Random(11)
with open(feat_d, "w") as f:
    f.write("p,u,y\n")
    for k in range(18):
        f.write(f"{exact_text(Fraction(g.randint(0, 10), 10))},{exact_text(Fraction(g.randint(-10, 10), 10))},"
                f"{exact_text(Fraction(g.randint(-100, 100), 100))}\n")
run_lpvid(["invalidate", "--data", feat_d, "--model", feat_path, "--certificate", out("feat.cert.json")])
want(out("feat.cert.json"))
want(out("feat.cert.lower.json"))

# A polynomial output map with a range narrower than its argument on the data: beyond the range
# the map continues linearly with the polynomial's value and slope at the nearer end; the second
# checker computes that line from the coefficients' derivative, not by Horner.
prange = copy.deepcopy(lti_model)
prange.pop("offset")
prange["static"] = {"output": {"kind": "polynomial", "coefficients": ["0.1", 1, "-0.2", "0.05"],
                               "range": ["-0.3", "0.4"]}}
with open(out("prange.json"), "w") as f:
    json.dump(prange, f, indent=1)
run_lpvid(["invalidate", "--data", lti_d, "--model", out("prange.json"), "--certificate", out("prange.cert.json")])
want(out("prange.cert.json"))

# x0 alone as the unknown of a multiplicative model (x0 moves z: a box, branch and bound); the
# model's own x0 is not zero, so the class's x0 entries must be read as changes of it.
mx0 = copy.deepcopy(lti_model)
mx0.pop("offset")
mx0.update({"correction": {"basis": []}, "uncertainty": {"structure": "multiplicative", "weight": "0.1"},
            "x0": ["0.5", "-0.25"]})
with open(out("mx0.json"), "w") as f:
    json.dump(mx0, f, indent=1)
run_lpvid(["identify", "--data", lti_d, "--model", out("mx0.json"), "--free-x0", "--class-leaves", "3",
           "--certificate", out("mx0.cert.json")])
want(out("mx0.cert.class.json"))

# Two records, one theta (identify over records: the alternating method); with --free-x0 each
# record has its own x0, which interacts with the output corrections (refused below).
run_lpvid(["identify", "--data", lti_d, "--data", lti_d, "--rows", "4:20", "--x0", "0,1", "--model", lti_path,
           "--class-leaves", "1", "--certificate", out("twoid.cert.json")])
want(out("twoid.cert.class.json"))
two_x0class = out("twox0.cert.class.json")
run_lpvid(["identify", "--data", lti_d, "--data", lti_d, "--rows", "4:20", "--x0", "0,1", "--model", lti_path,
           "--free-x0", "--class-leaves", "1", "--certificate", out("twox0.cert.json")])

# A state-scheduled model (rho = x1 on the grid) with output corrections: a class claim over theta
# alone is affine (the state does not depend on theta) and is decided; over theta and x0 it is not
# polynomial, and the second checker refuses it outright.
ss_model = {
    "format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": ["s"],
    "columns": {"u": ["u"], "y": ["y"], "rho": ["@x1"]},
    "initial": {"A": [{"basis": "1", "value": [["0.5"]]}, {"basis": "s", "value": [["0.2"]]}],
                "B": [{"basis": "1", "value": [[1]]}], "C": [{"basis": "1", "value": [[1]]}]},
    "correction": {"basis": ["1", "s"]},
    "uncertainty": {"structure": "multiplicative", "weight": "0.1"}}
ss_path = out("state_sched.json")
with open(ss_path, "w") as f:
    json.dump(ss_model, f, indent=1)
ss_d = out("state_sched.csv")
with open(ss_d, "w") as f:
    f.write("u,y\n")
    x = Fraction(0)
    for k in range(16):
        u = Fraction(g.choice([-1, 1, 2]), 4)
        f.write(f"{exact_text(u)},{exact_text(Fraction(round(x * 1100), 1000) + Fraction(g.randint(-20, 20), 1000))}\n")
        x = Fraction(round(((Fraction(1, 2) + Fraction(1, 5) * x) * x + u) * 10 ** 6), 10 ** 6)
run_lpvid(["identify", "--data", ss_d, "--model", ss_path, "--class-leaves", "2", "--certificate", out("ssid.cert.json")])
want(out("ssid.cert.json"))
want(out("ssid.cert.class.json"))
ssx0 = out("ssx0.cert.class.json")
ss_model["uncertainty"] = {"structure": "additive", "weight": "0.1"}  # every unknown free: one leaf
ss_add = out("state_sched_additive.json")
with open(ss_add, "w") as f:
    json.dump(ss_model, f, indent=1)
run_lpvid(["identify", "--data", ss_d, "--model", ss_add, "--free-x0", "--class-leaves", "1", "--certificate",
           out("ssx0.cert.json")])

# ---------------------------------------------------------------------------------------
# 2. The crafted x0 case: y_k = 0.9^k + 0.5^k, A = diag(0.9, 0.5), C = [1 0], x0 = 0,
#    output correction basis {1}. theta with C_1 = [0 1] and x0 = [1 1] fits exactly, so any
#    positive class lower end over (theta, x0) is false; the residual is bilinear in them.
# ---------------------------------------------------------------------------------------
x0dir = out("x0case")
os.makedirs(x0dir, exist_ok=True)


with open(os.path.join(x0dir, "data.csv"), "w") as f:
    f.write("u,y\n")
    for k in range(40):  # B = 0: u drives only the uncertainty channel z = 0.01 u
        f.write(f"{1 if k % 3 else -1},{exact_text(Fraction(9, 10) ** k + Fraction(1, 2) ** k)}\n")
x0model = {
    "format": "lpvid-model/1", "states": 2, "inputs": 1, "outputs": 1, "scheduling": [],
    "columns": {"u": ["u"], "y": ["y"]},
    "initial": {"A": [{"basis": "1", "value": [["0.9", 0], [0, "0.5"]]}],
                "B": [{"basis": "1", "value": [[0], [0]]}],
                "C": [{"basis": "1", "value": [[1, 0]]}]},
    "correction": {"basis": ["1"]},
    "uncertainty": {"structure": "additive", "weight": "0.01"},
    "x0": [0, 0]}
with open(os.path.join(x0dir, "model.json"), "w") as f:
    json.dump(x0model, f, indent=1)
x0cert = os.path.join(x0dir, "x0.cert.json")
run_lpvid(["identify", "--data", os.path.join(x0dir, "data.csv"), "--model", os.path.join(x0dir, "model.json"),
           "--free-x0", "--delta", "0.01", "--certificate", x0cert])
x0class = os.path.join(x0dir, "x0.cert.class.json")

# delta = 0 in closed form (docs/dual_certificates.md, "The delta = 0 lower end"): the exact interval
# of min d_max (a primal Delta = 0 with no taps and a zero_delta lower end), an invalidation at a fixed
# d_max, two records (MIMO, each its own x0), paper mode (w = 0), and the lower end 0 (nonnegative)
# of min delta at a d_max the noise alone reaches.
run_lpvid(["invalidate", "--data", data40, "--rows", "0:12", "--model", init_m, "--delta", "0",
           "--certificate", out("z0.cert.json")])
want(out("z0.cert.json"))
want(out("z0.cert.lower.json"))
run_lpvid(["invalidate", "--data", data40, "--rows", "0:12", "--model", init_m, "--delta", "0", "--dmax", "0.5",
           "--certificate", out("z0inv.cert.json")])
want(out("z0inv.cert.json"))
run_lpvid(["invalidate", "--data", data40, "--rows", "0:10", "--data", data40, "--rows", "20:32", "--x0", "1/10,-1/5",
           "--model", init_m, "--delta", "0", "--certificate", out("z0two.cert.json")])
want(out("z0two.cert.json"))
want(out("z0two.cert.lower.json"))
run_lpvid(["invalidate", "--data", data40, "--rows", "0:12", "--model", init_m, "--toeplitz", "paper", "--delta", "0",
           "--certificate", out("z0paper.cert.json")])
want(out("z0paper.cert.json"))
want(out("z0paper.cert.lower.json"))
run_lpvid(["invalidate", "--data", data40, "--rows", "0:12", "--model", init_m, "--dmax", "10",
           "--certificate", out("z0nn.cert.json")])
want(out("z0nn.cert.json"))
want(out("z0nn.cert.lower.json"))

print(f"-- {len(certs)} certificates written in {time.time() - start:.1f} s", flush=True)

# ---------------------------------------------------------------------------------------
# 3. Mutations: one number changed at a time
# ---------------------------------------------------------------------------------------


def scaled_text(v, factor):
    return exact_text_any(exact_checker.parse_number(v, "mutation") * factor)


def exact_text_any(q):
    return f"{q.numerator}/{q.denominator}" if q.denominator != 1 else str(q.numerator)


def dual_points(cert):
    if "dual" in cert:
        return [cert["dual"]]
    if "class" in cert:
        return [n["leaf"] for n in cert["class"]["nodes"] if "leaf" in n]
    return []


def least_dmax2(cert_path):
    """||r||^2/(n*ny) of a certificate's model on its data, by the second checker's own simulation:
    the exact least d_max^2 at delta = 0, and the model's (ny, nz)."""
    with open(cert_path) as f:
        c = exact_checker.load_json_exact(f.read())
    model = exact_checker.Model(c["model"])
    recs = exact_checker.load_records(c, model, os.path.dirname(os.path.abspath(cert_path)), None)
    sims = [exact_checker.simulate(model, rec, x0) for rec, x0 in recs]
    rr = sum(v * v for sim in sims for row in sim["r"] for v in row)
    return rr / (sum(rec["n"] for rec, _ in recs) * model.ny), model.ny, model.nz


def closed_form_mutations(cert, cert_path, add):
    """Closed forms (zero_delta) and the primal Delta = 0 beside them: claims a part in 10^40 on
    either side of the exact ||r||^2/(n*ny), delta2 a part in 10^40 above 0, a tap added to no taps."""
    tiny = Fraction(1, 10 ** 40)
    if cert["claim"] == "consistent" and cert["form"] == "delta" and not cert["delta_taps"]:
        _, ny, nz = least_dmax2(cert_path)
        add("a tap 1/1000 at delta2 = 0" if exact_checker.parse_number(cert["delta2"], "d") == 0 else "a tap 1/1000",
            lambda c: c.__setitem__("delta_taps", [["1/1000"] * (ny * nz)]))
    if cert.get("form") != "zero_delta":
        return
    m, _, _ = least_dmax2(cert_path)
    add("delta2 = 1e-40", lambda c: c.__setitem__("delta2", exact_text_any(tiny)))
    if cert["claim"] == "lower_bound":
        add("lower_bound = exact", lambda c: c.__setitem__("lower_bound", exact_text_any(m)))
        add("lower_bound = exact + 1e-40", lambda c: c.__setitem__("lower_bound", exact_text_any(m + tiny)))
    else:
        add("dmax2 = exact (equality is consistent)", lambda c: c.__setitem__("dmax2", exact_text_any(m)))
        add("dmax2 = exact - 1e-40", lambda c: c.__setitem__("dmax2", exact_text_any(m - tiny)))


def mutations(cert, rng, cert_path):
    """(name, mutated certificate) pairs; each changes one thing."""
    out_ = []

    def add(name, fn):
        c = copy.deepcopy(cert)
        if fn(c) is not False:
            out_.append((name, c))

    def pick(rows):
        i = rng.randrange(len(rows))
        j = rng.randrange(len(rows[i])) if rows[i] else None
        return i, j

    claim = cert["claim"]
    if claim in ("consistent", "not_a_witness"):
        for key, f in (("delta2", Fraction(1, 2)), ("dmax2", Fraction(1, 2)), ("delta2", Fraction(999, 1000))):
            add(f"{key}*{f}", lambda c, key=key, f=f: c.__setitem__(key, scaled_text(c[key], f)))
        if cert["form"] == "delta" and cert["delta_taps"]:
            def tap(c):
                i, j = pick(c["delta_taps"])
                c["delta_taps"][i][j] = scaled_text(c["delta_taps"][i][j], Fraction(3, 2)) \
                    if exact_checker.parse_number(c["delta_taps"][i][j], "t") != 0 else "1/1000"
            add("tap*1.5", tap)
        elif cert["form"] == "w":
            def wentry(c):
                i, j = pick(c["w"])
                c["w"][i][j] = exact_text_any(exact_checker.parse_number(c["w"][i][j], "w") + Fraction(1, 100))
            add("w+0.01", wentry)
        add("claim->not_a_witness" if claim == "consistent" else "claim->consistent",
            lambda c: c.__setitem__("claim", "not_a_witness" if claim == "consistent" else "consistent"))

        def lower_and_flip(c):
            c["delta2"] = scaled_text(c["delta2"], Fraction(1, 2))
            c["claim"] = "not_a_witness"
        if claim == "consistent":
            add("delta2/2+not_a_witness", lower_and_flip)
    closed_form_mutations(cert, cert_path, add)
    if claim == "class_lower_bound":
        # Claims at the exact lowest leaf bound the second checker computes: one a part in 10^9
        # below it holds, one a part in 10^9 above it does not, for any correct checker (the
        # verifier's square-root upper bounds are looser than this one's, never tighter). A
        # checker whose penalty terms are too small (an epsilon halved) accepts the second.
        exact_checker.BOUNDS.clear()
        holds, _ = exact_checker.check_certificate(cert_path)
        if holds == "holds" and exact_checker.BOUNDS and min(exact_checker.BOUNDS) > 0:
            lowest = min(exact_checker.BOUNDS)
            for name, f in (("at the lowest leaf - 1e-9", 1 - Fraction(1, 10**9)),
                            ("at the lowest leaf + 1e-9", 1 + Fraction(1, 10**9))):
                add(name, lambda c, f=f: c.__setitem__("lower_bound", exact_text_any(lowest * f)))
    if "lower_bound" in cert:
        add("lower_bound*2", lambda c: c.__setitem__("lower_bound", scaled_text(c["lower_bound"], 2))
            if exact_checker.parse_number(c["lower_bound"], "lb") != 0 else c.__setitem__("lower_bound", "1/100"))
        add("lower_bound*1/2", lambda c: c.__setitem__("lower_bound", scaled_text(c["lower_bound"], Fraction(1, 2))))
    if claim in ("invalidated", "class_invalidated"):
        add("dmax2*4", lambda c: c.__setitem__("dmax2", scaled_text(c["dmax2"], 4)))
    points = dual_points(cert)
    if points:
        k = rng.randrange(len(points))

        def point(c):
            return dual_points(c)[k]

        def g_entry(c):
            p = point(c)
            i, j = pick(p["g"])
            p["g"][i][j] = exact_text_any(exact_checker.parse_number(p["g"][i][j], "g") * Fraction(5, 4) + Fraction(1, 10))
        add("g entry", g_entry)
        add("sigma*2", lambda c: point(c).__setitem__("sigma", scaled_text(point(c)["sigma"], 2)))
        if "Y1" in points[k]:
            def y1(c):
                p = point(c)
                i = rng.randrange(len(p["Y1"]))
                j = rng.randrange(len(p["Y1"][i]))
                p["Y1"][i][j] = exact_text_any(exact_checker.parse_number(p["Y1"][i][j], "Y") + Fraction(1, 1000))
            add("Y1 entry", y1)
        else:
            add("t*3/2", lambda c: point(c).__setitem__("t", scaled_text(point(c)["t"], Fraction(3, 2))))
            add("u_floor*4", lambda c: point(c).__setitem__("u_floor", scaled_text(point(c)["u_floor"], 4)))
            add("x/8", lambda c: point(c).__setitem__("x", scaled_text(point(c)["x"], Fraction(1, 8))))

            def ptap(c):
                p = point(c)
                i, j = pick(p["taps"])
                p["taps"][i][j] = exact_text_any(exact_checker.parse_number(p["taps"][i][j], "h") + Fraction(1, 64))
            add("dual tap", ptap)
        if "epsilon" in points[k]:
            add("epsilon/2", lambda c: point(c).__setitem__("epsilon", scaled_text(point(c)["epsilon"], Fraction(1, 2))))
    if "class" in cert:
        cl = cert["class"]
        bounded = [i for i in range(len(cl["parameters"])) if i not in cl["free"]]
        if bounded:
            i = rng.choice(bounded)
            add("radius*4", lambda c: c["class"]["radius"].__setitem__(i, scaled_text(c["class"]["radius"][i], 4)))

            def move_centre(c):
                r = exact_checker.parse_number(c["class"]["radius"][i], "radius")
                ctr = exact_checker.parse_number(c["class"]["center"][i], "center")
                c["class"]["center"][i] = exact_text_any(ctr + (r / 2 if r else Fraction(1, 100)))
            add("center+radius/2", move_centre)
    # a record's row window moved by one sample
    def shift(c):
        d = c["data"] if "data" in c else c["records"][rng.randrange(len(c["records"]))]
        if "rows" not in d:
            return False
        d["rows"] = [d["rows"][0] + 1, d["rows"][1] + 1]
    if ("data" in cert and "rows" in cert["data"]) or "records" in cert:
        add("rows+1", shift)
    return out_


# ---------------------------------------------------------------------------------------
# 4. Both checkers on everything
# ---------------------------------------------------------------------------------------
rng = random.Random(49)
decided = {}          # claim/form -> count of decisions by the second checker
unsupported = []
agree = disagree = 0
verdicts = {}         # agreed verdict -> count
checked = 0
pending = []
for path in certs:
    pending.append((path, os.path.basename(path), None))
    with open(path) as f:
        cert = json.load(f)
    for name, mut in mutations(cert, rng, path):
        mpath = os.path.join(os.path.dirname(path), os.path.basename(path)[:-5] + f".mut.{name.replace('/', '_')}.json")
        with open(mpath, "w") as f:
            json.dump(mut, f)
        pending.append((mpath, os.path.basename(path) + " / " + name, mut))

# The second checker runs in two worker processes while lpvid-verify runs here.
with concurrent.futures.ProcessPoolExecutor(max_workers=2) as pool:
    second = [pool.submit(exact_checker.check_certificate, path) for path, _, _ in pending]
    first = [verifier(path) for path, _, _ in pending]
    second = [f.result() for f in second]
for (path, label, _), (a, why_a), (b, why_b) in zip(pending, first, second):
    with open(path) as f:
        cert = json.load(f)
    kind = f"{cert.get('claim')}/{cert.get('form')}" + ("/records" if "records" in cert else "")
    checked += 1
    line = f"{label}: lpvid-verify {a}, second checker {b}"
    if b == "unsupported":
        unsupported.append(f"{label}: {why_b}")
        print("unsupported: " + line + f" -- {why_b}", flush=True)
        continue
    decided[kind] = decided.get(kind, 0) + 1
    if a == "undecided":
        print("undecided: " + line, flush=True)
        continue
    if a == b:
        agree += 1
        verdicts[b] = verdicts.get(b, 0) + 1
        print("agree:  " + line, flush=True)
    else:
        disagree += 1
        note(False, line + f"\n        lpvid-verify: {why_a}\n        second: {why_b}")

# the certificates lpvid wrote must hold for both (an unmutated certificate is a true claim)
for path in certs:
    b, why = exact_checker.check_certificate(path)
    note(b in ("holds", "unsupported"), f"{os.path.basename(path)} written by lpvid holds for the second checker "
         f"({b}: {why[:160]})")

needed = ["consistent/delta", "consistent/w", "not_a_witness/delta", "lower_bound/dual_delta_path",
          "lower_bound/dual_delta", "invalidated/dual_delta_path", "invalidated/dual_delta",
          "class_lower_bound/dual_delta_path", "class_invalidated/dual_delta_path",
          "class_lower_bound/dual_delta_path/records", "consistent/delta/records", "lower_bound/dual_delta_path/records",
          "lower_bound/zero_delta", "invalidated/zero_delta", "lower_bound/zero_delta/records", "lower_bound/nonnegative"]
for kind in needed:
    note(decided.get(kind, 0) > 0, f"the second checker decided {kind} at least once ({decided.get(kind, 0)})")
note(verdicts.get("holds", 0) >= 20 and verdicts.get("refused", 0) >= 20,
     f"both verdicts agreed on many times ({verdicts})")
note(len(unsupported) <= checked // 4, f"at most a quarter unsupported ({len(unsupported)} of {checked})")

# ---------------------------------------------------------------------------------------
# 5. Class claims whose residual is not affine in the unknowns
# ---------------------------------------------------------------------------------------


FALSE_CLAIMS = os.path.join(source, "fixtures", "false_class_claims")


def refused_by_both(path, needle, what, fixture=None):
    """A class claim whose residual is not affine in its unknowns: lpvid must not write it (it says
    why it gives no class bound); the copy an earlier lpvid wrote (`fixture`, when there is one) is
    refused by the second checker for that reason and by lpvid-verify."""
    note(not os.path.exists(path), f"{what}: lpvid writes no such class claim ({os.path.basename(path)})")
    for p in ([path] if os.path.exists(path) else []) + ([fixture] if fixture else []):
        b, why_b = exact_checker.check_certificate(p)
        note(b == "refused" and needle in why_b, f"second checker refuses {what} ({b}: {why_b})")
        a, why_a = verifier(p)
        note(a == "refused", f"lpvid-verify refuses {what} ({a}: {why_a})")


x0_fixture = os.path.join(FALSE_CLAIMS, "output_correction_x0", "identify.class.json")
refused_by_both(x0class, "not affine", "the class claim over a free x0 with an output correction", x0_fixture)
if os.path.exists(x0_fixture):
    # The claim is false, not merely unproven: C_1 = [0 1] and x0 = [1 1] explain the data exactly.
    x0data = os.path.join(FALSE_CLAIMS, "output_correction_x0", "data.csv")
    with open(x0_fixture) as f:
        claim_lb = exact_checker.parse_number(json.load(f)["lower_bound"], "lower_bound")
    with open(os.path.join(FALSE_CLAIMS, "output_correction_x0", "model.json")) as f:
        fit = exact_checker.load_json_exact(f.read())
    fit["initial"]["C"] = [{"basis": "1", "value": [[1, 1]]}]
    fit["x0"] = [1, 1]
    fm = exact_checker.Model(fit)
    with open(x0data, "rb") as f:
        sha = exact_checker.hashlib.sha256(f.read()).hexdigest()
    rec = exact_checker.read_data(x0data, sha, None, None, fm, "x0 data")
    r = exact_checker.simulate(fm, rec, fm.x0)["r"]
    note(claim_lb > 0 and all(abs(v) < Fraction(1, 10**12) for row in r for v in row),
         f"the x0 class claim (lower end {float(claim_lb):.6g}) is false: theta with C_1 = [0 1], x0 = [1 1] "
         f"leaves the residual at the data's rounding")
refused_by_both(two_x0class, "not affine", "a two-record class claim over free x0 with output corrections")
refused_by_both(ssx0, "state", "a class claim over x0 with state scheduling",
                os.path.join(FALSE_CLAIMS, "state_scheduling_x0", "identify.class.json"))
refused_by_both(ssx0, "not affine", "a select-basis class invalidation over x0 with an output correction",
                os.path.join(FALSE_CLAIMS, "output_correction_x0", "select_basis.class.json"))

# ---------------------------------------------------------------------------------------
# 6. The command line: exit 0 / 1 / 3 and --data
# ---------------------------------------------------------------------------------------


def cli(*args):
    r = subprocess.run([sys.executable, os.path.join(HERE, "exact_checker.py"), *args], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    return r.returncode, r.stdout.strip()


if os.path.exists(out("ex1.cert.json")):
    moved = out("moved")
    os.makedirs(moved, exist_ok=True)
    with open(out("ex1.cert.json")) as f:
        c = json.load(f)
    c["data"]["file"] = "nowhere/noise_free_n40.csv"
    with open(os.path.join(moved, "ex1.cert.json"), "w") as f:
        json.dump(c, f)
    code, text = cli(os.path.join(moved, "ex1.cert.json"), "--data", data40)
    note(code == 0 and text.startswith("holds"), f"CLI with --data: exit {code}, {text[:80]}")
    code, text = cli(os.path.join(moved, "ex1.cert.json"))
    note(code == 1 and text.startswith("refused"), f"CLI without the data file: exit {code}, {text[:80]}")
    c["data"]["file"] = os.path.abspath(data40)
    c["delta2"] = scaled_text(c["delta2"], Fraction(1, 2))
    with open(os.path.join(moved, "low.cert.json"), "w") as f:
        json.dump(c, f)
    code, text = cli(os.path.join(moved, "low.cert.json"))
    note(code == 1 and text.startswith("refused: consistent does not hold"), f"CLI on a false claim: exit {code}, {text[:80]}")
if os.path.exists(out("ltiid.cert.class.json")):
    with open(out("ltiid.cert.class.json")) as f:
        c = json.load(f)
    c["model"]["static"] = {"output": {"kind": "abs"}}  # a class claim through an output map: not decided
    with open(os.path.join(work, "class_output_map.json"), "w") as f:
        json.dump(c, f)
    code, text = cli(os.path.join(work, "class_output_map.json"))
    note(code == 3 and text.startswith("unsupported"), f"CLI on an unsupported feature: exit {code}, {text[:80]}")

print(f"-- {len(certs)} certificates, {checked - len(certs)} mutations, {checked} checks: {agree} agree, "
      f"{disagree} disagree ({verdicts}), {len(unsupported)} unsupported; decided kinds: {decided}")
for u in unsupported:
    print("   unsupported: " + u)
print(f"-- {time.time() - start:.1f} s")
if failures:
    print(f"{len(failures)} failure(s)")
    sys.exit(1)
print("all checks passed")
