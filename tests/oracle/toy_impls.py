#!/usr/bin/env python3
"""Outside implementations for the tests of `lpvid oracle`: one correct, the
others deliberately wrong. Each answers a task by asking lpvid itself (so the right
answer is known) and then, depending on MODE:

  correct        the certified bound, rounded up, with lpvid's Delta taps as
                 the witness (decide: lpvid's verdict; identify: lpvid
                 identify --iterate's theta and d_max)
  scaled         every claimed bound times 0.95 (too good by 5 %)
  inflated       every claimed bound times 10 (the objective 100 times too
                 large: suboptimal)
  flipped        decide: "consistent" where lpvid certified "invalidated"
  bad_witness    the correct bound, but the witness's first tap moved by
                 3*delta: then ||T_Delta|| >= 2*delta > the claimed delta
  zero_theta     identify: theta = 0 (no correction) with 0.95 times lpvid's
                 d_max: too good for every theta of an additive class (the
                 class certificate refutes it); outside the certified box of
                 a multiplicative one
  leading_zeros  min_dmax computed without the leading samples where every
                 input is 0 (z = 0 there, so w must be 0; an implementation
                 that forgets it lets w absorb the residual there), the RMS
                 still over all n samples: a bound that is too good

usage: toy_impls.py MODE LPVID DATA MODEL TASK OUT
"""
import csv
import json
import math
import os
import subprocess
import sys


def run_lpvid(lpvid, data, model, task, stem):
    bounds = {
        "min_dmax": ["--delta", task.get("delta")],
        "min_delta": ["--dmax", task.get("dmax")],
        "weighted": ["--lambda", task.get("lambda")],
        "decide": ["--delta", task.get("delta"), "--dmax", task.get("dmax")],
        "identify": ["--delta", task.get("delta"), "--iterate"],
    }[task["kind"]]
    command = "identify" if task["kind"] == "identify" else "invalidate"
    cmd = [lpvid, command, "--quiet", "--data", data, "--model", model, "--report", stem + ".report.json",
           "--certificate", stem + ".cert.json"] + bounds
    code = subprocess.run(cmd, stdout=subprocess.DEVNULL).returncode
    with open(stem + ".report.json") as f:
        report = json.load(f)
    certificate = None
    if report.get("verified") and os.path.exists(stem + ".cert.json"):
        with open(stem + ".cert.json") as f:
            certificate = json.load(f)
    return code, report, certificate


def answer_from(task, code, report, certificate):
    a = {"format": "lpvid-oracle-answer/1"}
    if task["kind"] == "decide":
        a["verdict"] = "invalidated" if code == 1 else "consistent"
    elif task["kind"] == "identify":
        if report.get("dmax") is None:
            return {"format": "lpvid-oracle-answer/1", "status": "failed", "message": "lpvid did not verify"}
        a["dmax"] = report["dmax"]
        # the report gives the certified theta (rounded to 12 digits) as doubles: back to its exact decimals
        a["theta"] = {f: {k: [[format(x, ".12g") for x in row] for row in m] for k, m in t.items()}
                      for f, t in report["theta"].items()}
    else:
        if report.get("delta") is None:
            return {"format": "lpvid-oracle-answer/1", "status": "failed", "message": "lpvid did not verify"}
        a["delta"] = report["delta"]
        a["dmax"] = report["dmax"]
    if certificate is not None and certificate.get("form") == "delta" and a.get("verdict") != "invalidated":
        a["witness"] = {"delta_taps": certificate["delta_taps"], "delta_horizon": certificate["delta_horizon"]}
    return a


def leading_zero_rows(data, model):
    with open(model) as f:
        inputs = json.load(f)["columns"]["u"]
    with open(data, newline="") as f:
        rows = list(csv.DictReader(f))
    m = 0
    while m < len(rows) and all(float(rows[m][u]) == 0.0 for u in inputs):
        m += 1
    return rows, m


def main():
    mode, lpvid, data, model, task_path, out = sys.argv[1:7]
    with open(task_path) as f:
        task = json.load(f)
    stem = out + ".lpvid"
    if mode == "leading_zeros" and task["kind"] == "min_dmax":
        rows, m = leading_zero_rows(data, model)
        if 0 < m < len(rows):
            short = out + ".short.csv"
            with open(short, "w", newline="") as f:
                w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
                w.writeheader()
                w.writerows(rows[m:])
            code, report, _ = run_lpvid(lpvid, short, model, task, stem)
            n = len(rows)
            dmax = report["dmax"] * math.sqrt((n - m) / n)
            answer = {"format": "lpvid-oracle-answer/1", "dmax": dmax}
            with open(out, "w") as f:
                json.dump(answer, f)
            return
    code, report, certificate = run_lpvid(lpvid, data, model, task, stem)
    a = answer_from(task, code, report, certificate)
    if mode in ("scaled", "inflated"):
        a.pop("witness", None)
        for key in ("delta", "dmax"):
            if key in a:
                a[key] = a[key] * (0.95 if mode == "scaled" else 10)
    elif mode == "zero_theta" and "theta" in a:
        a.pop("witness", None)
        a["dmax"] = a["dmax"] * 0.95
        a["theta"] = {f: {k: [["0" for _ in row] for row in m] for k, m in t.items()} for f, t in a["theta"].items()}
    elif mode == "flipped" and task["kind"] == "decide" and code == 1:
        a["verdict"] = "consistent"
    elif mode == "bad_witness" and "witness" in a:
        delta = math.sqrt(float(eval_fraction(certificate["delta2"])))
        taps = a["witness"]["delta_taps"]
        bump = 3 * delta if delta > 0 else 1.0
        taps[0][0] = float(eval_fraction(taps[0][0])) + bump
    with open(out, "w") as f:
        json.dump(a, f)


def eval_fraction(text):
    """An exact number of a certificate (JSON number, decimal or p/q text) as a float."""
    if isinstance(text, (int, float)):
        return text
    if "/" in text:
        p, q = text.split("/")
        return float(p) / float(q)
    return float(text)


if __name__ == "__main__":
    main()
