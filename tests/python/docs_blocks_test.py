"""Every ```python block of a Markdown page runs as written, in order.

    PYTHONPATH=build/python python3 tests/python/docs_blocks_test.py docs/python.md <scratch dir>

Extracts the page's ```python blocks and runs them in one fresh Python
process, in the page's order and in one namespace (a later block may use the
names an earlier one defined), with the scratch folder as the working folder
(files a block writes land there) and matplotlib's Agg backend. Fails naming
the line of the page where the failing block starts, with its traceback (its
line numbers are the page's), when a block raises or the run takes longer
than the time limit.

A block whose following text (up to the next block) says "prints `X`" (or
"prints `X` and `Y`") must print each X: its standard output, with runs of
white space made one space, contains X made the same way. So the numbers the
page quotes are the numbers the code prints.

Exits 0 when every block ran and printed what the page says; 1 otherwise.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import time

TIME_LIMIT = 240  # seconds for all blocks together

# The runner: executes the blocks of a JSON list in one namespace, each compiled with the page's line
# numbers, its standard output copied to the terminal and kept; writes what happened as JSON.
RUNNER = r'''
import contextlib, io, json, sys, traceback
import matplotlib
matplotlib.use("Agg")
page, blocks_path, results_path = sys.argv[1:4]
with open(blocks_path, encoding="utf-8") as f:
    blocks = json.load(f)
namespace = {"__name__": "__main__"}
results = []


class Tee(io.TextIOBase):
    def __init__(self, out):
        self.out, self.kept = out, []

    def write(self, text):
        self.out.write(text)
        self.kept.append(text)
        return len(text)

    def flush(self):
        self.out.flush()


def save():
    with open(results_path, "w", encoding="utf-8") as f:
        json.dump(results, f)


for block in blocks:
    print(f"--- {page}:{block['line']}", file=sys.stderr, flush=True)
    tee = Tee(sys.stdout)
    result = {"line": block["line"], "ok": False, "stdout": "", "error": ""}
    results.append(result)
    save()  # a run that dies or hangs leaves the block it was in
    try:
        code = compile("\n" * block["first"] + block["source"], page, "exec")
        with contextlib.redirect_stdout(tee):
            exec(code, namespace)
        result["ok"] = True
    except BaseException:
        result["error"] = traceback.format_exc()
    result["stdout"] = "".join(tee.kept)
    save()
    if not result["ok"]:
        break
'''


def blocks_of(text):
    """[(line of the opening fence, line of the first code line - 1, source, text after the block up to
    the next fence)] of every ```python block; lines counted from 1."""
    lines = text.split("\n")
    blocks, k = [], 0
    while k < len(lines):
        if lines[k].strip() == "```python":
            start = k
            k += 1
            body = []
            while k < len(lines) and lines[k].strip() != "```":
                body.append(lines[k])
                k += 1
            if k == len(lines):
                sys.exit(f"FAILED: the ```python block at line {start + 1} is not closed")
            after = []
            k += 1
            while k < len(lines) and not lines[k].lstrip().startswith("```"):
                after.append(lines[k])
                k += 1
            blocks.append((start + 1, start + 1, "\n".join(body) + "\n", "\n".join(after)))
            continue
        if lines[k].lstrip().startswith("```"):  # another language's block: skip to its end
            k += 1
            while k < len(lines) and not lines[k].lstrip().startswith("```"):
                k += 1
        k += 1
    return blocks


def one_space(text):
    return " ".join(text.split())


def printed_claims(after):
    """The X of "prints `X`", "prints `X` and `Y`", "prints `X`, `Y` and `Z`" in the text."""
    claims = []
    for m in re.finditer(r"\bprints\s+((?:`[^`]+`(?:\s*(?:,|and|,\s*and)\s*)?)+)", after):
        claims += re.findall(r"`([^`]+)`", m.group(1))
    return claims


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    page, scratch = os.path.abspath(argv[1]), os.path.abspath(argv[2])
    with open(page, encoding="utf-8") as f:
        blocks = blocks_of(f.read())
    if not blocks:
        sys.exit(f"FAILED: {page} has no ```python block")
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    blocks_path, results_path = os.path.join(scratch, "blocks.json"), os.path.join(scratch, "results.json")
    with open(blocks_path, "w", encoding="utf-8") as f:
        json.dump([{"line": line, "first": first, "source": source} for line, first, source, _ in blocks], f)
    env = dict(os.environ, MPLBACKEND="Agg")
    started = time.monotonic()
    try:
        run = subprocess.run([sys.executable, "-c", RUNNER, page, blocks_path, results_path], cwd=scratch, env=env,
                             timeout=TIME_LIMIT)
        code = run.returncode
    except subprocess.TimeoutExpired:
        code = None
    seconds = time.monotonic() - started
    try:
        with open(results_path, encoding="utf-8") as f:
            results = json.load(f)
    except (OSError, ValueError):
        results = []
    name = argv[1]
    if code is None:
        last = results[-1]["line"] if results else blocks[0][0]
        sys.exit(f"FAILED: {name}: the blocks took longer than {TIME_LIMIT} s; the one at line {last} was running")
    failed = next((r for r in results if not r["ok"]), None)
    if failed:
        sys.exit(f"FAILED: {name}: the ```python block at line {failed['line']} raised:\n{failed['error']}")
    if code != 0 or len(results) != len(blocks):
        sys.exit(f"FAILED: {name}: the run ended with exit code {code} after {len(results)} of {len(blocks)} blocks")
    claims = 0
    for (line, _, _, after), result in zip(blocks, results):
        printed = one_space(result["stdout"])
        for claim in printed_claims(after):
            claims += 1
            if one_space(claim) not in printed:
                sys.exit(f"FAILED: {name}: the text after the block at line {line} says it prints\n  {claim}\n"
                         f"but it printed\n  {result['stdout'].strip()}")
    print(f"docs_blocks_test: {len(blocks)} blocks of {name} ran in order in {seconds:.0f} s; "
          f"{claims} printed values as the text says")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
