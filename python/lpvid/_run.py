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
raises the KeyboardInterrupt again. SIGTERM does the same when the package
runs in the main thread and SIGTERM has its default action: the run stops,
the call's folders are removed on the way out, and the process then ends
with exit code 143 (a SystemExit), as SIGTERM would have ended it; the
default action is back once the run has returned. A solver's own verbose
output (--verbose) is the solver library's and goes to the process's
stdout.
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


def _run_in_worker(run, args, on_line, kept, quiet=False):
    """run(args) in a worker thread; the calling thread passes the progress
    lines on as they come (none with quiet) and stays responsive to
    KeyboardInterrupt, SIGTERM and any other exception a signal handler
    raises: they stop the run and are raised again once the run has
    returned. The wait is on an Event, not Thread.join: a join that a
    KeyboardInterrupt interrupts can mark a running thread as stopped
    (CPython gh-90882), and the run would go on after the call returned."""
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

    def take():
        lines = _lpvid.take_progress()
        return [] if quiet else lines

    threading.Thread(target=work, name="lpvid-run", daemon=True).start()
    try:
        while not done.wait(0.05):
            _pass_on(on_line, take(), kept)
    except BaseException:  # Ctrl-C, SIGTERM (_Terminated), a handler's own exception
        _stop_requested_run()
        terminated = _wait_stopped(done)
        _pass_on(on_line, take(), kept)
        _messages(on_line, box)  # "lpvid: interrupted ...; removed the N file(s)"
        _clear_stop()
        if terminated is not None:
            raise terminated from None
        raise
    _pass_on(on_line, take(), kept)
    if "error" in box:
        raise box["error"]
    _messages(on_line, box)
    return box["result"]


class _Terminated(SystemExit):
    """SIGTERM during a run: raised in the calling thread like Ctrl-C's
    KeyboardInterrupt, so that the run stops and every folder of the call
    is removed on the way out; uncaught, it ends the process with exit code
    143 (128 + SIGTERM), as a shell reports a process that SIGTERM ended."""

    def __init__(self):
        super().__init__(128 + signal.SIGTERM)

    def __str__(self):
        return "terminated (SIGTERM)"


def _on_sigterm(signum, frame):
    raise _Terminated()


@contextlib.contextmanager
def _sigterm_stops_the_run():
    """For the time of a run: SIGTERM raises _Terminated in this thread,
    when it is the main thread (the only one Python signal handlers run in)
    and SIGTERM still has its default action (a handler of the caller's own
    is left alone). The earlier handler is put back afterwards."""
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        yield
        return
    signal.signal(signal.SIGTERM, _on_sigterm)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _wait_stopped(done):
    """Waits for a run asked to stop: a second Ctrl-C does not abandon it
    half-stopped. Returns the _Terminated of a SIGTERM that came meanwhile
    (it ends the process, whatever the first exception was), else None."""
    terminated = None
    while not done.is_set():
        try:
            done.wait(0.05)
        except _Terminated as e:
            terminated = e
        except BaseException:  # noqa: BLE001 - the first one is raised once the run has returned
            pass
    return terminated


def _messages(on_line, box):
    """The program's own stderr lines (its messages), once it has returned."""
    if "result" in box:
        for line in box["result"][2].splitlines():
            if line.strip():
                on_line(line)


def _draw_pngs(on):
    """gnuplot PNGs for --plots (on), or only the figure descriptions that
    lpvid.plots draws from (an extension without the switch always draws)."""
    switch = getattr(_lpvid, "set_png_drawing", None)
    if switch is not None:
        switch(bool(on))


def run_captured(program, args, progress=None, quiet=False, pngs=True):
    """Runs `program` ('lpvid' or 'lpvid-verify') with `args` in-process;
    returns (exit code, stdout text, stderr text: the progress lines, then
    what the program wrote on stderr). Progress lines go to the logger
    "lpvid" and to progress(line) as they come (with quiet: nowhere, for a
    command without --quiet); the program's stderr lines (its messages)
    when it returns. pngs=False: --plots writes the figure descriptions
    only (no gnuplot run), for a call whose files are not kept."""
    run = _lpvid.run_lpvid_captured if program == "lpvid" else _lpvid.run_lpvid_verify_captured
    words = [str(a) for a in args]
    logger.debug("%s %s", program, " ".join(words))
    on_line, kept = _line_handler(progress), []
    with _one_run, _sigterm_stops_the_run():
        _clear_stop()
        _lpvid.take_progress()  # nothing an earlier run left behind
        _draw_pngs(pngs)
        try:
            code, out, err = _run_in_worker(run, words, on_line, kept, quiet)
        finally:
            _draw_pngs(True)
    text = "".join(line + "\n" for line in kept) + err
    return code, out, text


def error_message(stdout, stderr, fallback):
    """lpvid's own message: its 'lpvid: ...' lines (or lpvid-verify's),
    else the last lines it printed (without the command line's advice to
    run --help), else `fallback`."""
    lines = [ln for ln in stderr.splitlines() if ln.strip() and not ln.startswith("Run with --help")]
    own = [ln for ln in lines if ln.startswith(("lpvid: ", "lpvid-verify: "))]
    if own:
        return "\n".join(own)
    if lines:
        return "\n".join(lines[-5:])
    tail = [ln for ln in stdout.splitlines() if ln.strip()][-5:]
    return "\n".join(tail) if tail else fallback
