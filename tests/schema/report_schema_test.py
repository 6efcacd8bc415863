#!/usr/bin/env python3
"""docs/<command>_report.schema.json against the reports the built lpvid writes.

Every command whose help lists --report must have a schema. Runs each command
on small generated data, in the variants that change the report's shape
(invalidate with both bounds, one, none, delta = 0, the paper's T_z and two
records; certify on csdp's solution; identify with and without a solution,
with the class interval and with x0 free; select-basis found and not found;
tradeoff; fit-linear with --order auto, with validation data and with two
records; compare with one and two models on one and two records; diagnose
with a validation record, with folds, with two records and two test sets;
oracle with confirmed, identify and error cases; jobs merge with verified,
missing, refused windows and the joint claim, and the jobs' own invalidate
reports), validates every report and prints the failing report and JSON
path. Then
makes broken copies of every report and checks that the schema refuses each:
a key the writer always writes deleted (every top-level one, and the first
key of every nested object), every key renamed, every number turned into a
string (one copy per distinct field). Only the open maps (theta's basis
terms, units, offset_phi, diagnose's effect parameters) are left out. Also
checks that the versioned schemas name the writers' format strings, that the
$defs shared by several schemas are identical, and that docs/reports.md
names every schema.

usage: report_schema_test.py LPVID SOURCE_DIR WORK_DIR
"""
import copy
import json
import os
import re
import shutil
import subprocess
import sys
import time

import jsonschema

lpvid, source, work = sys.argv[1:4]
source = os.path.abspath(source)
lpvid = os.path.abspath(lpvid)
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []
started = time.time()

# The command (as `lpvid <command> --help` names it) and its schema file.
SCHEMA_FILES = {
    "fit-linear": "fit_linear_report.schema.json",
    "compare": "compare_report.schema.json",
    "invalidate": "invalidate_report.schema.json",
    "certify": "certify_report.schema.json",
    "identify": "identify_report.schema.json",
    "select-basis": "select_basis_report.schema.json",
    "tradeoff": "tradeoff_report.schema.json",
    "diagnose": "diagnose_report.schema.json",
    "oracle": "oracle_report.schema.json",
    "jobs merge": "jobs_merge_report.schema.json",
}
# Objects whose keys are names from the data or the model (open maps), and
# diagnose's kind-specific effect parameters: no key of theirs is checked.
OPEN_MAPS = {"theta", "units", "offset_phi"}
OPEN_SECTIONS = {"parameters", "parameters_when_chosen"}


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)
    return ok


def load(path):
    # lpvid writes no NaN or Infinity (nlohmann writes null); neither may the reports.
    def bad_constant(name):
        raise ValueError(f"{name} is not JSON")
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_constant=bad_constant)


def read_text(*parts):
    with open(os.path.join(source, *parts), encoding="utf-8") as f:
        return f.read()


