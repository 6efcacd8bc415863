"""lpvid from Python: robust identification and invalidation of LPV systems
with exactly verified certificates.

    import lpvid
    before = lpvid.fit_linear(u, y, order=2)                          # a Model
    d = lpvid.diagnose(before, u=u, y=y, test=(u_test, y_test))       # a Diagnosis
    d.rms_before, d.rms_after, d.model, d.certificates
    lpvid.compare({"before": before, "after": d.model}, u=u_test, y=y_test).scores
    all(lpvid.verify(c) for c in d.certificates)                     # rechecked exactly

One function per command of the `lpvid` program (fit_linear, simulate,
compare, generate, invalidate, certify, identify, select_basis, tradeoff,
diagnose, oracle) and verify for `lpvid-verify`: the model first, the
signals by keyword (the positional order of version 0.1 still works, with a
DeprecationWarning). They run the same C++ code as the programs, in this
process, on arrays, Series, DataFrames, Model objects or files; nothing is
left on disk unless out_dir= is given. Progress lines go to the logger
"lpvid" (INFO; lpvid.log_to_stderr() shows them) and to a progress=
callback; Ctrl-C stops a running call. Exit codes 0 and 1 are answers; a
bad argument raises LpvidValueError, LpvidTypeError or
LpvidFileNotFoundError (also ValueError, TypeError, FileNotFoundError),
any other failure LpvidError (with .code and .message). The API reference
is docs/python.md; every function has a numpydoc docstring.
"""

import logging
import os


def _pin_blas_kernel():
    """OpenBLAS's Haswell kernels on every CPU that runs them, as the lpvid program pins them: one
    BLAS code path, so one answer on every machine (docs/determinism.md). OpenBLAS reads the
    variable when it is loaded; if another module loaded it first, its kernels stay as chosen."""
    try:
        with open("/proc/cpuinfo") as f:
            flags = next((line.split(":", 1)[1].split() for line in f if line.startswith("flags")), [])
    except OSError:
        return
    if "avx2" in flags and "fma" in flags:
        os.environ["OPENBLAS_CORETYPE"] = "Haswell"


_pin_blas_kernel()

from . import benchmarks  # noqa: F401  (lpvid.benchmarks.cascaded_tanks(...), ...)
from ._commands import (certify, compare, diagnose, fit_linear, generate, identify, invalidate, oracle, read_table,
                        select_basis, simulate, tradeoff)
from ._errors import EXIT_CODES, LpvidError, LpvidFileNotFoundError, LpvidTypeError, LpvidValueError
from ._lpvid import run_lpvid, run_lpvid_verify, version
from .certificate import Certificate, Verification, verify
from .model import Matrices, Model
from .results import (BasisSelection, Bounds, Comparison, Diagnosis, Generated, Identification, Interval, ModelScore,
                      OracleRun, Result, Simulation, Tradeoff, TradeoffPoint, exact)


def log_to_stderr(level=logging.INFO):
    """Shows lpvid's progress lines on stderr (a handler on the logger "lpvid")."""
    logger = logging.getLogger("lpvid")
    if not any(getattr(h, "_lpvid", False) for h in logger.handlers):
        handler = logging.StreamHandler()
        handler.setFormatter(logging.Formatter("%(message)s"))
        handler._lpvid = True
        logger.addHandler(handler)
    logger.setLevel(level)
    return logger


__all__ = ["fit_linear", "simulate", "compare", "generate", "invalidate", "certify", "identify", "select_basis",
           "tradeoff", "diagnose", "oracle", "verify", "Model", "Matrices", "Certificate", "Verification", "Result", "Bounds",
           "Identification", "BasisSelection", "Tradeoff", "TradeoffPoint", "Diagnosis", "Comparison", "ModelScore",
           "Simulation", "Generated", "OracleRun", "Interval", "LpvidError", "LpvidValueError", "LpvidTypeError",
           "LpvidFileNotFoundError", "EXIT_CODES", "exact", "read_table",
           "log_to_stderr", "benchmarks", "run_lpvid", "run_lpvid_verify", "version"]
__version__ = version()
