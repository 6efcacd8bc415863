"""Running the command lines in this process and capturing what they print.

The extension runs the C++ code of `lpvid` and `lpvid-verify` directly; it
prints to the process's file descriptors 1 and 2, not to Python's
sys.stdout/sys.stderr. While a run lasts both descriptors are pointed at
pipes whose reader threads keep the text (lpvid's error message becomes the
LpvidError's message) and, unless quiet, pass it on as it comes.
"""

import codecs
import contextlib
import os
import sys
import threading

from . import _lpvid
from ._files import number_text


class _Reader:
    """Drains one pipe into a buffer, echoing to `echo_fd` (or not)."""

    def __init__(self, read_fd, echo_fd):
        self._fd, self._echo = read_fd, echo_fd
        self._decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")
        self._parts = []
        self._thread = threading.Thread(target=self._drain, daemon=True)
        self._thread.start()

    def _drain(self):
        while True:
            data = os.read(self._fd, 65536)
            if not data:
                break
            self._parts.append(self._decoder.decode(data))
            if self._echo is not None:
                with contextlib.suppress(OSError):
                    os.write(self._echo, data)
        self._parts.append(self._decoder.decode(b"", final=True))
        os.close(self._fd)

    def text(self):
        self._thread.join()
        return "".join(self._parts)


@contextlib.contextmanager
def _captured(echo):
    """Points fds 1 and 2 at pipes for the duration; yields a dict that
    holds 'stdout' and 'stderr' text afterwards."""
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(Exception):
            stream.flush()
    out = {"stdout": "", "stderr": ""}
    saved, readers = {}, {}
    try:
        for fd, name in ((1, "stdout"), (2, "stderr")):
            try:
                saved[fd] = os.dup(fd)
            except OSError:  # a closed descriptor: nothing to capture
                continue
            r, w = os.pipe()
            os.dup2(w, fd)
            os.close(w)
            readers[name] = _Reader(r, saved[fd] if echo else None)
        yield out
    finally:
        # Restoring closes the pipes' last write ends: the readers see EOF.
        for fd, copy in saved.items():
            os.dup2(copy, fd)
        for name, reader in readers.items():
            out[name] = reader.text()
        for copy in saved.values():
            os.close(copy)


# The descriptors are the process's: two runs from two threads would
# capture each other's text, so one run at a time (the extension runs one
# at a time anyway).
_one_run = threading.Lock()


def run_captured(program, args, echo):
    """Runs `program` ('lpvid' or 'lpvid-verify') with `args` in-process;
    returns (exit code, stdout text, stderr text). Ctrl-C takes effect when
    the run returns (the C++ code does not look at Python's signals)."""
    run = _lpvid.run_lpvid if program == "lpvid" else _lpvid.run_lpvid_verify
    with _one_run, _captured(echo) as out:
        code = run([str(a) for a in args])
    return code, out["stdout"], out["stderr"]


def option_words(options):
    """Keyword options as command-line words, named exactly as the CLI's
    options with '_' for '-' (max_taps=0 -> --max-taps 0). True: a flag;
    False or None: left out; a list: the option followed by its values; a
    list of lists: the option repeated, each value list joined by commas
    (diagnose --test-columns uVal,yVal)."""
    words = []
    for key, value in options.items():
        flag = "--" + key.rstrip("_").replace("_", "-")
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


def error_message(stdout, stderr, fallback):
    """lpvid's own message: its 'lpvid: ...' lines (or lpvid-verify's),
    else the last lines it printed, else `fallback`."""
    lines = [ln for ln in stderr.splitlines() if ln.strip()]
    own = [ln for ln in lines if ln.startswith(("lpvid: ", "lpvid-verify: "))]
    if own:
        return "\n".join(own)
    if lines:
        return "\n".join(lines[-5:])
    tail = [ln for ln in stdout.splitlines() if ln.strip()][-5:]
    return "\n".join(tail) if tail else fallback
