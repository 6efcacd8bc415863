#!/usr/bin/env python3
"""tests/ mirrors src/ folder by folder: the tests of the functions of
src/<room>/ are in tests/<room>/ (those of verify/ in tests/verify/), and a
test that runs the `lpvid` command line is in tests/cli/. Each tests/ folder
holding *_test.cc files is one test program (tests/CMakeLists.txt), so this
check fails, naming the folder, when
  - a tests/ folder holding *_test.cc is neither a room of src/, verify, nor
    one of the folders beside the rooms (NOT_ROOMS below);
  - a room of src/ (or verify/) has no tests/ folder holding *_test.cc;
  - a *_test.cc lies in tests/ itself, outside every folder (no program
    builds it).
Run by ctest (TestsMirror), hence by CI.

    python3 scripts/check_tests_mirror.py [repository root]
"""
import os
import sys

# The tests/ folders that are no room of src/, and what each holds.
NOT_ROOMS = {
    "support": "helpers shared by the test programs: generators, fixtures, runners",
    "schema": "the JSON schemas of docs/ against the files lpvid writes",
    "python": "the Python module's tests",
    "scripts": "tests of the scripts/ tools",
    "second_checker": "an independent exact checker written from docs/ alone",
    "explore": "tests of bench/explore/, built with the benchmarks",
}
SOURCE_SUFFIXES = (".h", ".cc")


def holds(folder, suffixes):
    """Whether a file ending in one of `suffixes` lies in `folder` or below it."""
    for _, _, names in os.walk(folder):
        if any(name.endswith(suffixes) for name in names):
            return True
    return False


def rooms(root):
    """The rooms: the folders of src/ that hold sources, and verify."""
    src = os.path.join(root, "src")
    found = {name for name in os.listdir(src)
             if os.path.isdir(os.path.join(src, name)) and holds(os.path.join(src, name), SOURCE_SUFFIXES)}
    if holds(os.path.join(root, "verify"), SOURCE_SUFFIXES):
        found.add("verify")
    return found


def problems_of(root):
    """Every way tests/ fails to mirror the rooms, one line each."""
    tests = os.path.join(root, "tests")
    room_names = rooms(root)
    problems = []
    test_folders = set()
    for name in sorted(os.listdir(tests)):
        path = os.path.join(tests, name)
        if os.path.isfile(path) and name.endswith("_test.cc"):
            problems.append(f"tests/{name}: a test outside every folder of tests/ (no test program builds it)")
        elif os.path.isdir(path) and holds(path, ("_test.cc",)):
            test_folders.add(name)
    for name in sorted(test_folders - room_names - set(NOT_ROOMS)):
        problems.append(f"tests/{name}/: holds *_test.cc but is no room of src/ (nor verify, nor one of "
                        f"{', '.join(sorted(NOT_ROOMS))}); move its tests to the folder of the room they test")
    for name in sorted(room_names - test_folders):
        where = "verify/" if name == "verify" else f"src/{name}/"
        problems.append(f"{where}: has no tests/{name}/ folder holding *_test.cc")
    return problems, room_names, test_folders


def main():
    root = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
    problems, room_names, test_folders = problems_of(root)
    if problems:
        print("\n".join(problems))
        print(f"check_tests_mirror: {len(problems)} problem(s)")
        return 1
    others = sorted(test_folders - room_names)
    print(f"check_tests_mirror: {len(room_names)} rooms (src/ and verify/), each with its tests/ folder; "
          f"other test folders: {', '.join(others) if others else 'none'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
