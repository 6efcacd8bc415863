"""Keyword options: checked against the command's own options, then turned
into command-line words.

Every function of the package takes the options of its command as keyword
arguments, named as the command-line option with '_' for '-'
(max_taps=0 for --max-taps 0). A keyword the command does not have is
refused before anything runs, with the closest names ("did you mean").
The list of options comes from the programs themselves (the extension's
command_options(), built from the same option tables as `lpvid --help`),
so it cannot drift from the command line.
"""

import difflib
import os
import re

from . import _lpvid
from ._errors import LpvidError
from ._files import number_text

_cache = {}


def _from_help(command):
    """The long option names of `lpvid <command> --help` (for an extension
    built without command_options())."""
    from ._run import run_captured  # late: _run imports nothing from here
    program, words = ("lpvid-verify", ["certificate", "--help"]) if command == "lpvid-verify" else \
        ("lpvid", command.split() + ["--help"])
    _, out, _ = run_captured(program, words)
    names = {}
    for line in out.splitlines():
        m = re.match(r"\s+(?:-\w,)?((?:--[\w-]+,?)+)", line)
        if m:
            aliases = [a[2:] for a in m.group(1).split(",") if a]
            for a in aliases:
                names[a] = {"names": aliases, "flag": " TEXT" not in line and " INT" not in line
                            and " FLOAT" not in line and " UINT" not in line}
    return names


def command_options(command):
    """{long option name: info} of one command ("diagnose", "jobs plan",
    "lpvid-verify"); info has "names" (every alias) and "flag"."""
    if command in _cache:
        return _cache[command]
    table = getattr(_lpvid, "command_options", None)
    if table is not None:
        everything = table()
        found = {}
        for key in (command, "global", ""):
            for opt in everything.get(key, []):
                names = opt.get("names") or [opt["name"]]
                for n in names:
                    found[n] = dict(opt, names=names)
        if found:
            _cache[command] = found
            return found
    _cache[command] = _from_help(command)
    return _cache[command]


def flag_of(key):
    """The command-line option of a keyword: max_taps -> max-taps (a trailing
    '_' for Python keywords: lambda_ -> lambda)."""
    return key.rstrip("_").replace("_", "-")


def check(function, command, options, own=(), managed=()):
    """Refuses a keyword that is neither one of the function's own (`own`)
    nor an option of `command`, or one that the package sets itself
    (`managed`: the files it writes and reads), with "did you mean"."""
    known = command_options(command)
    for key in options:
        flag = flag_of(key)
        if flag in managed:
            raise LpvidError(2, f"{function}(): {key}= is set by the Python package (the files it writes); "
                                f"give out_dir= to keep the files of a run")
        if flag in known or key in own:
            continue
        candidates = sorted({n.replace("-", "_") for n in known if n not in managed and n != "help"}
                            | set(own))
        close = difflib.get_close_matches(key, candidates, n=3, cutoff=0.6)
        hint = f"; did you mean {' or '.join(c + '=' for c in close)}?" if close else \
            f"; its options: {', '.join(candidates)}"
        raise LpvidError(2, f"{function}(): unknown option {key}={hint}")


def option_words(options):
    """Keyword options as command-line words. True: a flag; False or None:
    left out; a list: the option followed by its values; a list of lists:
    the option repeated, each value list joined by commas
    (test_columns=[["uVal", "yVal"]] -> --test-columns uVal,yVal)."""
    words = []
    for key, value in options.items():
        flag = "--" + flag_of(key)
        if value is None or value is False:
            continue
        if isinstance(value, os.PathLike):
            value = os.fspath(value)
        if value is True:
            words.append(flag)
        elif isinstance(value, (list, tuple)):
            if value and all(isinstance(v, (list, tuple)) for v in value):
                for group in value:
                    words += [flag, ",".join(number_text(v) for v in group)]
            else:
                words += [flag] + [number_text(v) for v in value]
        else:
            words += [flag, number_text(value)]
    return words
