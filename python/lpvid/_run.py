"""Running the command lines in this process: output, progress, Ctrl-C.

The extension runs the C++ code of `lpvid` and `lpvid-verify` directly
(_lpvid.run_lpvid_captured): what the program prints on stdout and stderr
comes back as text (lpvid's error message becomes the LpvidError's message),
and its progress lines wait in a queue inside the extension. No file
descriptor of the process is touched, so a logging handler that writes to
sys.stderr (logging.basicConfig, log_to_stderr, Jupyter) cannot feed back
into the capture.

The run itself goes on in a worker thread (the extension releases the
interpreter while it computes); the calling thread waits in short steps,
taking the queued progress lines each time and passing them, in order and
each once, to the logger "lpvid" (level INFO) and to the caller's
`progress` callback, all in the calling thread. Ctrl-C (KeyboardInterrupt)
reaches it at once: it asks the run to stop (lpvid's own stop request,
checked between solver steps, fit steps, windows and pivots of the exact
checks), waits for it to return (exit code 130, its outputs removed) and
raises the KeyboardInterrupt again. A solver's own verbose output (--verbose)
is the solver library's and goes to the process's stdout.
"""

import contextlib
import logging
import signal
import threading

from . import _lpvid

logger = logging.getLogger("lpvid")

# The extension runs one call at a time (its input limits and record of a
# run's outputs are per process); so does this package.
_one_run = threading.Lock()


def _line_handler(progress):
    def on_line(line):
        if line.startswith(("lpvid: ", "lpvid-verify: ")) and ("error" in line or "removed" in line):
            logger.warning(line)
        else:
            logger.info(line)
        if progress is not None:
            with contextlib.suppress(Exception):  # a failing callback must not stop the run
                progress(line)
    return on_line


def _pass_on(on_line, lines, kept):
    for line in lines:
        kept.append(line)
        on_line(line)


def _stop_requested_run():
    """Asks the running call to stop (lpvid's cooperative stop request)."""
    request = getattr(_lpvid, "request_stop", None)
    if request is not None:
        request()


def _clear_stop():
    clear = getattr(_lpvid, "clear_stop", None)
    if clear is not None:
        clear()


def _run_in_worker(run, args, on_line, kept):
    """run(args) in a worker thread; the calling thread passes the progress
    lines on as they come and stays responsive to KeyboardInterrupt, which
    stops the run and is raised again once the run has returned. The wait is
    on an Event, not Thread.join: a join that a KeyboardInterrupt interrupts
    can mark a running thread as stopped (CPython gh-90882), and the run
    would go on after the call returned."""
    box = {}
    done = threading.Event()

    def work():
        try:
            # Ctrl-C belongs to the calling thread: blocked here (and so in every
            # thread the run starts), it cannot interrupt a system call of the run.
            signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
            box["result"] = run(args)
        except BaseException as e:  # noqa: BLE001 - handed to the caller
            box["error"] = e
        finally:
            done.set()

    threading.Thread(target=work, name="lpvid-run", daemon=True).start()
    try:
        while not done.wait(0.05):
            _pass_on(on_line, _lpvid.take_progress(), kept)
    except KeyboardInterrupt:
        _stop_requested_run()
        while not done.is_set():  # a second Ctrl-C does not abandon the run half-stopped
            with contextlib.suppress(KeyboardInterrupt):
                done.wait(0.05)
        _pass_on(on_line, _lpvid.take_progress(), kept)
        _messages(on_line, box)  # "lpvid: interrupted ...; removed the N file(s)"
        _clear_stop()
        raise
    _pass_on(on_line, _lpvid.take_progress(), kept)
    if "error" in box:
        raise box["error"]
    _messages(on_line, box)
    return box["result"]


def _messages(on_line, box):
    """The program's own stderr lines (its messages), once it has returned."""
    if "result" in box:
        for line in box["result"][2].splitlines():
            if line.strip():
                on_line(line)


def run_captured(program, args, progress=None):
    """Runs `program` ('lpvid' or 'lpvid-verify') with `args` in-process;
    returns (exit code, stdout text, stderr text: the progress lines, then
    what the program wrote on stderr). Progress lines go to the logger
    "lpvid" and to progress(line) as they come; the program's stderr lines
    (its messages) when it returns."""
    run = _lpvid.run_lpvid_captured if program == "lpvid" else _lpvid.run_lpvid_verify_captured
    words = [str(a) for a in args]
    logger.debug("%s %s", program, " ".join(words))
    on_line, kept = _line_handler(progress), []
    with _one_run:
        _clear_stop()
        _lpvid.take_progress()  # nothing an earlier run left behind
        code, out, err = _run_in_worker(run, words, on_line, kept)
    text = "".join(line + "\n" for line in kept) + err
    return code, out, text


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
