#!/usr/bin/env python3
"""The floors of the house: every folder of src/ (and verify/, python/) has a
level, and a file may include only headers of its own folder or of a lower
level. An include that runs up a floor, a folder without a level, or a circle
of folders (which a strict order excludes, and which is reported by itself
for clarity) makes this check fail with the file and line of each offending
include. Inside a folder the files must have an order too: a circle of files
(x.h with x.cc count as one file, a Python module's imports count, also those
inside a function) fails, named file by file. Run by ctest (IncludeLayers),
hence by CI.

    python3 scripts/check_layers.py [repository root]
"""
import os
import re
import sys

# Lowest first. What each floor is for, in one line:
LEVELS = [
    ("src/core", "numbers, text, files, limits, threads: no mathematics of the paper"),
    ("src/dense", "dense floating factorisations and inverses whose bits depend on neither threads nor vector width"),
    ("src/json", "exact JSON: the tree with number text and lines, exact numbers, members with located errors"),
    ("src/data", "CSV tables, column maps, experiments, signal descriptions"),
    ("src/model", "the LPV model, its file format and simulation"),
    ("src/toeplitz", "Toeplitz operators of the model along a trajectory (templated on the scalar)"),
    ("src/examples", "known systems: the paper's examples, plant analogues, effect cases"),
    ("verify/psd", "the exact verifier's PSD decisions: filter, witnesses, exact LDLT (never a solver)"),
    ("verify/certificate", "the exact verifier's certificate files and their checks (C1, C2, dual points)"),
    ("verify", "the lpvid-verify command line over the two rooms below it"),
    ("src/solvers", "SDP back ends (CSDP, SDPA, outside solvers)"),
    ("src/lmi", "the LMIs of Theorems 2.1 and 3.1 and their structured solvers"),
    ("src/certify", "Theorem 2.1 for a fixed model: certificates of the upper end, the lower end or invalidation"),
    ("src/jobs", "a long record as one job per window: the plan, each job's certificates judged against it, the merge's verdict"),
    ("src/identify", "identification (Theorem 3.1), fit -> fix -> certify, basis selection, trade-off curves"),
    ("src/fit", "least-squares and output-error fits of model parameters"),
    ("src/diagnose", "residual -> missing effect -> re-fitted model, certified"),
    ("src/oracle", "judging outside implementations' answers against lpvid's certified ones"),
    ("src/plot", "figures (gnuplot) of the results"),
    ("src/cli", "the command lines: options, reports, file names"),
    ("python", "the Python module over the command lines"),
]
LEVEL = {room: i for i, (room, _) in enumerate(LEVELS)}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
PY_IMPORT = re.compile(r'^\s*from\s+(\.+|lpvid\.?)([A-Za-z_][\w.]*)?\s+import\s+(.+)$')


def unit_of(path):
    """A file's unit: its path without the extension (x.h and x.cc are one)."""
    return os.path.splitext(path)[0]


def python_targets(root, path, line):
    """The repository paths of the package modules a Python import line names."""
    m = PY_IMPORT.match(line)
    if not m:
        return []
    base = os.path.dirname(path)
    module = (m.group(2) or "").replace(".", "/")
    names = [n.strip().split(" ")[0] for n in m.group(3).strip("()\\ ").split(",")]
    found = []
    for candidate in ([module] if module else []) + [os.path.join(module, n) for n in names if n]:
        f = os.path.join(base, candidate + ".py")
        if os.path.isfile(os.path.join(root, f)):
            found.append(os.path.normpath(f))
            break
    return found


def circles_of(edges):
    """Every circle a depth-first search of the graph `edges` meets."""
    state, stack, circles = {}, [], []

    def visit(v):
        state[v] = 1
        stack.append(v)
        for w in sorted(edges.get(v, ())):
            if state.get(w) == 1:
                circles.append(stack[stack.index(w):] + [w])
            elif w not in state:
                visit(w)
        stack.pop()
        state[v] = 2

    for v in sorted(edges):
        if v not in state:
            visit(v)
    return circles


def room_of(path):
    """The folder (room) of a repository-relative path, e.g. src/lmi."""
    parts = path.split("/")
    if parts[0] in ("src", "verify") and len(parts) > 2:
        return parts[0] + "/" + parts[1]
    return parts[0]


def resolve(root, inc):
    """The repository path an include names (src/ or top level), or None."""
    for candidate in ("src/" + inc, inc):
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    problems, edges, unit_edges = [], {}, {}
    files = 0
    for top in ("src", "verify", "python"):
        for dirpath, _, names in os.walk(os.path.join(root, top)):
            for name in sorted(names):
                path = os.path.relpath(os.path.join(dirpath, name), root)
                if name.endswith(".py"):
                    with open(os.path.join(root, path), encoding="utf-8") as f:
                        for line in f:
                            for target in python_targets(root, path, line):
                                if unit_of(target) != unit_of(path):
                                    unit_edges.setdefault(unit_of(path), set()).add(unit_of(target))
                    continue
                if not name.endswith((".h", ".cc")):
                    continue
                files += 1
                a = room_of(path)
                if a not in LEVEL:
                    problems.append(f"{path}: the folder {a} has no level in scripts/check_layers.py")
                    continue
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    for line_no, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = resolve(root, m.group(1))
                        if target is None:
                            continue
                        if unit_of(target) != unit_of(path):
                            unit_edges.setdefault(unit_of(path), set()).add(unit_of(target))
                        b = room_of(target)
                        if b == a:
                            continue
                        edges.setdefault(a, set()).add(b)
                        if b not in LEVEL:
                            problems.append(f"{path}:{line_no}: includes {m.group(1)} of {b}, a folder with no level")
                        elif LEVEL[b] > LEVEL[a]:
                            problems.append(f"{path}:{line_no}: includes {m.group(1)}: {a} (level {LEVEL[a]}) "
                                            f"may not include {b} (level {LEVEL[b]}, higher)")
    circles = circles_of(edges)
    problems += ["circle of folders: " + " -> ".join(c) for c in circles]
    problems += ["circle of files (each includes or imports the next): " + " -> ".join(c)
                 for c in circles_of(unit_edges)]
    if problems:
        print("\n".join(problems))
        print(f"check_layers: {len(problems)} problem(s) in {files} files")
        return 1
    print(f"check_layers: {files} files in {len(LEVELS)} levels, "
          f"{sum(len(v) for v in edges.values())} folder-to-folder include edges, all downward; "
          f"no circles of folders or of files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
