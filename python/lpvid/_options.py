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
from ._errors import LpvidTypeError
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
    """Refuses, with LpvidTypeError as Python refuses a keyword a function
    does not have: a keyword that is neither one of the function's own
    (`own`) nor an option of `command` ("did you mean"), one that the
    package sets itself (`managed`: the files it writes and reads), and a
    value the command line could not take as given (_check_value)."""
    known = command_options(command)
    for key, value in options.items():
        flag = flag_of(next(iter(python_options({key: None}))))
        if flag in managed:
            raise LpvidTypeError(f"{function}() got the keyword argument '{key}', which the package sets itself "
                                 f"(the files it writes); give out_dir= to keep the files of a run")
        if key in own:
            continue
        if flag not in known:
            candidates = sorted({n.replace("-", "_") for n in known if n not in managed and n != "help"}
                                | set(own))
            close = difflib.get_close_matches(key, candidates, n=3, cutoff=0.6)
            hint = f"; did you mean {' or '.join(c + '=' for c in close)}?" if close else \
                f"; its options: {', '.join(candidates)}"
            raise LpvidTypeError(f"{function}() got an unexpected keyword argument '{key}'{hint}")
        _check_value(function, key, value, bool(known[flag].get("flag")), f"no-{flag}" in known)


def _check_value(function, key, value, is_flag, has_no_form):
    """A switch (an option without a value) takes True or False; an option
    with a value takes a value, not True, nor False unless the command has
    its --no- form. None leaves any option out."""
    if value is None:
        return
    if is_flag and not isinstance(value, bool):
        raise LpvidTypeError(f"{function}(): {key}={value!r}: {key}= is a switch: give True or False")
    if not is_flag and (value is True or (value is False and not has_no_form)):
        raise LpvidTypeError(f"{function}(): {key}={value!r}: {key}= takes a value, not True or False (None for "
                             f"the default)")


# Keywords spelt as Python users spell them, for options the command line
# names differently.
KEYWORD_ALIASES = {"units": "unit"}


def python_options(options):
    """The options with the package's keyword aliases (units= for unit=)
    replaced by the command line's names."""
    return {KEYWORD_ALIASES.get(k, k): v for k, v in options.items()}


def _window_option(name, command):
    """True for an option whose values are row windows B:E."""
    info = command_options(command).get(name) if command else None
    if info is not None:
        return "B:E" in (info.get("help") or "")
    return name.endswith("rows") or name == "window"


def _window_text(value):
    begin, end = value
    return f"{number_text(begin)}:{number_text(end)}"


def _is_window(value):
    if isinstance(value, range) and value.step == 1:
        return True
    return isinstance(value, tuple) and len(value) == 2 and all(isinstance(v, int) and not isinstance(v, bool)
                                                                 for v in value)


def _value_words(name, value, command):
    """The words after --name for a value that is not True/False/None."""
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if isinstance(value, range):
        value = (value.start, value.stop)
    if _window_option(name, command):
        if _is_window(value):
            return [_window_text(value)]
        if isinstance(value, list) and value and all(_is_window(v) for v in value):
            return [_window_text(tuple(v) if not isinstance(v, range) else (v.start, v.stop)) for v in value]
    if isinstance(value, dict):
        return [f"{k}={number_text(v)}" for k, v in value.items()]
    if isinstance(value, (list, tuple)):
        return [number_text(v) for v in value]
    return [number_text(value)]


def option_words(options, command=None):
    """Keyword options as command-line words. True: a flag; None: left out;
    False: left out, or the option's --no- form when the command has one
    (offset=False -> --no-offset); a (begin, end) tuple or a range for an
    option of row windows: "B:E" (rows=(0, 700) -> --rows 0:700); a dict:
    NAME=VALUE words (units={"uEst": "V"} -> --unit uEst=V); a list: the
    option followed by its values; a list of lists: the option repeated,
    each value list joined by commas (test_columns=[["uVal", "yVal"]] ->
    --test-columns uVal,yVal)."""
    words = []
    for key, value in python_options(options).items():
        name = flag_of(key)
        if value is None:
            continue
        if value is False:
            if command and f"no-{name}" in command_options(command):
                words.append(f"--no-{name}")
            continue
        if value is True:
            words.append("--" + name)
        elif isinstance(value, (list, tuple)) and value and all(isinstance(v, (list, tuple)) for v in value) \
                and not _window_option(name, command):
            for group in value:
                words += ["--" + name, ",".join(number_text(v) for v in group)]
        else:
            words += ["--" + name] + _value_words(name, value, command)
    return words
