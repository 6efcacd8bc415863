#!/usr/bin/env python3
"""Lists the functions longer than a limit in the given folders or files (C++
sources in this repository's style: a function's signature starts at column
0, or at column 2 inside a class, and its body ends with a `}` at the same
column). Exits 1 when one is found, 2 when a path does not exist. Run by
ctest (CertifyPathFunctionLengths) on the certification path (src/certify,
src/lmi, src/identify), the verifier (verify/) and src/diagnose.

    python3 scripts/function_lengths.py [--max 60] FOLDER_OR_FILE...
"""
import os
import re
import sys

SKIP = re.compile(r"^\s*(//|#|namespace\b|}|struct\b|class\b|enum\b|using\b|template\b|extern\b|public:|private:|protected:|case\b|default:|return\b|if\b|for\b|while\b|switch\b|else\b|do\b|static_assert\b)")


def functions(path):
    """(first line, length, signature) of each function body in the file."""
    lines = open(path, encoding="utf-8").read().split("\n")
    out = []
    i = 0
    while i < len(lines):
        line = lines[i]
        indent = len(line) - len(line.lstrip(" "))
        if line.strip() and indent in (0, 2) and not SKIP.match(line) and "(" in line and not line.rstrip().endswith(";"):
            # the signature runs to the line that ends with `{` (a body) or `;` (a declaration)
            j = i
            while j < len(lines) and not lines[j].rstrip().endswith(("{", ";")) and j - i < 8:
                j += 1
            if j < len(lines) and lines[j].rstrip().endswith("{") and "=" not in lines[i].split("(")[0]:
                close = " " * indent + "}"
                k = j + 1
                while k < len(lines) and not (lines[k] == close or lines[k].startswith(close + " ") or lines[k].startswith(close + ";")):
                    k += 1
                out.append((i + 1, k - i + 1, line.strip()))
                i = k + 1
                continue
        i += 1
    return out


def main(argv):
    limit = 60
    if len(argv) >= 2 and argv[0] == "--max":
        limit = int(argv[1])
        argv = argv[2:]
    found = 0
    for given in argv:
        if os.path.isfile(given):
            paths = [given]
        elif os.path.isdir(given):
            paths = [os.path.join(root, name) for root, _, files in os.walk(given) for name in sorted(files)]
        else:
            print(f"function_lengths: {given}: no such file or folder")
            return 2
        for path in paths:
            if not path.endswith((".cc", ".h")):
                continue
            for first, length, signature in functions(path):
                if length > limit:
                    found += 1
                    print(f"{path}:{first}: {length} lines: {signature[:90]}")
    print(f"function_lengths: {found} function(s) above {limit} lines in {', '.join(argv)}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
