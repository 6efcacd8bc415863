"""Running the command lines in this process: capture, progress, Ctrl-C.

The extension runs the C++ code of `lpvid` and `lpvid-verify` directly; it
prints to the process's file descriptors 1 and 2, not to Python's
sys.stdout/sys.stderr. While a run lasts both descriptors are pointed at
pipes whose reader threads keep the text (lpvid's error message becomes the
LpvidError's message) and pass every line of stderr on, as it comes, to the
logger "lpvid" (level INFO) and to the caller's `progress` callback.

The run itself goes on in a worker thread (the extension releases the
interpreter while it computes); the calling thread waits in short steps, so
that Ctrl-C (KeyboardInterrupt) reaches it at once. It then asks the run to
stop (lpvid's own stop request, checked between solver steps, fit steps,
windows and pivots of the exact checks), waits for it to return (exit code
130, its outputs removed) and raises the KeyboardInterrupt again.
"""

import codecs
import contextlib
import logging
import os
import signal
import sys
import threading

from . import _lpvid

logger = logging.getLogger("lpvid")


class _Reader:
    """Drains one pipe into a buffer; every complete line goes to `on_line`."""

    def __init__(self, read_fd, on_line):
        self._fd, self._on_line = read_fd, on_line
        self._decoder = codecs.getincrementaldecoder("utf-8")(errors="replace")
        self._parts = []
        self._pending = ""
        self._thread = threading.Thread(target=self._drain, daemon=True)
        self._thread.start()

    def _lines(self, text):
        if self._on_line is None:
            return
        self._pending += text
        *complete, self._pending = self._pending.split("\n")
        for line in complete:
            if line.strip():
                with contextlib.suppress(Exception):  # a failing callback must not stop the capture
                    self._on_line(line)

    def _drain(self):
        while True:
            data = os.read(self._fd, 65536)
            if not data:
                break
            text = self._decoder.decode(data)
            self._parts.append(text)
            self._lines(text)
        tail = self._decoder.decode(b"", final=True)
        self._parts.append(tail)
        self._lines(tail + "\n")
        os.close(self._fd)

    def text(self):
        self._thread.join()
        return "".join(self._parts)


@contextlib.contextmanager
def _captured(on_stderr_line):
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
            readers[name] = _Reader(r, on_stderr_line if name == "stderr" else None)
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


def _line_handler(progress):
    def on_line(line):
        if line.startswith(("lpvid: ", "lpvid-verify: ")) and ("error" in line or "removed" in line):
            logger.warning(line)
        else:
            logger.info(line)
        if progress is not None:
            progress(line)
    return on_line


def _stop_requested_run():
    """Asks the running call to stop (lpvid's cooperative stop request)."""
    request = getattr(_lpvid, "request_stop", None)
    if request is not None:
        request()


def _clear_stop():
    clear = getattr(_lpvid, "clear_stop", None)
    if clear is not None:
        clear()


def _run_in_worker(run, args):
    """run(args) in a worker thread; the calling thread stays responsive to
    KeyboardInterrupt, which stops the run and is raised again once the run
    has returned. The wait is on an Event, not Thread.join: a join that a
    KeyboardInterrupt interrupts can mark a running thread as stopped
    (CPython gh-90882), and the run would go on after the call returned."""
    box = {}
    done = threading.Event()

    def work():
        try:
            # Ctrl-C belongs to the calling thread: blocked here (and so in every
            # thread the run starts), it cannot interrupt a system call of the run.
            signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
            box["code"] = run(args)
        except BaseException as e:  # noqa: BLE001 - handed to the caller
            box["error"] = e
        finally:
            done.set()

    threading.Thread(target=work, name="lpvid-run", daemon=True).start()
    try:
        while not done.wait(0.05):
            pass
    except KeyboardInterrupt:
        _stop_requested_run()
        while not done.is_set():  # a second Ctrl-C does not abandon the run half-stopped
            with contextlib.suppress(KeyboardInterrupt):
                done.wait(0.05)
        _clear_stop()
        raise
    if "error" in box:
        raise box["error"]
    return box["code"]


def run_captured(program, args, progress=None):
    """Runs `program` ('lpvid' or 'lpvid-verify') with `args` in-process;
    returns (exit code, stdout text, stderr text). stderr lines go to the
    logger "lpvid" and to progress(line) as they come."""
    run = _lpvid.run_lpvid if program == "lpvid" else _lpvid.run_lpvid_verify
    words = [str(a) for a in args]
    logger.debug("%s %s", program, " ".join(words))
    with _one_run:
        _clear_stop()
        with _captured(_line_handler(progress)) as out:
            code = _run_in_worker(run, words)
    return code, out["stdout"], out["stderr"]


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
