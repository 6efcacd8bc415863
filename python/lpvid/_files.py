"""The input files a run reads: the data table (CSV) and the model file.

lpvid reads every number as exact text, and a certificate names its data
file by path and SHA-256, so the arrays are written once, to a file that
stays beside the certificates, with text that reads back as exactly the
same double (the shortest round-trip form, Python's repr).
"""

import csv
import errno
import json
import math
import numbers
import os
from fractions import Fraction

import numpy as np

from ._errors import LpvidError, LpvidFileNotFoundError, LpvidTypeError, LpvidValueError


def number_text(x):
    """Exact text of one number: ints as they are, floats by their shortest
    round-trip decimal (repr), Fractions as p/q, other text unchanged.
    NaN and infinities are written as "nan"/"inf" so that lpvid, not this
    module, refuses them with its own message (file, line and column)."""
    if isinstance(x, str):
        return x
    if isinstance(x, bool):
        raise TypeError("a boolean is not a number of the data or the model")
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    if isinstance(x, numbers.Real):
        f = float(x)  # numpy float32/float64 scalars convert exactly
        if math.isnan(f):
            return "nan"
        if math.isinf(f):
            return "inf" if f > 0 else "-inf"
        return repr(f)
    raise TypeError(f"not a number: {x!r}")


def _json_default(x):
    """json.dump's fallback for the values a model dict may hold besides
    plain JSON: numpy arrays and scalars, Fractions (written as exact text,
    which the model format accepts)."""
    if isinstance(x, Fraction):
        return number_text(x)
    if hasattr(x, "tolist"):  # numpy arrays and scalars, without importing numpy
        return x.tolist()
    raise TypeError(f"not JSON serialisable in a model: {x!r}")


def write_model(model, path):
    """Writes a model dict as an lpvid-model/1 file."""
    with open(path, "w", encoding="utf-8") as f:
        json.dump(model, f, indent=2, default=_json_default)
        f.write("\n")


def read_json(path):
    """A JSON file; a missing one raises LpvidFileNotFoundError (an OSError,
    so that callers catching OSError still do)."""
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except FileNotFoundError:
        raise _not_found(path, f"{os.fspath(path)}: no such file") from None


def _not_found(path, message):
    e = LpvidFileNotFoundError(os.fspath(path), message)
    e.errno, e.strerror = errno.ENOENT, "no such file"
    return e


def existing_path(path, name):
    """The absolute path of a file the caller named as argument `name`;
    LpvidFileNotFoundError naming the path as given when there is nothing
    there."""
    given = os.fspath(path)
    if not os.path.exists(given):
        raise _not_found(given, f"{name}: {given}: no such file")
    return os.path.abspath(given)


def read_model_file(path):
    """The document of a model file the caller named, with the standard
    errors: LpvidFileNotFoundError (no such file), LpvidValueError (not
    JSON), LpvidError code 6 (there but unreadable)."""
    given = os.fspath(path)
    try:
        with open(given, encoding="utf-8") as f:
            return json.load(f)
    except FileNotFoundError:
        raise _not_found(given, f"model: {given}: no such file") from None
    except OSError as e:
        raise LpvidError(6, f"model: {given}: {e.strerror}") from None
    except ValueError as e:
        raise LpvidValueError(f"model: {given}: not JSON: {e}") from None


def model_columns(model):
    """The data columns the model reads: (u names, y names, rho names). Rho
    columns that start with '@' are functions of the model's own state,
    computed by lpvid, not read from the data."""
    columns = model.get("columns") or {}
    u = list(columns.get("u") or [])
    y = list(columns.get("y") or [])
    rho = columns.get("rho")
    if rho is None:
        rho = model.get("scheduling") or []
    rho = [c for c in rho if not (isinstance(c, str) and c.startswith("@"))]
    return u, y, rho


