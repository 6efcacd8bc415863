#!/usr/bin/env python3
"""docs/model.schema.json against real model files, and against the reader.

Validates every lpvid-model/1 file under fixtures/ and the models the built
`lpvid` writes (generate example1/example2, generate effect-case for every
effect `lpvid generate --help` lists, fit-linear --model-out, identify
--model-out). Then makes broken copies (a required key removed, another
format version, an unknown key, a string where a list belongs, ...) and
checks that the schema refuses each AND that `lpvid invalidate` refuses it
too with exit code 2 and a message naming the model file: schema and reader
must agree. Finally some odd but legal spellings (numbers as " 0.1 ", ".5",
"1/ 3"; an integer as the string "2"; a state column with a shift) must
pass both. Also checks that the schema's version is the reader's.

usage: model_schema_test.py LPVID SOURCE_DIR WORK_DIR
"""
import copy
import glob
import json
import os
import re
import subprocess
import sys

import jsonschema

lpvid, source, work = sys.argv[1:4]
work = os.path.abspath(work)
os.makedirs(work, exist_ok=True)
failures = []
counts = {"validated": 0, "refused_by_both": 0, "accepted_by_both": 0}


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)
    return ok


with open(os.path.join(source, "docs", "model.schema.json"), encoding="utf-8") as f:
    schema = json.load(f)
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
with open(os.path.join(source, "src", "model", "model_file.h"), encoding="utf-8") as f:
    version = re.search(r'kModelFormat = "([^"]+)"', f.read()).group(1)
check(schema["properties"]["format"]["const"] == version and schema["$id"].endswith(version),
      f"schema format const and $id name {version}, the version the reader accepts")


def errors(doc):
    return [e.message for e in validator.iter_errors(doc)]


def load(path):
    # The reader refuses NaN/Infinity; so must the test's JSON parser.
    def bad_constant(name):
        raise ValueError(f"{name} is not JSON")
    with open(path, encoding="utf-8") as f:
        return json.load(f, parse_constant=bad_constant)


