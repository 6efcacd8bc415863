#!/usr/bin/env python3
"""Checks scripts/function_lengths.py on a crafted C++ file whose functions
have lengths known by construction: one-line functions (whose braces open and
close on the signature line), a multi-line function holding a lambda and
braces inside string and character literals and comments, a class with
one-line and multi-line methods, a declaration, and a function padded to a
chosen length. Exits 1 on the first wrong answer.

    python3 tests/scripts/function_lengths_test.py SCRIPT
"""
import importlib.util
import os
import subprocess
import sys
import tempfile

PADDED = 61  # the padded function is this many lines long, one above the limit below


def crafted():
    """The C++ text and the expected {signature start: (line, length)}."""
    parts = []
    expected = {}

    def add(text, name=None, length=None):
        if name is not None:
            expected[name] = (len(parts) + 1, length)
        parts.extend(text.split("\n"))

    add("#include <string>\n\nnamespace demo {\n")
    add("bool is_open(char c) { return c == '{' || c == '('; }", "bool is_open", 1)
    add("int twice(int x) { return 2 * x; }", "int twice", 1)
    add("int declared_only(int x);")
    add("")
    add("int with_lambda(int n) {\n"
        "  auto f = [&](int k) {\n"
        "    if (k > 0) { return k; }\n"
        "    return -k;\n"
        "  };\n"
        "  std::string s = \"}}} {\";  // a } in a comment\n"
        "  /* and { in a block\n"
        "     comment } */\n"
        "  char c = '}';\n"
        "  return f(n) + static_cast<int>(s.size()) + c;\n"
        "}", "int with_lambda", 11)
    add("")
    add("class Counter {\n public:")
    add("  explicit Counter(int start) : count_(start) {}", "explicit Counter", 1)
    add("  int next() { return ++count_; }", "int next", 1)
    add("  int add(int a,\n"
        "          int b) {\n"
        "    count_ += a;\n"
        "    count_ += b;\n"
        "    return count_;\n"
        "  }", "int add", 6)
    add("\n private:\n  int count_ = 0;\n};\n")
    add("int padded() {\n  int x = 0;\n" + "  x += 1;\n" * (PADDED - 4) + "  return x;\n}", "int padded", PADDED)
    add("")
    add("}  // namespace demo")
    return "\n".join(parts) + "\n", expected


def main(script):
    spec = importlib.util.spec_from_file_location("function_lengths", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    text, expected = crafted()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "crafted.cc")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        found = {}
        for first, length, signature in module.functions(path):
            name = next((n for n in expected if signature.startswith(n)), signature)
            found[name] = (first, length)
        if found != expected:
            print("function_lengths_test: expected (line, length)", sorted(expected.items()))
            print("function_lengths_test: found", sorted(found.items()))
            return 1
        run = subprocess.run([sys.executable, script, "--max", str(PADDED - 1), path], capture_output=True, text=True)
        wanted = f"{path}:{expected['int padded'][0]}: {PADDED} lines: int padded() {{"
        if run.returncode != 1 or wanted not in run.stdout or "1 function(s) above" not in run.stdout:
            print("function_lengths_test: --max", PADDED - 1, "should name only the padded function, exit 1:")
            print(run.returncode, run.stdout)
            return 1
        run = subprocess.run([sys.executable, script, "--max", str(PADDED), path], capture_output=True, text=True)
        if run.returncode != 0:
            print("function_lengths_test: --max", PADDED, "should find nothing:", run.stdout)
            return 1
    print("function_lengths_test: every length as constructed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
