"""The input files a run reads: the data table (CSV) and the model file.

lpvid reads every number as exact text, and a certificate names its data
file by path and SHA-256, so the arrays are written once, to a file that
stays beside the certificates, with text that reads back as exactly the
same double (the shortest round-trip form, Python's repr).
"""

import csv
import json
import math
import numbers
import os
from fractions import Fraction

from ._errors import LpvidError


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
    with open(path, encoding="utf-8") as f:
        return json.load(f)


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


def _as_rows(name, values, width):
    """values (1-D: one channel; 2-D: samples x channels) as a list of rows
    of `width` cells; a mismatch is an error naming the argument."""
    if hasattr(values, "to_numpy"):  # a pandas Series or DataFrame: its values, not its labels
        values = values.to_numpy()
    if hasattr(values, "tolist"):
        values = values.tolist()
    values = list(values)
    rows = []
    for k, v in enumerate(values):
        if isinstance(v, (list, tuple)):
            row = list(v)
        elif hasattr(v, "tolist") and isinstance(v.tolist(), list):
            row = v.tolist()
        else:
            row = [v]
        if len(row) != width:
            raise LpvidError(2, f"{name}: sample {k} has {len(row)} channel(s), the model has {width} "
                                f"column(s) for it")
        rows.append(row)
    return rows


def write_data(path, model, u, y, rho):
    """Writes u, y and rho as the CSV data file of `model`: a header with
    the model's column names, then one row per sample. Returns the number
    of samples."""
    u_names, y_names, rho_names = model_columns(model)
    blocks = [("u", u, u_names), ("y", y, y_names), ("rho", rho, rho_names)]
    header, columns, n = [], [], None
    for name, values, names in blocks:
        if values is None:
            if names:
                raise LpvidError(2, f"{name}: missing; the model reads the column(s) {', '.join(names)}")
            continue
        if not names:
            raise LpvidError(2, f"{name}: given, but the model reads no {name} column from the data")
        rows = _as_rows(name, values, len(names))
        if n is None:
            n = len(rows)
        elif len(rows) != n:
            first = next(b for b in blocks if b[1] is not None)[0]
            raise LpvidError(2, f"{name} has {len(rows)} samples, {first} has {n}: every signal needs one "
                                f"value per sample")
        header += names
        columns.append(rows)
    if len(set(header)) != len(header):
        raise LpvidError(2, f"the model's columns repeat a name: {header}")
    for h in header:
        if any(c in h for c in ',"\n\r'):
            raise LpvidError(2, f"column name {h!r}: a comma, quote or line break cannot be a CSV header cell")
    lines = [",".join(header)]
    for k in range(n or 0):
        lines.append(",".join(number_text(x) for rows in columns for x in rows[k]))
    tmp = f"{path}.tmp-{os.getpid()}"
    with open(tmp, "w", encoding="utf-8", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(tmp, path)
    return n or 0


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
