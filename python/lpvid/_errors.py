"""Exit codes (docs/exit_codes.md) and the error
raised for every code that is not an answer."""

EXIT_CODES = {
    0: "bounds found and verified (lpvid-verify: the certificate's claim holds)",
    1: "invalidated at the given bounds, checked exactly (lpvid-verify: the claim does not hold)",
    2: "bad input: missing, malformed, not a regular file, or above a limit; bad options",
    3: "the SDP backend failed (no bound is reported)",
    4: "bounds were computed but the exact check did not accept them",
    5: "fixed bounds: neither consistency nor invalidation could be certified",
    6: "I/O failure: an existing input could not be read, or an output could not be written",
    124: "timed out: the --timeout given passed before an answer; the run's outputs were removed",
    130: "interrupted: the run's outputs were removed",
}


class LpvidError(Exception):
    """A run that gave no answer: its exit code (`code`), lpvid's own
    message (`message`) and, when the run got that far, what it wrote
    (`result`: the Result with the report, or None)."""

    def __init__(self, code, message, result=None):
        self.code = code
        self.message = message
        self.result = result
        meaning = EXIT_CODES.get(code, "unknown exit code")
        super().__init__(f"[exit {code}: {meaning}] {message}")
