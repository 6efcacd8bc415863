"""Exit codes (docs/exit_codes.md) and the errors the package raises.

Every error is an LpvidError (with .code, the exit code the command line
would give, and .message). Errors in what the caller passed are also the
standard Python class for that kind of mistake, so `except ValueError`
catches a NaN in y just as it would in numpy or scipy:

- LpvidValueError (ValueError): a bad value: NaN or inf in a signal,
  lengths that differ, an array of the wrong shape, a model whose matrices
  do not fit together, an option value out of range;
- LpvidTypeError (TypeError): an argument of the wrong type, a keyword the
  function does not have;
- LpvidFileNotFoundError (FileNotFoundError): a named file that is not
  there.

The message names the argument and the index as the caller wrote them
("y[10] is NaN"), never a temporary file of the package.
"""

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
    """A call that gave no answer: the exit code the command line gives for
    it (`code`, docs/exit_codes.md; `meaning` says what it means), the
    message (`message`, also str(error)) and, when the run got that far,
    what it wrote (`result`: the Result with the report, or None)."""

    def __init__(self, code, message, result=None):
        self.code = code
        self.message = message
        self.result = result
        self.meaning = EXIT_CODES.get(code, "unknown exit code")
        super().__init__(message)

    def __str__(self):
        return self.message

    def __repr__(self):
        return f"{type(self).__name__}(code={self.code}, message={self.message!r})"


class LpvidValueError(LpvidError, ValueError):
    """A bad value in what the caller passed (exit code 2 on the command line)."""

    def __init__(self, message, result=None):
        super().__init__(2, message, result)


class LpvidTypeError(LpvidError, TypeError):
    """An argument of the wrong type, or a keyword the function does not have."""

    def __init__(self, message, result=None):
        super().__init__(2, message, result)


class LpvidFileNotFoundError(LpvidError, FileNotFoundError):
    """A file the caller named that does not exist (`filename`)."""

    def __init__(self, filename, message=None, result=None):
        super().__init__(2, message or f"{filename}: no such file", result)
        self.filename = str(filename)


ERROR_CLASSES = ["LpvidError", "LpvidValueError", "LpvidTypeError", "LpvidFileNotFoundError"]
