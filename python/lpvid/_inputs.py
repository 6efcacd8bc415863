"""The signals of a call, written as the data files lpvid reads.

Signals come in one of three ways:
- arrays u, y, rho (numpy arrays or lists; 1-D: one channel, 2-D:
  samples x channels) in the order of the model's columns;
- data= a pandas DataFrame, or a dict {column name: array}, written with its
  own column names;
- data= the path of an existing data file (or a list of paths: several
  records), read by lpvid in place.
records=[{"u":.., "y":.., "rho":..}, (u, y, rho), ...] gives several records
of one system under one Delta (one file each).
"""

import os

from ._errors import LpvidError
from ._files import number_text, write_data


def _is_frame(x):
    return hasattr(x, "columns") and hasattr(x, "to_numpy")


def write_table(path, table):
    """Writes a DataFrame or a dict {name: 1-D array} as CSV (header = the
    names; numbers as exact round-trip text)."""
    if _is_frame(table):
        names = [str(c) for c in table.columns]
        columns = [table[c].to_numpy().tolist() for c in table.columns]
    elif isinstance(table, dict):
        names = [str(k) for k in table]
        columns = [v.tolist() if hasattr(v, "tolist") else list(v) for v in table.values()]
    else:
        raise LpvidError(2, f"data: expected a path, a list of paths, a DataFrame or a dict of columns, not "
                            f"{type(table).__name__}")
    lengths = {len(c) for c in columns}
    if len(lengths) > 1:
        raise LpvidError(2, f"data: the columns have different lengths {sorted(lengths)}")
    for n in names:
        if any(ch in n for ch in ',"\n\r') or not n:
            raise LpvidError(2, f"data: column name {n!r} cannot be a CSV header cell")
    lines = [",".join(names)]
    for k in range(lengths.pop() if lengths else 0):
        lines.append(",".join(number_text(c[k]) for c in columns))
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    return path


def _record_signals(record, k):
    """(u, y, rho) of one entry of records=."""
    if isinstance(record, dict):
        unknown = set(record) - {"u", "y", "rho"}
        if unknown:
            raise LpvidError(2, f"records[{k}]: unknown key(s) {sorted(unknown)} (expected u, y, rho)")
        return record.get("u"), record.get("y"), record.get("rho")
    if isinstance(record, (tuple, list)) and len(record) in (2, 3):
        return record[0], record[1], record[2] if len(record) == 3 else None
    raise LpvidError(2, f"records[{k}]: expected a dict with u, y (and rho) or a tuple (u, y[, rho])")


def _given(u, y, rho):
    return u is not None or y is not None or rho is not None


def data_files(folder, model_doc, u, y, rho, data=None, records=None, stem="data"):
    """The data file(s) of a call in `folder`: a list of paths."""
    given = [name for name, v in (("u, y, rho", _given(u, y, rho) or None), ("data", data),
                                  ("records", records)) if v is not None]
    if len(given) > 1:
        raise LpvidError(2, "give the signals one way: as arrays (u, y, rho), as data (a file, a DataFrame or "
                            f"a dict of columns) or as records=, not {' and '.join(given)}")
    if not given:
        raise LpvidError(2, "no signals: give u, y (and rho) arrays, data= or records=")
    if data is not None:
        if isinstance(data, (str, os.PathLike)):
            return [os.path.abspath(os.fspath(data))]
        if isinstance(data, (list, tuple)) and all(isinstance(p, (str, os.PathLike)) for p in data):
            return [os.path.abspath(os.fspath(p)) for p in data]
        return [write_table(os.path.join(folder, f"{stem}.csv"), data)]
    if records is not None:
        if len(records) == 0:
            raise LpvidError(2, "records=: no records")
        paths = []
        for k, record in enumerate(records):
            paths.append(os.path.join(folder, f"{stem}{k + 1}.csv"))
            write_data(paths[-1], model_doc, *_record_signals(record, k))
        return paths
    path = os.path.join(folder, f"{stem}.csv")
    write_data(path, model_doc, u, y, rho)
    return [path]


def width(values):
    """Channels of a 1-D (one) or 2-D (samples x channels) array-like."""
    if hasattr(values, "to_numpy"):
        values = values.to_numpy()
    if hasattr(values, "shape"):
        return 1 if len(values.shape) == 1 else int(values.shape[1])
    first = list(values)[0] if len(values) else 0
    return len(first) if isinstance(first, (list, tuple)) else 1


def generic_names(prefix, values):
    """u1, u2, ... for the channels of an array."""
    if values is None:
        return []
    return [f"{prefix}{k + 1}" for k in range(width(values))]


def generic_table(u, y, rho):
    """{u1: .., y1: .., rho1: ..}: arrays as named columns (for the
    commands that take the column names as options)."""
    table = {}
    for prefix, values in (("u", u), ("y", y), ("rho", rho)):
        if values is None:
            continue
        if hasattr(values, "to_numpy"):
            values = values.to_numpy()
        rows = values.tolist() if hasattr(values, "tolist") else list(values)
        w = width(values)
        for j in range(w):
            table[f"{prefix}{j + 1}"] = [r[j] if isinstance(r, (list, tuple)) else r for r in rows]
    return table


def is_names(x):
    """True for a column name or a list of column names (not numbers)."""
    if isinstance(x, str):
        return True
    return isinstance(x, (list, tuple)) and len(x) > 0 and all(isinstance(v, str) for v in x)


def as_names(x):
    return [x] if isinstance(x, str) else list(x)
