"""One function per command of `lpvid`, on arrays, DataFrames, Model
objects and files: the package's public functions, gathered from the
modules that hold them.

- _bounds_commands.py: invalidate, certify, identify, select_basis,
  tradeoff (Theorems 2.1 and 3.1 of "Robust identification and
  invalidation of LPV systems");
- _diagnose_command.py: diagnose;
- _record_commands.py: fit_linear, simulate, compare;
- _case_commands.py: generate, oracle;
- _command_files.py: what each of them does around its run (the files it
  writes, the report and certificates it reads back).

Each call checks its keyword options against the command's own options,
writes its inputs into a private folder (or the caller's out_dir), runs the
same code as the command line in this process, reads what the run wrote
into the result, and removes the private folder. Exit codes 0 and 1 are
answers; any other code raises an LpvidError in the caller's terms.
"""

from ._bounds_commands import certify, identify, invalidate, select_basis, tradeoff
from ._case_commands import generate, oracle
from ._diagnose_command import diagnose
from ._files import read_table
from ._record_commands import compare, fit_linear, simulate
from .results import Result

__all__ = ["invalidate", "certify", "identify", "select_basis", "tradeoff", "diagnose", "fit_linear", "simulate",
           "compare", "generate", "oracle", "read_table", "Result"]
