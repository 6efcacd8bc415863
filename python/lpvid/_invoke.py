"""Running one command of `lpvid` from a package function: the keyword
options checked against the command's own, the command line assembled, the
run captured, and any exit code other than 0 and 1 (the answers) raised as
LpvidError with lpvid's message. Below the modules that use it (the command
functions and the Model class), so that none of them imports another in a
circle."""

from ._errors import EXIT_CODES, LpvidError
from ._options import check, command_options, option_words
from ._run import error_message, run_captured

# Options the package sets itself: the files a run reads and writes.
FILES = ("data", "model", "report", "certificate", "model-out", "out", "plots", "csv", "plot", "work", "junit",
         "test", "validation", "validation-out", "truth-out")


def run(function, command, words, options, *, own=(), managed=FILES, progress=None, quiet=False):
    """(exit code, stdout, stderr messages) of `lpvid COMMAND WORDS OPTIONS`."""
    check(function, command, options, own=own, managed=managed)
    args = command.split() + list(words) + option_words(options)
    if quiet and "quiet" in command_options(command):
        args.append("--quiet")
    return run_captured("lpvid", args, progress)


def raise_unless_answer(code, output, messages, result=None):
    """Raises LpvidError unless the exit code is an answer (0 or 1)."""
    if code not in (0, 1):
        raise LpvidError(code, error_message(output, messages, EXIT_CODES.get(code, "")), result)
