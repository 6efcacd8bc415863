"""lpvid from Python: robust identification and invalidation of LPV systems
with exactly verified certificates.

    import lpvid
    before = lpvid.fit_linear(u=u, y=y, order=2)                     # a Model
    d = lpvid.diagnose(u, y, None, before, test=(u_test, y_test))     # a Diagnosis
    d.rms_before, d.rms_after, d.model, d.certificates
    lpvid.compare(u=u_test, y=y_test, models={"before": before, "after": d.model}).scores
    all(lpvid.verify(c) for c in d.certificates)                     # rechecked exactly

One function per command of the `lpvid` program (fit_linear, simulate,
compare, generate, invalidate, certify, identify, select_basis, tradeoff,
diagnose, oracle) and verify for `lpvid-verify`. They run the same C++ code
as the programs, in this process, on arrays, DataFrames, Model objects or
files; nothing is left on disk unless out_dir= is given. Progress lines go
to the logger "lpvid" (INFO; lpvid.log_to_stderr() shows them) and to a
progress= callback; Ctrl-C stops a running call. Exit codes 0 and 1 are
answers; every other code raises LpvidError (with .code and .message).
The API reference is docs/python.md.
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
from ._errors import EXIT_CODES, LpvidError
from ._lpvid import run_lpvid, run_lpvid_verify, version
from .certificate import Certificate, Verification, verify
from .model import Model
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
           "tradeoff", "diagnose", "oracle", "verify", "Model", "Certificate", "Verification", "Result", "Bounds",
           "Identification", "BasisSelection", "Tradeoff", "TradeoffPoint", "Diagnosis", "Comparison", "ModelScore",
           "Simulation", "Generated", "OracleRun", "Interval", "LpvidError", "EXIT_CODES", "exact", "read_table",
           "log_to_stderr", "benchmarks", "run_lpvid", "run_lpvid_verify", "version"]
__version__ = version()
