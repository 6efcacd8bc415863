#!/usr/bin/env python3
"""docs/certificate.schema.json against real certificates.

Writes certificates with the built `lpvid` on fixtures/example1 (a primal
"consistent" one in form delta, its dual "lower_bound" and "class_lower_bound" companions, form w of
--toeplitz paper, a dual "invalidated" one, the closed forms "zero_delta" and "nonnegative" of
delta = 0 and of a lower end 0) and validates each against the
schema; then checks that broken copies (a required field removed, another
format version, a key of the other form) FAIL. Also checks that the schema's
version is the one verify/certificate/certificate.h names (the reader in certificate_file.h accepts it), so neither can drift.

usage: certificate_schema_test.py LPVID SOURCE_DIR WORK_DIR
"""
import copy
import json
import os
import re
import subprocess
import sys

import jsonschema

lpvid, source, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
ex1 = os.path.join(source, "fixtures", "example1")
data = os.path.join(ex1, "noise_free_n40.csv")
failures = []


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)


with open(os.path.join(source, "docs", "certificate.schema.json"), encoding="utf-8") as f:
    schema = json.load(f)
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
with open(os.path.join(source, "verify", "certificate", "certificate.h"), encoding="utf-8") as f:
    version = re.search(r'kCertificateFormat = "([^"]+)"', f.read()).group(1)
check(schema["properties"]["format"]["const"] == version and schema["$id"].endswith(version),
      f"schema format const and $id name {version}, the version the reader accepts")


def lpvid_run(name, model, *options, exit_codes=(0,)):
    cert = os.path.join(work, name + ".cert.json")
    args = [lpvid, options[0], "--data", data, "--model", os.path.join(ex1, model), "--certificate", cert,
            "--report", os.path.join(work, name + ".report.json"), *options[1:]]
    r = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode not in exit_codes:
        print(r.stdout)
        check(False, f"{' '.join(args)}: exit {r.returncode}")
    return cert


def errors(doc):
    return [e.message for e in validator.iter_errors(doc)]


certificates = [
    lpvid_run("identify", "initial_model.json", "identify"),
    lpvid_run("paper", "true_model.json", "invalidate", "--toeplitz", "paper"),
    lpvid_run("invalidated", "initial_model.json", "invalidate", "--delta", "0.001", "--dmax", "0.001",
              exit_codes=(1,)),  # 1: invalidated, certified
    lpvid_run("invalidated_dense", "initial_model.json", "invalidate", "--delta", "0.001", "--dmax", "0.001",
              "--dense-dual", exit_codes=(1,)),
    # delta = 0 in closed form: Delta = 0 (no taps) and its zero_delta lower end; an invalidation;
    # the lower end 0 (form nonnegative) of min delta at a d_max the noise alone reaches
    lpvid_run("zero_delta", "initial_model.json", "invalidate", "--delta", "0"),
    lpvid_run("zero_delta_invalidated", "initial_model.json", "invalidate", "--delta", "0", "--dmax", "0.01",
              exit_codes=(1,)),
    lpvid_run("nonnegative", "initial_model.json", "invalidate", "--dmax", "10"),
]
for companion in ("identify.cert.lower.json", "identify.cert.class.json", "zero_delta.cert.lower.json",
                  "nonnegative.cert.lower.json"):
    if os.path.exists(os.path.join(work, companion)):
        certificates.append(os.path.join(work, companion))

seen = set()
for path in certificates:
    if not os.path.exists(path):
        check(False, f"{path} was written")
        continue
    with open(path, encoding="utf-8") as f:
        cert = json.load(f)
    seen.add((cert["claim"], cert["form"]))
    e = errors(cert)
    check(not e, f"{os.path.basename(path)} ({cert['claim']}, form {cert['form']}) is valid" + "".join("\n  " + m for m in e))

    def broken(what, mutate):
        doc = copy.deepcopy(cert)
        mutate(doc)
        check(bool(errors(doc)), f"{os.path.basename(path)} with {what} is rejected")

    broken("no 'format'", lambda d: d.pop("format"))
    broken("no 'data.sha256'", lambda d: d["data"].pop("sha256"))
    broken("no 'model.columns'", lambda d: d["model"].pop("columns"))
    broken("format lpvid-certificate/2", lambda d: d.update(format="lpvid-certificate/2"))
    broken("an unknown key", lambda d: d.update(comment="x"))
    broken("a number as text 'abc'", lambda d: d.update(delta2="abc") if "delta2" in d else d.update(lower_bound="abc"))
    required = {"delta": "delta_taps", "w": "w", "dual_delta": "dual", "dual_delta_path": "dual",
                "zero_delta": "delta2", "nonnegative": "lower_bound"}[cert["form"]]
    if cert["form"] in ("zero_delta", "nonnegative"):
        broken("a 'dual' beside a closed form", lambda d: d.update(dual={"horizon": 1, "sigma": 1, "g": [[0]]}))
        broken("claim 'consistent'", lambda d: d.update(claim="consistent"))
    if cert["form"] == "zero_delta" and cert["claim"] == "lower_bound":
        broken("objective 'min_delta' (with dmax2)", lambda d: d.update(objective="min_delta", dmax2=d.pop("delta2")))
    if cert["form"] == "nonnegative":
        def invalidation(d):
            d.update(claim="invalidated", objective="feasibility", delta2=0, dmax2=1)
            d.pop("lower_bound")
        broken("claim 'invalidated'", invalidation)
    if cert["claim"].startswith("class_"):
        required = "class"
        broken("a 'dual' beside 'class'", lambda d: d.update(dual=d["class"]["nodes"][-1]["leaf"]))
        broken("no 'class.nodes'", lambda d: d["class"].pop("nodes"))
        broken("a leaf without 'epsilon'", lambda d: d["class"]["nodes"][-1]["leaf"].pop("epsilon"))
    broken(f"no '{required}'", lambda d: d.pop(required))
    if cert["form"] == "dual_delta_path" and "dual" in cert:
        broken("no 'dual.u_floor'", lambda d: d["dual"].pop("u_floor"))
        broken("a 'dual.Y1' beside the recipe", lambda d: d["dual"].update(Y1=[[1]]))
    if cert["form"] == "dual_delta":
        broken("a 'dual.taps' beside Y1", lambda d: d["dual"].update(taps=[[0]]))

for kind in [("consistent", "delta"), ("consistent", "w"), ("lower_bound", "dual_delta_path"),
             ("invalidated", "dual_delta_path"), ("invalidated", "dual_delta"),
             ("class_lower_bound", "dual_delta_path"), ("lower_bound", "zero_delta"), ("invalidated", "zero_delta"),
             ("lower_bound", "nonnegative")]:
    check(kind in seen, f"a certificate with claim {kind[0]}, form {kind[1]} was validated")
print(f"{len(failures)} failed" if failures else "all schema checks passed")
sys.exit(1 if failures else 0)
