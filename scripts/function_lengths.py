#!/usr/bin/env python3
"""Lists the functions longer than a limit in the given folders or files (C++
sources in this repository's style: a function's signature starts at column
0, or at column 2 inside a class; its body is found by counting braces outside
comments and string and character literals, so a one-line function is one line
long and a lambda belongs to the function around it). Exits 1 when one is
found, 2 when a path does not exist. Run by ctest (FunctionLengths) on all of
src/ and verify/ (see tests/CMakeLists.txt).

    python3 scripts/function_lengths.py [--max 60] FOLDER_OR_FILE...
"""
import os
import re
import sys

SKIP = re.compile(r"^\s*(#|namespace\b|}|struct\b|class\b|enum\b|using\b|template\b|extern\b|public:|private:|protected:|case\b|default:|return\b|if\b|for\b|while\b|switch\b|else\b|do\b|static_assert\b)")
SIGNATURE_LINES = 12  # a signature longer than this is not looked for


def blank_literals(text):
    """The text with comments and the insides of string and character literals
    replaced by spaces (newlines kept), so that their braces are not counted."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            open_paren = text.find("(", i + 2)
            delimiter = ")" + text[i + 2:open_paren] + '"'
            j = text.find(delimiter, open_paren)
            j = n if j < 0 else j + len(delimiter)
            out.append('""' + re.sub(r"[^\n]", " ", text[i + 2:j]))
            i = j
        elif c in "\"'" and not (c == "'" and i > 0 and text[i - 1].isalnum() and i + 1 < n and text[i + 1].isalnum()):
            # a literal up to its unescaped closing quote (a ' between digits is a digit separator)
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(c + " " * (j - i - 2) + c)
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def body_span(lines, i):
    """(line of the body's `{`, line of its matching `}`) for a signature that
    starts on line i, or None when a `;` at bracket depth 0 comes first (a
    declaration) or no body opens within SIGNATURE_LINES lines."""
    parens = 0
    start = None
    depth = 0
    for k in range(i, len(lines)):
        if start is None and k - i >= SIGNATURE_LINES:
            return None
        for c in lines[k]:
            if start is None:
                if c in "([":
                    parens += 1
                elif c in ")]":
                    parens -= 1
                elif c == ";" and parens == 0:
                    return None
                elif c == "{" and parens == 0:
                    start, depth = k, 1
            elif c == "{":
                depth += 1
            elif c == "}":
                depth -= 1
                if depth == 0:
                    return start, k
    return None


def functions(path):
    """(first line, length, signature) of each function body in the file. A
    function's signature starts at column 0, or at column 2 inside a class;
    its length runs from the signature's first line to the line of the `}`
    that closes its body (a one-line function is 1 line long)."""
    original = open(path, encoding="utf-8").read().split("\n")
    lines = blank_literals("\n".join(original)).split("\n")
    out = []
    i = 0
    while i < len(lines):
        line = lines[i]
        indent = len(line) - len(line.lstrip(" "))
        if (line.strip() and indent in (0, 2) and not SKIP.match(line) and "(" in line
                and "=" not in line.split("(")[0]):
            span = body_span(lines, i)
            if span is not None:
                out.append((i + 1, span[1] - i + 1, original[i].strip()))
                i = span[1] + 1
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