# -- the signals, checked in the caller's terms ------------------------------------
def as_signal(name, values, finite=True):
    """values (a list, a numpy array, a pandas Series or DataFrame) as a
    numpy array of one dimension (one channel) or two (samples ×
    channels), every value a number or a number's text, and finite unless
    finite=False (a column that lpvid may never read). A mistake
    raises LpvidTypeError or LpvidValueError naming the argument `name` and
    the index as the caller wrote them ("y[10] is NaN")."""
    if hasattr(values, "to_numpy"):  # a pandas Series or DataFrame: its values, not its labels
        values = values.to_numpy()
    if isinstance(values, (str, bytes, dict, set)) or values is None:
        raise LpvidTypeError(f"{name}: expected an array of numbers (samples × channels), not "
                             f"{type(values).__name__}")
    try:
        a = np.asarray(values)
    except ValueError:
        raise LpvidValueError(f"{name} is ragged: its rows have different lengths") from None
    if a.ndim == 0:
        raise LpvidTypeError(f"{name}: expected an array of numbers (samples × channels), not a single "
                             f"{type(values).__name__}")
    if a.ndim > 2:
        raise LpvidValueError(f"{name} has {a.ndim} dimensions; give samples × channels")
    if a.dtype.kind in "bcmMV":
        kind = {"b": "booleans", "c": "complex numbers"}.get(a.dtype.kind, f"{a.dtype} values")
        raise LpvidTypeError(f"{name} holds {kind}, not real numbers")
    if a.dtype.kind == "f" and finite:
        bad = np.argwhere(~np.isfinite(a))
        if len(bad):
            _refuse_value(name, tuple(int(i) for i in bad[0]), float(a[tuple(bad[0])]))
    elif a.dtype.kind == "O":
        for index, v in np.ndenumerate(a):
            _check_cell(name, index, v, finite)
    return a


def _index_text(name, index):
    return f"{name}[{', '.join(str(i) for i in index)}]"


def _refuse_value(name, index, v):
    what = "NaN" if math.isnan(v) else ("inf" if v > 0 else "-inf")
    raise LpvidValueError(f"{_index_text(name, index)} is {what}")


def _check_cell(name, index, v, finite):
    """One value of an array of objects: a real number (finite) or a
    number's text (which lpvid reads, and refuses with its own message)."""
    if isinstance(v, str):
        return
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise LpvidTypeError(f"{_index_text(name, index)} is {v!r}, not a number")
    if finite and not isinstance(v, numbers.Rational) and not math.isfinite(float(v)):
        _refuse_value(name, index, float(v))


def _suspect_transposed(a, want, lengths):
    """A 2-D array with fewer rows than columns that looks like channels ×
    samples: its column count is the other signals' length, or its row
    count is the channel count the model asks for."""
    if not _wide(a):
        return False
    return a.shape[1] in lengths or (want is not None and a.shape[0] == want and a.shape[1] != want)


def _wide(a):
    return a.ndim == 2 and a.shape[0] < a.shape[1]


def check_signals(arrays, names, want=None):
    """The shapes of signals together (arrays: {role: numpy array}): none
    transposed, each with the model's channel count (want: {role: column
    names}) and all of one length. Returns the sample count."""
    for role, a in arrays.items():
        others = {b.shape[0] for r, b in arrays.items() if r != role and not _wide(b)}
        columns = (want or {}).get(role)
        if _suspect_transposed(a, None if columns is None else len(columns), others):
            raise LpvidValueError(f"{names[role]} has shape {a.shape}: give samples × channels ({names[role]}.T?)")
        channels = 1 if a.ndim == 1 else a.shape[1]
        if columns is not None and channels != len(columns):
            raise LpvidValueError(f"{names[role]} has {_count(channels, 'channel')}; the model has "
                                  f"{_count(len(columns), ROLES[role])} ({', '.join(columns)})")
    first, n = None, None
    for role, a in arrays.items():
        if first is None:
            first, n = role, a.shape[0]
        elif a.shape[0] != n:
            raise LpvidValueError(f"{names[first]} has {n} samples, {names[role]} has {a.shape[0]}")
    return n or 0


ROLES = {"u": "input", "y": "output", "rho": "scheduling variable"}


