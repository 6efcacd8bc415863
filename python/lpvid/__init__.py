"""lpvid from Python: robust identification and invalidation of LPV systems
with exactly verified certificates.

    import lpvid
    r = lpvid.invalidate(u, y, rho, model_dict, delta=0)   # min dmax at delta = 0
    r.dmax, r.dmax2_exact, r.certificate                   # certified, with its certificate
    lpvid.verify(r.certificate).ok                         # rechecked exactly

The functions run the same code as the `lpvid` and `lpvid-verify` programs,
in this process (lpvid._lpvid), on files they write into one folder: the
arrays become data.csv (exact round-trip text) because a certificate names
its data file by path and SHA-256. Exit codes 0 and 1 are answers; every
other code raises LpvidError (README "Exit codes").
"""

from ._commands import Result, Verification, diagnose, exact, identify, invalidate, verify
from ._errors import EXIT_CODES, LpvidError
from ._lpvid import run_lpvid, run_lpvid_verify, version

__all__ = ["invalidate", "identify", "diagnose", "verify", "exact", "Result", "Verification", "LpvidError",
           "EXIT_CODES", "run_lpvid", "run_lpvid_verify", "version"]
__version__ = version()
