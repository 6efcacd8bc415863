"""Running one command of `lpvid` from a package function: the keyword
options checked against the command's own, the command line assembled, the
run captured, and any exit code other than 0 and 1 (the answers) raised as
LpvidError with lpvid's message, told in the caller's terms. Below the
modules that use it (the command functions and the Model class), so that
none of them imports another in a circle.

lpvid's messages name what it was given: the files the package wrote and
the command-line options. raise_unless_answer tells them as the caller
wrote them: "<folder>/data.csv:12: column 'y': 'nan' is not a number" is
"y[10] is NaN" (the header is line 1; _files.register_source says which
argument each column came from), the model file written from a dict is
"model", "--max-effects" is "max_effects=", and the command line's advice
to run --help is left out. The message as lpvid wrote it stays in the
error's `detail`.
"""

import os
import re
import tempfile
import threading

from ._errors import EXIT_CODES, LpvidError, LpvidFileNotFoundError, LpvidValueError
from ._files import number_text, take_sources
from ._options import check, command_options, flag_of, option_words, python_options
from ._run import error_message, run_captured

# Options the package sets itself: the files a run reads and writes.
FILES = ("data", "model", "report", "certificate", "model-out", "out", "plots", "csv", "plot", "work", "junit",
         "test", "validation", "validation-out", "truth-out")

# The call whose failure raise_unless_answer tells (one run at a time per thread).
_last = threading.local()


def run(function, command, words, options, *, own=(), managed=FILES, progress=None, quiet=False, pngs=True):
    """(exit code, stdout, stderr messages) of `lpvid COMMAND WORDS OPTIONS`.
    quiet: --quiet where the command has it; else its progress lines are
    dropped here (neither the logger nor `progress` gets them). pngs=False:
    no gnuplot PNG for --plots, only the figure descriptions (the call's
    files are not kept; its figures are drawn from them on .plot())."""
    check(function, command, options, own=own, managed=managed)
    args = command.split() + [str(w) for w in words] + option_words(options, command)
    has_quiet = "quiet" in command_options(command)
    if quiet and has_quiet:
        args.append("--quiet")
    _last.call = {"args": args, "options": dict(options), "sources": take_sources(args)}
    return run_captured("lpvid", args, progress, quiet=bool(quiet) and not has_quiet, pngs=pngs)


def raise_unless_answer(code, output, messages, result=None):
    """Raises unless the exit code is an answer (0 or 1), as raise_error
    does, about the call that run() made last in this thread."""
    if code in (0, 1):
        return
    call = getattr(_last, "call", None) or {"args": [], "options": {}, "sources": {}}
    _last.call = None
    raise_error(code, output, messages, call, result)


def raise_error(code, output, messages, call, result=None):
    """Raises the error of a run that gave no answer: a missing file the
    caller named as LpvidFileNotFoundError, any other bad input (code 2) as
    LpvidValueError, every other code as LpvidError; the message in the
    caller's terms (call: {"args": the command line's words, "options": the
    caller's keyword options, "sources": what take_sources gave}), lpvid's
    own text in `detail`."""
    detail = error_message(output, messages, EXIT_CODES.get(code, ""))
    message = caller_terms(detail, call)
    missing = re.search(r"^(?:lpvid(?:-verify)?: )?(.+?): cannot open: no such file", detail, re.M)
    if code == 2 and missing and not _in_workspace(missing.group(1)):
        error = LpvidFileNotFoundError(missing.group(1), message, result)
    elif code == 2:
        error = LpvidValueError(message, result)
    else:
        error = LpvidError(code, message, result)
    error.detail = detail
    raise error


def caller_terms(text, call):
    """lpvid's message `text` about the run `call` (its args, the caller's
    options, the files written from the caller's arguments) in the caller's
    terms."""
    lines = []
    for line in text.splitlines():
        line = re.sub(r"^lpvid(?:-verify)?: ", "", line)
        line = _files_told(line, call["sources"])
        lines.append(_options_told(line, call))
    return "\n".join(lines)


def _in_workspace(path):
    """True for a path inside a private folder of the package."""
    folder = os.path.join(tempfile.gettempdir(), "lpvid-")
    return os.path.abspath(path).startswith(folder)


_NOT_A_NUMBER = re.compile(r": '([+-]?)(nan|inf|infinity)' is not a number", re.I)