def _count(n, word):
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def signal_names(label=None, form=None):
    """How the caller writes each signal: u, y, rho for the arguments;
    records[1]['y'] in a dict record (form dict); records[1][1] in a tuple
    (form tuple). "label" names the whole record in messages."""
    if label is None:
        return {"u": "u", "y": "y", "rho": "rho", "label": "u, y, rho"}
    if form is dict:
        return {"u": f"{label}['u']", "y": f"{label}['y']", "rho": f"{label}['rho']", "label": label}
    return {"u": f"{label}[0]", "y": f"{label}[1]", "rho": f"{label}[2]", "label": label}


def _names_of_file(path):
    """The caller's names for a data file written without names=: test2.csv
    is diagnose's test[1] (a tuple (u, y, rho)); anything else the
    arguments u, y, rho."""
    stem = os.path.splitext(os.path.basename(path))[0]
    if stem.startswith("test") and stem[4:].isdigit():
        return signal_names(f"test[{int(stem[4:]) - 1}]", tuple)
    return signal_names()


def _rows(a):
    """The rows of a checked signal as lists (exact values: tolist keeps
    ints, Fractions and text, and turns float32/float64 into the same
    Python float)."""
    values = a.tolist()
    return [[v] for v in values] if a.ndim == 1 else values


# -- what a written file holds, for messages about it ------------------------------------
_sources = {}


def register_source(path, label, columns):
    """Remembers that the file `path` holds the caller's `label` (a record,
    data=, ...), column by column: columns {name: (argument text, channel
    index or None for a 1-D signal)}. A message of lpvid about line L of
    that column is then told as argument[L - 2] (the header is line 1)."""
    if len(_sources) > 200:  # files of runs that never started
        _sources.pop(next(iter(_sources)))
    _sources[os.path.abspath(path)] = {"label": label, "columns": dict(columns)}


def take_sources(paths):
    """{path: what it holds} for the files among `paths` that the package
    wrote from the caller's arrays; they are forgotten here."""
    found = {}
    for p in paths:
        key = os.path.abspath(p) if isinstance(p, str) and p.startswith(os.sep) else None
        if key in _sources:
            found[key] = _sources.pop(key)
    return found


def write_data(path, model, u, y, rho, names=None):
    """Writes u, y and rho as the CSV data file of `model`: a header with
    the model's column names, then one row per sample. The signals are
    checked first, named as the caller wrote them (names: from
    signal_names). Returns the number of samples."""
    names = names or _names_of_file(path)
    want = dict(zip(("u", "y", "rho"), model_columns(model)))
    arrays = {}
    for role, values in (("u", u), ("y", y), ("rho", rho)):
        if values is None:
            if want[role]:
                raise LpvidTypeError(f"{names[role]} is missing: the model reads the {ROLES[role]} column(s) "
                                     f"{', '.join(want[role])}")
            continue
        if not want[role]:
            raise LpvidValueError(f"{names[role]} given, but the model has no {ROLES[role]} column in the data")
        arrays[role] = as_signal(names[role], values)
    n = check_signals(arrays, names, want)
    header = [c for role in arrays for c in want[role]]
    if len(set(header)) != len(header):
        raise LpvidValueError(f"model: its columns repeat a name: {header}")
    for h in header:
        if any(c in h for c in ',"\n\r'):
            raise LpvidValueError(f"model: column name {h!r}: a comma, quote or line break cannot be a CSV "
                                  f"header cell")
    blocks = [_rows(a) for a in arrays.values()]
    lines = [",".join(header)]
    for k in range(n):
        lines.append(",".join(number_text(x) for rows in blocks for x in rows[k]))
    tmp = f"{path}.tmp-{os.getpid()}"
    with open(tmp, "w", encoding="utf-8", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)
    register_source(path, names["label"], {c: (names[role], j if a.ndim == 2 else None)
                                          for role, a in arrays.items() for j, c in enumerate(want[role])})
    return n


def read_table(path):
    """A CSV file as {column: array}: numbers as float arrays (an empty
    cell: NaN), any other column as an array of str."""
    import numpy as np
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    table = {}
    for j, name in enumerate(header):
        cells = [r[j] if j < len(r) else "" for r in body]
        try:
            table[name] = np.array([float(c) if c != "" else np.nan for c in cells], dtype=float)
        except ValueError:
            table[name] = np.array(cells, dtype=str)
    return table