def run(args):
    r = subprocess.run([lpvid, *args], cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    return r.returncode, r.stdout


def out(name):
    return os.path.join(work, name)


# ---------------------------------------------------------------- models to validate
models = []  # (label, model path, data path or None)

for path in sorted(glob.glob(os.path.join(source, "fixtures", "**", "*.json"), recursive=True)):
    try:
        doc = load(path)
    except ValueError:
        continue
    if isinstance(doc, dict) and str(doc.get("format", "")).startswith("lpvid-model/"):
        models.append((os.path.relpath(path, source), path, None))
check(len(models) >= 4, f"{len(models)} model files found under fixtures/")

# data that matches each fixture model (by its columns), for the reader checks
lti_data = out("lti_siso.csv")
with open(lti_data, "w", encoding="utf-8") as f:
    f.write("u,y\n")
    for k in range(24):
        f.write(f"{(-1) ** (k // 3)},{0.1 * ((k * 7) % 5) - 0.2:.2f}\n")
fixture_data = {
    "example1": os.path.join(source, "fixtures", "example1", "noise_free_n40.csv"),
    "example2": os.path.join(source, "fixtures", "example2", "data.csv"),
    "example1_initial": os.path.join(source, "fixtures", "example1", "noise_free_n40.csv"),
    "lti_siso": lti_data,
}
models = [(label, path, next((d for k, d in fixture_data.items() if k in label), None)) for label, path, _ in models]


def generated(label, args, written):
    rc, text = run(args)
    if not check(rc == 0 and all(os.path.exists(p) for p, _ in written), f"lpvid {' '.join(args[:2])}: wrote {label}"):
        print(text)
        return
    for path, data in written:
        models.append((f"{label} {os.path.basename(path)}", path, data))


for which in ("example1", "example2"):
    generated(which, ["generate", which, "--n", "40", "--out", out(f"{which}.csv"), "--model-out",
                      out(f"{which}.model.json"), "--truth-out", out(f"{which}.truth.json")],
              [(out(f"{which}.model.json"), out(f"{which}.csv")), (out(f"{which}.truth.json"), out(f"{which}.csv"))])

rc, text = run(["generate", "--help"])
listed = re.search(r"--effect TEXT[^(]*\(([^)]*)\)", text)
effects = [e.strip() for e in listed.group(1).split(",")] if listed else []
check(len(effects) >= 5, f"effects listed by 'lpvid generate --help': {', '.join(effects)}")
for effect in effects:
    generated(f"effect-case {effect}",
              ["generate", "effect-case", "--effect", effect, "--out", out(f"{effect}.csv"), "--validation-out",
               out(f"{effect}.val.csv"), "--model-out", out(f"{effect}.model.json"), "--truth-out",
               out(f"{effect}.truth.json")],
              [(out(f"{effect}.model.json"), out(f"{effect}.csv")), (out(f"{effect}.truth.json"), out(f"{effect}.csv"))])

ex2_data = os.path.join(source, "fixtures", "example2", "data.csv")
generated("fit-linear", ["fit-linear", "--data", ex2_data, "--u", "u1", "--y", "y1", "--order", "2", "--model-out",
                         out("fit_linear.json")], [(out("fit_linear.json"), ex2_data)])
generated("fit-linear --offset", ["fit-linear", "--data", ex2_data, "--u", "u1", "--y", "y1", "--order", "2",
                                  "--offset", "--model-out", out("fit_linear_offset.json")],
          [(out("fit_linear_offset.json"), ex2_data)])
ex1_data = fixture_data["example1"]
generated("identify example1", ["identify", "--quiet", "--data", ex1_data, "--model",
                                os.path.join(source, "fixtures", "models", "example1_initial.json"), "--certificate",
                                out("identify1.cert.json"), "--model-out", out("identified1.json")],
          [(out("identified1.json"), ex1_data)])
generated("identify example2 (offset)", ["identify", "--quiet", "--data", ex2_data, "--model",
                                         os.path.join(source, "fixtures", "example2", "initial_model.json"),
                                         "--certificate", out("identify2.cert.json"), "--model-out",
                                         out("identified2.json")], [(out("identified2.json"), ex2_data)])

seen_keys = set()
for label, path, _ in models:
    try:
        doc = load(path)
    except ValueError as e:
        check(False, f"{label}: plain JSON ({e})")
        continue
    seen_keys.update(doc)
    e = errors(doc)
    if check(not e, f"{label} is valid" + "".join("\n  " + m for m in e)):
        counts["validated"] += 1
for key in ("correction", "offset", "static", "x0", "description"):
    check(key in seen_keys, f"some validated model has '{key}'")


# ---------------------------------------------------------------- schema and reader agree
def reader(doc, name, data):
    """lpvid's verdict on doc: (exit code, output)."""
    path = out(name + ".json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=1)
    rc, text = run(["invalidate", "--quiet", "--data", data, "--model", path, "--delta", "0.1", "--dmax", "1",
                    "--certificate", out(name + ".cert.json")])
    return rc, text, path


def refused(base, what, mutate):
    label, path, data = base
    doc = load(path)
    mutate(doc)
    name = "broken_" + re.sub(r"[^A-Za-z0-9]+", "_", f"{os.path.basename(path)}_{what}")
    schema_no = bool(errors(doc))
    rc, text, written = reader(doc, name, data)
    reader_no = rc == 2 and os.path.basename(written) in text
    said = [line for line in text.splitlines() if os.path.basename(written) + ":" in line]
    ok = check(schema_no and reader_no, f"{label} with {what}: refused by the schema ({schema_no}) and by lpvid "
                                        f"(exit {rc}, naming the model: {os.path.basename(written) in text})"
               + (f"\n        lpvid: {said[-1].split(': ', 1)[-1]}" if said else ""))
    if not ok:
        print("  " + text.strip().replace("\n", "\n  "))
    counts["refused_by_both"] += ok


def accepted(base, what, mutate):
    label, path, data = base
    doc = load(path)
    mutate(doc)
    name = "odd_" + re.sub(r"[^A-Za-z0-9]+", "_", f"{os.path.basename(path)}_{what}")
    e = errors(doc)
    rc, text, _ = reader(doc, name, data)
    ok = check(not e and rc in (0, 1), f"{label} with {what}: accepted by the schema and by lpvid (exit {rc})"
               + "".join("\n  " + m for m in e))
    if not ok:
        print("  " + text.strip().replace("\n", "\n  "))
    counts["accepted_by_both"] += ok


def by_label(part):
    return next(m for m in models if part in m[0])


lti = by_label("lti_siso")
ex1 = by_label("example1_initial")
ex2 = by_label("example2/initial_model")
sat = by_label("input_saturation.truth.json")
for base in (lti, ex1, ex2, sat):
    # the reader's first checks: these apply to every model
    refused(base, "no 'format'", lambda d: d.pop("format"))
    refused(base, "format lpvid-model/2", lambda d: d.update(format="lpvid-model/2"))
    refused(base, "no 'states'", lambda d: d.pop("states"))
    refused(base, "no 'columns'", lambda d: d.pop("columns"))
    refused(base, "no 'initial'", lambda d: d.pop("initial"))
    refused(base, "an unknown top-level key", lambda d: d.update(comment="x"))
    refused(base, "'inputs': 0", lambda d: d.update(inputs=0))
    refused(base, "'states': 2.5", lambda d: d.update(states=2.5))
    refused(base, "an A term's value as a string", lambda d: d["initial"]["A"][0].update(value="[[1]]"))
    refused(base, "a matrix row that is a number", lambda d: d["initial"]["A"][0].update(value=[1, 2]))
    refused(base, "a matrix entry 'abc'", lambda d: d["initial"]["A"][0]["value"][0].__setitem__(0, "abc"))
    refused(base, "a matrix entry '1/0'", lambda d: d["initial"]["A"][0]["value"][0].__setitem__(0, "1/0"))
    refused(base, "a matrix entry '1e5000'", lambda d: d["initial"]["A"][0]["value"][0].__setitem__(0, "1e5000"))
    refused(base, "an unknown key in a term", lambda d: d["initial"]["A"][0].update(scale=1))
    refused(base, "a term without 'value'", lambda d: d["initial"]["A"][0].pop("value"))
    refused(base, "'initial.E'", lambda d: d["initial"].update(E=[]))
    refused(base, "an unknown key in 'columns'", lambda d: d["columns"].update(w=["w"]))
    refused(base, "an empty column name", lambda d: d["columns"]["u"].__setitem__(0, ""))
    refused(base, "'columns.u' as a string", lambda d: d["columns"].update(u="u1"))
    refused(base, "basis '1*1'", lambda d: d["initial"]["A"][0].update(basis="1*1"))
    refused(base, "uncertainty 'general' with a weight",
            lambda d: d.update(uncertainty={"structure": "general", "nz": 1, "weight": 1}))
    refused(base, "uncertainty 'multiplicative' with nz",
            lambda d: d.update(uncertainty={"structure": "multiplicative", "nz": 1}))
    refused(base, "uncertainty 'general' without nz or terms", lambda d: d.update(uncertainty={"structure": "general"}))
    refused(base, "uncertainty structure 'relative'", lambda d: d.update(uncertainty={"structure": "relative"}))
    refused(base, "weight 0", lambda d: d.update(uncertainty={"weight": 0}))
    refused(base, "weight '-1/10'", lambda d: d.update(uncertainty={"weight": "-1/10"}))
    refused(base, "correction with 'C'", lambda d: d.update(correction={"basis": ["1"], "C": []}))
    refused(base, "correction without 'basis'", lambda d: d.update(correction={}))
    refused(base, "correction basis '1' twice", lambda d: d.update(correction={"basis": ["1", "1"]}))
    refused(base, "offset without 'basis'", lambda d: d.update(offset={"values": []}))
    refused(base, "state_offset without 'values'", lambda d: d.update(state_offset={"basis": ["1"]}))
    refused(base, "x0 as a number", lambda d: d.update(x0=0))
    refused(base, "a static map of kind 'clip'", lambda d: d.update(static={"input": {"kind": "clip"}}))
    refused(base, "a saturation without 'upper'",
            lambda d: d.update(static={"input": {"kind": "saturation", "lower": -1}}))
    refused(base, "an abs map with 'lower'", lambda d: d.update(static={"output": {"kind": "abs", "lower": 0}}))
    refused(base, "a polynomial without coefficients",
            lambda d: d.update(static={"output": {"kind": "polynomial", "coefficients": []}}))
    refused(base, "a piecewise_linear map with one knot",
            lambda d: d.update(static={"output": {"kind": "piecewise_linear", "knots": [0], "values": [0]}}))
    refused(base, "'static.input_delay': -1", lambda d: d.update(static={"input_delay": -1}))
    refused(base, "an unknown key in 'static'", lambda d: d.update(static={"delay": 1}))
    refused(base, "scheduling as a string", lambda d: d.update(scheduling="rho1"))
    refused(base, "'description': 3", lambda d: d.update(description=3))
for base in (ex1, ex2, sat):  # models with scheduling variables
    refused(base, "scheduling name '1rho'", lambda d: d["scheduling"].__setitem__(0, "1rho"))
    refused(base, "scheduling names twice", lambda d: d["scheduling"].append(d["scheduling"][0]))
    refused(base, "basis 'rho1^0'", lambda d: d["initial"]["A"][0].update(basis="rho1^0"))
    refused(base, "basis 'rho1^17'", lambda d: d["initial"]["A"][0].update(basis="rho1^17"))
    refused(base, "basis 'rho1**2'", lambda d: d["initial"]["A"][0].update(basis="rho1**2"))
    refused(base, "rho column '@x0'", lambda d: d["columns"].update(rho=["@x0"] + d["columns"]["rho"][1:]))
    refused(base, "rho column '@abs(x1--0.5)'",
            lambda d: d["columns"].update(rho=["@abs(x1--0.5)"] + d["columns"]["rho"][1:]))
    refused(base, "rho column '@cube(x1)'", lambda d: d["columns"].update(rho=["@cube(x1)"] + d["columns"]["rho"][1:]))

# odd but legal: the schema must not refuse what the reader takes
for base in (lti, ex1):
    accepted(base, "numbers ' 0.1 ', '.5', '3.', '1/ 3', '+2', '-3/-4', 1e-3",
             lambda d: d["initial"]["A"].append({"basis": "1", "value": [[" 0.1 ", ".5"], ["1/ 3", "0"]]})
             or d["initial"]["A"].append({"basis": "1", "value": [["+2e-3", "-3/-400"], [1e-3, "3.e-2"]]}))
    accepted(base, "states as the string '2', inputs as 1.0 (an integral JSON number)",
             lambda d: d.update(states="2", inputs=float(d["inputs"])))
    accepted(base, "'initial': {} (all zero), additive, and a description",
             lambda d: d.update(initial={}, description="x", uncertainty={"structure": "additive"}))
    accepted(base, "uncertainty 'general' with nz from the first C1 term",
             lambda d: d.update(uncertainty={"structure": "general", "C1": [
                 {"basis": "1", "value": [[1] * d["states"]]}]}))
    accepted(base, "x0 and a state offset", lambda d: d.update(x0=["1/8"] * d["states"],
                                                               state_offset={"basis": ["1"], "values": [[0] * d["states"]]}))
    accepted(base, "static maps and a delay given as '1'",
             lambda d: d.update(static={"input_delay": "1", "input": {"kind": "dead_zone", "lower": "-0.1", "upper": 0.1},
                                        "output": {"kind": "piecewise_linear", "knots": [-1, 0, 1], "values": [1, 0, 1]}}))
accepted(ex1, "basis ' rho1 ^ 2 * rho2 ' and 'rho1*rho1' in a term",
         lambda d: d["initial"]["A"].extend([{"basis": " rho1 ^ 2 * rho2 ", "value": [[0, 0], [0, 0]]},
                                             {"basis": "rho1*rho1", "value": [[0, 0], [0, 0]]}]))
accepted(ex1, "rho column '@abs(x1-1/4)' (a state function)",
         lambda d: d["columns"].update(rho=["@abs(x1-1/4)", d["columns"]["rho"][1]]))

print(f"{counts['validated']} models validated; {counts['refused_by_both']} broken copies refused by both the schema "
      f"and lpvid; {counts['accepted_by_both']} odd but legal copies accepted by both")
print(f"{len(failures)} failed" if failures else "all model schema checks passed")
sys.exit(1 if failures else 0)
