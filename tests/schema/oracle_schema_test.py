#!/usr/bin/env python3
"""docs/oracle_task.schema.json and docs/oracle_answer.schema.json against the
files lpvid writes and reads.

Writes random cases with `lpvid generate random` for every task kind (SISO and
MIMO, leading zeros, delays) and validates each task.json; answers every task
with examples/oracle/my_impl.py (docs/oracle.md's ten-line outside implementation)
and validates the answers; then makes broken copies (a required key removed,
an unknown key, another format version, a negative bound, a witness with
both forms) and checks that the schema refuses each AND that `lpvid oracle
--cases-dir` does not accept it either (an unreadable task stops the run with
exit 2; an unreadable answer is an "error" case, never judged). Also checks
that the schemas' versions are the readers'.

usage: oracle_schema_test.py LPVID SOURCE_DIR WORK_DIR
"""
import copy
import json
import os
import re
import shutil
import subprocess
import sys

import jsonschema

lpvid, source, work = sys.argv[1:4]
work = os.path.abspath(work)
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def check(ok, what):
    print(("ok:     " if ok else "FAILED: ") + what)
    if not ok:
        failures.append(what)
    return ok


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def dump(path, obj):
    with open(path, "w", encoding="utf-8") as f:
        json.dump(obj, f)


validators = {}
for name, header, constant in (("task", "task.h", "kOracleTaskFormat"), ("answer", "answer.h", "kOracleAnswerFormat")):
    schema = load(os.path.join(source, "docs", f"oracle_{name}.schema.json"))
    jsonschema.Draft202012Validator.check_schema(schema)
    validators[name] = jsonschema.Draft202012Validator(schema)
    with open(os.path.join(source, "src", "oracle", header), encoding="utf-8") as f:
        version = re.search(constant + r' = "([^"]+)"', f.read()).group(1)
    check(schema["properties"]["format"]["const"] == version and schema["$id"].endswith(version),
          f"{name} schema: format const and $id name {version}, the version the reader accepts")

env = dict(os.environ, LPVID=lpvid)
impl = os.path.join(source, "examples", "oracle", "my_impl.py")
cases = os.path.join(work, "cases")
variants = [["--siso"], [], ["--siso", "--leading-zeros", "4"], ["--max-delay", "2"], ["--lti"]]
seed = 1
for kind in ("min_dmax", "min_delta", "weighted", "decide", "identify"):
    for extra in variants[:3] if kind != "decide" else variants:
        folder = os.path.join(cases, f"{kind}-{seed}")
        r = subprocess.run([lpvid, "generate", "random", "--seed", str(seed), "--kinds", kind, "--min-n", "10",
                            "--max-n", "30", "--out", folder] + extra, capture_output=True, text=True)
        seed += 1
        if not check(r.returncode == 0, f"generate random {kind} {' '.join(extra)}: exit 0 ({r.stderr.strip()})"):
            continue
        task = load(os.path.join(folder, "task.json"))
        errors = [e.message for e in validators["task"].iter_errors(task)]
        check(not errors and task["kind"] == kind, f"{folder}/task.json valid, kind {kind} {errors}")
        out = os.path.join(folder, "answer.json")
        if kind == "identify":  # the ten-line example answers the fixed-model kinds; the toy answers identify
            toy = os.path.join(source, "tests", "oracle", "toy_impls.py")
            r = subprocess.run([sys.executable, toy, "correct", lpvid, os.path.join(folder, "data.csv"),
                                os.path.join(folder, "model.json"), os.path.join(folder, "task.json"), out],
                               capture_output=True, text=True)
            if check(r.returncode == 0 and os.path.exists(out), f"toy answers {folder} ({r.stderr.strip()[-300:]})"):
                errors = [e.message for e in validators["answer"].iter_errors(load(out))]
                check(not errors and "theta" in load(out), f"{folder}/answer.json valid, with theta {errors}")
            continue
        r = subprocess.run([sys.executable, impl, os.path.join(folder, "data.csv"), os.path.join(folder, "model.json"),
                            os.path.join(folder, "task.json"), out], env=env, capture_output=True, text=True)
        if check(r.returncode == 0 and os.path.exists(out), f"my_impl.py answers {folder} ({r.stderr.strip()[-300:]})"):
            errors = [e.message for e in validators["answer"].iter_errors(load(out))]
            check(not errors, f"{folder}/answer.json valid {errors}")