def _files_told(line, sources):
    """Paths of files the package wrote, as the arguments they came from."""
    for path in sorted(sources, key=len, reverse=True):
        source = sources[path]
        pattern = re.escape(path) + r"(?::(\d+))?(?:: column '((?:[^'\\]|\\.)*)')?"
        line = re.sub(pattern, lambda m: _cell_told(m, source), line)
    workspace = re.escape(os.path.join(tempfile.gettempdir(), "lpvid-")) + r"[^/\s]*/([^\s:]+?)(?::\d+)?(?=[:\s]|$)"
    line = re.sub(workspace, lambda m: _workspace_file(m.group(1)), line)

    def number(m):
        return " is " + ("NaN" if m.group(2).lower() == "nan" else ("-inf" if m.group(1) == "-" else "inf"))

    return _NOT_A_NUMBER.sub(number, line)


def _cell_told(m, source):
    """One "<file>:<line>: column '<name>'" as argument[sample(, channel)]."""
    line_no, column = m.group(1), m.group(2)
    k = int(line_no) - 2 if line_no else None
    if column is not None and column in source["columns"] and k is not None and k >= 0:
        argument, channel = source["columns"][column]
        return f"{argument}[{k}]" if channel is None else f"{argument}[{k}, {channel}]"
    told = source["label"] + (f" sample {k}" if k is not None and k >= 0 else "")
    return told + (f": column '{column}'" if column is not None else "")


def _workspace_file(name):
    """A file of the package's private folder not written from an array:
    model.json is the model, other files by their name."""
    stem = os.path.splitext(os.path.basename(name))[0]
    return "model" if stem == "model" else stem


def _options_told(line, call):
    """--max-effects as max_effects= (with the value given), and the
    command line's range and choice messages in plain words."""
    line = _RANGE.sub(lambda m: f"{_keyword_value(m.group(1), call, m.group(2))}: must be {_range(m)}", line)
    line = _CHOICE.sub(lambda m: f"{_keyword_value(m.group(1), call, m.group(2))}: must be one of "
                                 f"{', '.join(repr(c) for c in m.group(3).split(','))}", line)
    line = re.sub(r"^--([a-z][a-z0-9-]*):", lambda m: _keyword_value(m.group(1), call) + ":", line)
    return re.sub(r"(?<![\w-])--([a-z][a-z0-9-]*)( \S+)?", lambda m: _flag_told(m, call), line)


_RANGE = re.compile(r"^--([a-z][a-z0-9-]*): Value (\S+) not in range (\S+) to (\S+)$")
_CHOICE = re.compile(r"^--([a-z][a-z0-9-]*): (\S+) not in \{([^}]*)\}$")


def _range(m):
    low, high = (_plain_number(v) for v in (m.group(3), m.group(4)))
    try:
        unbounded = float(m.group(4)) > 1e300
    except ValueError:
        unbounded = False
    return f"≥ {low}" if unbounded else f"between {low} and {high}"


def _plain_number(text):
    """1.000000 as 1, 0.500000 as 0.5."""
    return text.rstrip("0").rstrip(".") if re.fullmatch(r"-?\d+\.\d+", text) else text


def _flag_told(m, call):
    """One "--opt [word]" inside a message: opt=word when the word is the
    value of that option in the call, or a number; else opt=value: with the
    option's value in the call ("--delta must be" is "delta=-1: must be"),
    or opt= when it has none."""
    flag, after = m.group(1), m.group(2) or ""
    word = after[1:]
    given = _cli_value(flag, call)
    if call["options"].get(_keyword(flag, call)) is True:  # a switch the caller turned on
        return f"{_keyword(flag, call)}=True{after}"
    if given is not None and word.startswith(given):
        return _keyword_value(flag, call) + word[len(given):]
    if re.fullmatch(r"-?[\d.]+[,;]?", word):
        return f"{_keyword(flag, call)}={word}"
    if given is not None or _keyword(flag, call) in call["options"]:
        return _keyword_value(flag, call) + ":" + after
    return f"{_keyword(flag, call)}={after}"


def _keyword(flag, call):
    """The keyword argument of a command-line option, as the caller wrote
    it (lambda_ for --lambda)."""
    for key in call["options"]:
        if flag_of(next(iter(python_options({key: None})))) == flag:
            return key
    return "lambda_" if flag == "lambda" else flag.replace("-", "_")


def _cli_value(flag, call):
    """The word after --flag on the command line (None for a switch)."""
    args = call["args"]
    for i, a in enumerate(args[:-1]):
        if a == "--" + flag:
            return None if args[i + 1].startswith("--") else args[i + 1]
    return None


def _keyword_value(flag, call, fallback=None):
    """keyword=value: the caller's own value (a text quoted, as Python
    shows it), else the option's word on the command line."""
    key = _keyword(flag, call)
    if key in call["options"]:
        value = call["options"][key]
        shown = repr(value) if isinstance(value, str) else _shown(value)
        return f"{key}={shown}"
    value = fallback if fallback is not None else _cli_value(flag, call)
    return f"{key}={value if value is not None else ''}"


def _shown(value):
    try:
        return number_text(value)
    except TypeError:
        return repr(value)