def run(args, cwd=work, env=None):
    r = subprocess.run(args, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return r.returncode, r.stdout


# ---------------------------------------------------------------- the schemas
schemas, validators = {}, {}
for command, name in SCHEMA_FILES.items():
    schema = load(os.path.join(source, "docs", name))
    jsonschema.Draft202012Validator.check_schema(schema)
    schemas[command] = schema
    validators[command] = jsonschema.Draft202012Validator(schema)

# Every command with --report has a schema, and every schema a command.
code, text = run([lpvid, "--help"])
listed = re.findall(r"^  ([a-z][a-z-]*)\s{2,}", text.split("Subcommands:")[1], re.M)
with_report = []
for command in listed:
    code, text = run([lpvid, command, "--help"])
    if command == "jobs":
        for sub in re.findall(r"^  ([a-z][a-z-]*)\s{2,}", text.split("Subcommands:")[1], re.M):
            code, subtext = run([lpvid, "jobs", sub, "--help"])
            if "--report" in subtext:
                with_report.append("jobs " + sub)
    elif "--report" in text:
        with_report.append(command)
check(len(listed) >= 10 and sorted(with_report) == sorted(SCHEMA_FILES),
      f"every command with --report has a schema: {sorted(with_report)}")

# The versioned reports: the schema's format const and $id are the writer's string.
for command, path, pattern in (("oracle", ("src", "oracle", "oracle_report.cc"), r'j\["format"\] = "([^"]+)"'),
                               ("jobs merge", ("src", "cli", "jobs_command.cc"), r'report\["format"\] = "([^"]+)"')):
    version = re.search(pattern, read_text(*path)).group(1)
    schema = schemas[command]
    check(schema["properties"]["format"]["const"] == version and schema["$id"].endswith(version),
          f"{command} schema: format const and $id name {version}, the string {'/'.join(path)} writes")

# A $def of the same name is the same in every schema (one writer: report.cc, records_report.cc).
shared = {}
for command, schema in schemas.items():
    for name, definition in schema.get("$defs", {}).items():
        shared.setdefault(name, []).append((command, definition))
for name, uses in sorted(shared.items()):
    if len(uses) > 1:
        check(all(u[1] == uses[0][1] for u in uses),
              f"$defs/{name} is identical in the {len(uses)} schemas that hold it ({', '.join(u[0] for u in uses)})")

reports_md = read_text("docs", "reports.md")
missing = [name for name in SCHEMA_FILES.values() if name not in reports_md]
missing += [s["$id"] for s in schemas.values() if s["$id"] not in reports_md]
check(not missing, f"docs/reports.md names every report schema and its $id {missing}")

# ---------------------------------------------------------------- the data
for args in (["generate", "example1", "--n", "30", "--out", "d.csv", "--model-out", "m.json"],
             ["generate", "example1", "--n", "80", "--out", "long.csv", "--model-out", "long.json"],
             ["generate", "effect-case", "--effect", "output_offset", "--n", "200", "--out", "ec.csv",
              "--validation-out", "ecv.csv", "--model-out", "ecm.json"]):
    code, out = run([lpvid] + args)
    if not check(code == 0, f"lpvid {' '.join(args)}: exit {code}" + ("" if code == 0 else f" ({out.strip()[-300:]})")):
        sys.exit(1)

# ---------------------------------------------------------------- the reports
reports = []  # (label, command, path)


def produce(label, command, args, exits, report=None, cwd=work, env=None):
    """Runs `lpvid <args> --report <label>.json` and remembers the report."""
    path = os.path.join(work, report or label.replace(" ", "_").replace("/", "_") + ".json")
    if report is None:
        args = args + ["--report", path]
    code, out = run([lpvid] + args, cwd=cwd, env=env)
    if check(code in exits and os.path.exists(path), f"{label}: exit {code} (expected {exits}), report written"
             + ("" if code in exits else f" ({out.strip()[-400:]})")):
        reports.append((label, command, path))
    return path


q = ["--quiet"]
data = ["--data", "d.csv", "--model", "m.json"]
ec = ["--u", "u1", "--y", "y1"]

produce("fit-linear/auto", "fit-linear", ["fit-linear", "--data", "ec.csv"] + ec + ["--max-order", "2", "--model-out",
                                                                                   "fl2.json"], {0})
produce("fit-linear/validation", "fit-linear", ["fit-linear", "--data", "ec.csv"] + ec + [
    "--order", "1", "--offset", "--validation", "ecv.csv", "--sample-time", "0.5", "--unit", "y1=V",
    "--model-out", "fl1.json"], {0})
produce("fit-linear/two-records", "fit-linear", ["fit-linear", "--data", "ec.csv", "--rows", "0:100", "--data",
                                                 "ec.csv", "--rows", "100:200"] + ec + ["--max-order", "2"], {0})

produce("compare/one-model", "compare", ["compare", "--data", "ecv.csv", "--model", "fl1.json", "--out", "c.csv",
                                         "--plots", "compare-plots"], {0})
produce("compare/two-models", "compare", ["compare", "--data", "ecv.csv", "--model", "fl2.json", "--model", "fl1.json",
                                          "--x0", "fit", "--predict", "3"], {0})
produce("compare/two-records", "compare", ["compare", "--data", "ecv.csv", "--rows", "0:100", "--data", "ecv.csv",
                                           "--rows", "100:200", "--model", "fl2.json", "--warmup", "5"], {0})
produce("compare/two-models-two-records", "compare", ["compare", "--data", "ecv.csv", "--rows", "0:100", "--data",
                                                      "ecv.csv", "--rows", "100:200", "--model", "fl2.json",
                                                      "--model", "fl1.json"], {0})

produce("invalidate/no-bound", "invalidate", ["invalidate"] + data + q, {0})
produce("invalidate/delta", "invalidate", ["invalidate"] + data + q + ["--delta", "0.1"], {0})
produce("invalidate/dmax", "invalidate", ["invalidate"] + data + q + ["--dmax", "0.1"], {0})
produce("invalidate/both-consistent", "invalidate", ["invalidate"] + data + q + ["--delta", "1", "--dmax", "1"], {0})
produce("invalidate/both-invalidated", "invalidate", ["invalidate"] + data + q + ["--delta", "0.1", "--dmax", "0.1"],
        {1})
# delta = 0: answered in closed form with no solve where lpvid has it (src/certify/closed_form.h)
produce("invalidate/delta-zero", "invalidate", ["invalidate"] + data + q + ["--delta", "0"], {0})
produce("invalidate/delta-zero-invalidated", "invalidate", ["invalidate"] + data + q + ["--delta", "0", "--dmax",
                                                                                      "0.0001"], {1})
produce("invalidate/paper", "invalidate", ["invalidate"] + data + q + ["--toeplitz", "paper"], {0})
produce("invalidate/two-records", "invalidate", ["invalidate", "--data", "d.csv", "--rows", "0:15", "--data", "d.csv",
                                                 "--rows", "15:30", "--model", "m.json", "--delta", "0.1"] + q, {0})

# certify: the Theorem 2.1 program solved by the csdp program outside lpvid.
if shutil.which("csdp"):
    code, out = run([lpvid, "invalidate"] + data + q + ["--delta", "0.1", "--write-sdpa", "p.dat-s"])
    code_csdp, _ = run(["csdp", "p.dat-s", "p.sol"])
    if check(code == 0 and code_csdp == 0, f"invalidate --write-sdpa and csdp: exits {code}, {code_csdp}"):
        produce("certify/csdp", "certify", ["certify"] + data + q + ["--delta", "0.1", "--program", "p.dat-s",
                                                                     "--solution", "p.sol"], {0})
else:
    print("note:   no csdp program on PATH: certify's report is not produced here")

produce("identify/class-interval", "identify", ["identify"] + data + q + ["--basis", "1", "--class-leaves", "1",
                                                                        "--model-out", "idm.json"], {0})
produce("identify/both-bounds", "identify", ["identify"] + data + q + ["--basis", "1", "--delta", "0.1", "--dmax",
                                                                     "0.5"], {0})
produce("identify/alternating-free-x0", "identify", ["identify"] + data + q + [
    "--basis", "1,rho1", "--method", "alternating", "--free-x0", "--dmax", "0.5"], {0})
produce("identify/no-solution", "identify", ["identify"] + data + q + ["--basis", "1", "--delta", "0", "--dmax",
                                                                     "0.0001"], {5})

produce("select-basis/found", "select-basis", ["select-basis"] + data + q + ["--delta", "0.1", "--dmax", "0.3",
                                                                           "--degree", "1"], {0})
produce("select-basis/not-decided", "select-basis", ["select-basis"] + data + q + ["--delta", "0", "--dmax", "0.001",
                                                                                 "--degree", "1"], {1, 5})
produce("select-basis/no-class-bound", "select-basis", ["select-basis"] + data + q + [
    "--delta", "0.01", "--dmax", "0.01", "--degree", "0", "--no-class-bound"], {5})

produce("tradeoff/two-lambdas", "tradeoff", ["tradeoff"] + data + q + ["--basis", "1", "--lambdas", "0.2,0.8", "--csv",
                                                                     "curve.csv"], {0})

small = ["--max-effects", "1", "--degree", "1", "--max-input-delay", "1", "--state-degree", "0", "--fixed-dynamics",
         "--max-windows", "1", "--threads", "1"] + q
produce("diagnose/validation", "diagnose", ["diagnose", "--data", "ec.csv", "--model", "ecm.json", "--validation",
                                            "ecv.csv", "--test", "ecv.csv"] + small, {0})
produce("diagnose/folds", "diagnose", ["diagnose", "--data", "ec.csv", "--model", "ecm.json", "--folds", "2",
                                       "--test-columns", "u1,y1", "--test-rows", "100:200", "--model-out",
                                       "dgm.json"] + small, {0})
produce("diagnose/two-records", "diagnose", ["diagnose", "--data", "ec.csv", "--rows", "0:100", "--data", "ec.csv",
                                             "--rows", "100:200", "--model", "ecm.json", "--folds", "2", "--test",
                                             "ecv.csv", "--test", "ecv.csv", "--test-rows", "0:120"] + small, {0})

# oracle: the ten-line example on two given cases, the toy on an identify case, a command that fails.
cases = os.path.join(work, "cases")
for seed, kind, folder in ((3, "min_dmax", "fixed/c1"), (4, "decide", "fixed/c2"), (5, "identify", "identify/c1")):
    run([lpvid, "generate", "random", "--seed", str(seed), "--kinds", kind, "--min-n", "10", "--max-n", "20",
         "--siso", "--out", os.path.join(cases, folder)])
env = dict(os.environ, LPVID=lpvid)
impl = os.path.join(source, "examples", "oracle", "my_impl.py")
toy = os.path.join(source, "tests", "oracle", "toy_impls.py")
produce("oracle/confirmed", "oracle", ["oracle", "--quiet", "--cases-dir", os.path.join(cases, "fixed"), "--work",
                                       "oracle-fixed", "--command",
                                       f"{sys.executable} {impl} {{data}} {{model}} {{task}} {{out}}"], {0}, env=env)
produce("oracle/identify", "oracle", ["oracle", "--quiet", "--cases-dir", os.path.join(cases, "identify"), "--work",
                                      "oracle-identify", "--command",
                                      f"{sys.executable} {toy} correct {lpvid} {{data}} {{model}} {{task}} {{out}}"],
        {0}, env=env)
produce("oracle/error", "oracle", ["oracle", "--quiet", "--cases", "1", "--seed", "2", "--min-n", "10", "--max-n", "15",
                                   "--work", "oracle-error", "--command", "false"], {3})

# jobs: two windows and the joint claim; window 0 and the joint job run, window 1 does not.
code, out = run([lpvid, "jobs", "plan", "--data", "long.csv", "--model", "long.json", "--dir", "jobs",
                 "--window-length", "40", "--min-last", "10", "--dmax", "1", "--joint"])
if check(code == 0, f"jobs plan: exit {code}"):
    with open(os.path.join(work, "jobs", "jobs.txt"), encoding="utf-8") as f:
        lines = f.read().splitlines()
    for line in (lines[0], lines[-1]):
        code, out = run(["sh", "-c", line])
        check(code == 0, f"job {line[:60]}...: exit {code}")
    produce("jobs merge/missing-joint", "jobs merge", ["jobs", "merge", "--dir", "jobs", "--quiet"], {4})
    for name in ("w00000.report.json", "joint.report.json"):
        reports.append((f"invalidate/jobs-{name}", "invalidate", os.path.join(work, "jobs", name)))
    # window 0's certificate in place of window 1's: merge refuses it (other rows)
    shutil.copy(os.path.join(work, "jobs", "w00000.cert.json"), os.path.join(work, "jobs", "w00001.cert.json"))
    produce("jobs merge/refused", "jobs merge", ["jobs", "merge", "--dir", "jobs", "--quiet"], {4})


# ---------------------------------------------------------------- validation
def leaf_errors(error):
    """The innermost errors of a failed oneOf/anyOf/if, deepest first."""
    if not error.context:
        return [error]
    found = [e for sub in error.context for e in leaf_errors(sub)]
    return sorted(found, key=lambda e: -len(e.absolute_path))


def error_lines(validator, doc, limit=6):
    lines = []
    for e in validator.iter_errors(doc):
        for leaf in leaf_errors(e)[:2]:
            lines.append(f"{leaf.json_path}: {leaf.message[:200]}")
    return lines[:limit]


docs = {}
for label, command, path in reports:
    try:
        doc = load(path)
    except (OSError, ValueError) as e:
        check(False, f"{label}: {path} is readable JSON ({e})")
        continue
    errors = error_lines(validators[command], doc)
    if check(not errors, f"{label}: {os.path.relpath(path, work)} valid against docs/{SCHEMA_FILES[command]}"):
        docs[label] = (command, doc)
    else:
        for line in errors:
            print("          " + line)

# What the schemas cannot say about two keys at once.
for label, (command, doc) in docs.items():
    if command == "invalidate" and "verdict" in doc:
        check(doc["verdict"] == doc["status"], f"{label}: verdict is status ({doc['verdict']}, {doc['status']})")
check(docs.get("invalidate/both-invalidated", ("", {}))[1].get("verdict") == "invalidated",
      "the invalidated variant carries the verdict 'invalidated'")
check("message" in docs.get("identify/no-solution", ("", {}))[1], "the identify variant without a solution has 'message'")
check(docs.get("select-basis/found", ("", {}))[1].get("final_basis") is not None and
      docs.get("select-basis/not-decided", ("", {}))[1].get("final_basis", 0) is None,
      "select-basis: one variant found a basis, one did not")


# ---------------------------------------------------------------- broken copies
def always_written(command, doc):
    """Top-level keys the writer writes in every report of this shape (from the C++ writers)."""
    bounds = ["status", "delta", "dmax", "noise_normalisation", "toeplitz_mode", "solver", "certificate", "verified",
              "certification"]
    if command == "invalidate":
        return bounds + ["relaxation", "model_as_written", "iterations", "samples"]
    if command == "certify":
        return bounds + ["relaxation", "program", "solution", "samples"]
    if command == "identify":
        if "message" in doc:
            return ["status", "verified", "delta", "dmax", "message"]
        return bounds + ["method", "relaxation", "iterations", "pinned_samples", "iterates", "theta", "samples"]
    if command == "select-basis":
        found = ["certification", "delta2_exact", "dmax2_exact", "final_step"] if doc.get("final_basis") else []
        return bounds[:-1] + found + ["relaxation", "command", "iterations", "delta_given", "dmax_given", "iterate",
                                      "max_degree", "order", "steps", "final_basis", "theta", "samples"]
    if command == "tradeoff":
        return ["command", "status", "verified", "noise_normalisation", "toeplitz_mode", "solver", "relaxation",
                "iterations", "points", "monotone", "csv", "plots", "samples"]
    if command == "fit-linear":
        return ["command", "order", "offset", "rms_estimation", "rms_arx", "spectral_radius", "iterations"]
    if command == "compare":
        if "models" in doc:
            return ["data", "warmup_rows", "prediction", "predict_steps", "models"]
        if "records" in doc:
            return ["data", "model", "samples", "rms", "fit_percent", "finite", "records", "prediction",
                    "predict_steps", "columns"]
        return ["data", "model", "rows", "warmup_rows", "x0", "x0_values", "outputs", "rms", "fit_percent", "finite",
                "prediction", "predict_steps", "columns"]
    if command == "diagnose":
        return ["status", "command", "estimation", "validation" if "validation" in doc else "selection", "test",
                "tests", "effects", "before", "after", "noise_normalisation", "toeplitz_mode", "solver", "blas",
                "relaxation", "verified", "rounds", "residual_analysis_validation", "plots"]
    if command == "oracle":
        return ["format", "command", "seconds", "strict", "totals", "cases"]
    return ["format", "data", "model", "objective", "counts", "windows"]  # jobs merge


def nodes(x, path=()):
    """(path, value) of every value, parents first; a path is a tuple of keys and indices."""
    yield path, x
    if isinstance(x, dict):
        for k, v in x.items():
            yield from nodes(v, path + (k,))
    elif isinstance(x, list):
        for i, v in enumerate(x):
            yield from nodes(v, path + (i,))


def json_path(path):
    return "$" + "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in path)


def pattern(path):
    """The path with every index a wildcard: one broken copy per distinct field."""
    return tuple("*" if isinstance(p, int) else p for p in path)


def in_open_section(path):
    return any(p in OPEN_SECTIONS for p in path if isinstance(p, str))


def open_map(path):
    return bool(path) and path[-1] in OPEN_MAPS


def at(doc, path):
    for p in path:
        doc = doc[p]
    return doc


def broken_copies(command, doc):
    """(what, broken document) for every mutation the schema must refuse."""
    for key in always_written(command, doc):
        if key not in doc:
            check(False, f"{command}: '{key}' is missing, but the writer always writes it")
            continue
        broken = copy.deepcopy(doc)
        del broken[key]
        yield f"{json_path((key,))} deleted", broken
    seen = set()
    for path, value in nodes(doc):
        if in_open_section(path):
            continue
        if isinstance(value, dict) and value and not open_map(path) and path:
            if ("first", pattern(path)) not in seen:  # the first key of every writer object is unconditional
                seen.add(("first", pattern(path)))
                broken = copy.deepcopy(doc)
                first = next(iter(value))
                del at(broken, path)[first]
                yield f"{json_path(path + (first,))} deleted", broken
        if isinstance(value, dict) and not open_map(path):
            for key in value:
                if ("rename", pattern(path + (key,))) in seen:
                    continue
                seen.add(("rename", pattern(path + (key,))))
                broken = copy.deepcopy(doc)
                parent = at(broken, path)
                parent[key + "_renamed"] = parent.pop(key)
                yield f"{json_path(path + (key,))} renamed to {key}_renamed", broken
        if isinstance(value, (int, float)) and not isinstance(value, bool) and path:
            if ("string", pattern(path)) in seen:
                continue
            seen.add(("string", pattern(path)))
            broken = copy.deepcopy(doc)
            at(broken, path[:-1])[path[-1]] = str(value)
            yield f"{json_path(path)} = {value} turned into the string \"{value}\"", broken


total = 0
for label, (command, doc) in docs.items():
    validator = validators[command]
    refused, accepted = 0, []
    for what, broken in broken_copies(command, doc):
        if validator.is_valid(broken):
            accepted.append(what)
        else:
            refused += 1
    total += refused + len(accepted)
    check(not accepted and refused > 0, f"{label}: {refused} broken copies refused"
          + (f"; ACCEPTED: {'; '.join(accepted[:8])}" if accepted else ""))

print(f"\n{len(docs)} reports valid, {total} broken copies tried, {time.time() - started:.1f} s")
print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