# The oracle over these cases with the same implementation: nothing refuted.
for folder in os.listdir(cases):
    if folder.startswith("identify"):
        shutil.rmtree(os.path.join(cases, folder))
cmd = f"{sys.executable} {impl} {{data}} {{model}} {{task}} {{out}}"
r = subprocess.run([lpvid, "oracle", "--quiet", "--cases-dir", cases, "--command", cmd, "--report",
                    os.path.join(work, "report.json")], env=env, capture_output=True, text=True)
check(r.returncode == 0, f"lpvid oracle --cases-dir over the generated cases: exit 0 ({r.stdout[-600:]} {r.stderr[-300:]})")

# Broken tasks: refused by the schema and by the oracle (exit 2, naming the file).
good = os.path.join(cases, "decide-13")
base_task = load(os.path.join(good, "task.json"))
broken_tasks = {
    "no kind": lambda t: t.pop("kind"),
    "unknown key": lambda t: t.update(speed="fast"),
    "format 2": lambda t: t.update(format="lpvid-oracle-task/2"),
    "negative delta": lambda t: t.update(delta="-0.1"),
    "lambda on decide": lambda t: t.update({"lambda": "0.5"}),
}
for what, breaking in broken_tasks.items():
    t = copy.deepcopy(base_task)
    breaking(t)
    check(not validators["task"].is_valid(t), f"task schema refuses: {what}")
    bad = os.path.join(work, "bad-task", "case")
    shutil.rmtree(os.path.dirname(bad), ignore_errors=True)
    shutil.copytree(good, bad)
    dump(os.path.join(bad, "task.json"), t)
    r = subprocess.run([lpvid, "oracle", "--quiet", "--cases-dir", os.path.dirname(bad), "--command", "true"],
                       capture_output=True, text=True)
    check(r.returncode == 2 and "task.json" in r.stderr, f"lpvid oracle refuses a task with {what} (exit {r.returncode}: {r.stderr.strip()})")

# Broken answers: refused by the schema; the oracle reports an error case.
base_answer = load(os.path.join(cases, "min_dmax-1", "answer.json"))
broken_answers = {
    "no format": lambda a: a.pop("format"),
    "unknown key": lambda a: a.update(confidence=1),
    "both witness forms": lambda a: a.update(witness={"w": [[0]], "delta_taps": [[0]], "delta_horizon": 1}),
    "verdict maybe": lambda a: a.update(verdict="maybe"),
}
for what, breaking in broken_answers.items():
    a = copy.deepcopy(base_answer)
    breaking(a)
    check(not validators["answer"].is_valid(a), f"answer schema refuses: {what}")
    folder = os.path.join(work, "bad-answer", "case")
    shutil.rmtree(os.path.dirname(folder), ignore_errors=True)
    shutil.copytree(os.path.join(cases, "min_dmax-1"), folder)
    dump(os.path.join(work, "answer.fixed.json"), a)
    report = os.path.join(work, "bad-answer.json")
    r = subprocess.run([lpvid, "oracle", "--quiet", "--cases-dir", os.path.dirname(folder), "--command",
                        "cp " + os.path.join(work, "answer.fixed.json") + " {out}", "--report", report],
                       capture_output=True, text=True)
    verdict = load(report)["cases"][0]["verdict"] if os.path.exists(report) else None
    check(r.returncode == 3 and verdict == "error", f"lpvid oracle calls an answer with {what} an error (exit {r.returncode}, {verdict})")

print(f"\n{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
