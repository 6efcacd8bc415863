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

from ._errors import LpvidTypeError, LpvidValueError
from ._files import (as_signal, check_signals, existing_path, number_text, register_source, signal_names,
                     write_data)


def _is_frame(x):
    return hasattr(x, "columns") and hasattr(x, "to_numpy")


def _table_columns(table):
    """[(name, caller's text for the column, values)] of a DataFrame or a
    dict of columns."""
    if _is_frame(table):
        return [(str(c), f"data[{c!r}]", table[c]) for c in table.columns]
    if isinstance(table, dict):
        return [(str(k), f"data[{k!r}]", v) for k, v in table.items()]
    raise LpvidTypeError(f"data: expected a path, a list of paths, a DataFrame or a dict of columns, not "
                         f"{type(table).__name__}")


def write_table(path, table):
    """Writes a DataFrame or a dict {name: 1-D array} as CSV (header = the
    names; numbers as exact round-trip text). Each column is checked first,
    named as the caller wrote it (data['yEst']; for a SignalTable, the
    argument it came from: y[:, 1]). lpvid reads only the columns it is
    told to, so the values are its to judge: a NaN it refuses is told as
    data['yEst'][10] (register_source)."""
    sources = getattr(table, "sources", None)
    columns, first = [], None
    for name, text, values in _table_columns(table):
        if not name or any(ch in name for ch in ',"\n\r'):
            raise LpvidValueError(f"data: column name {name!r} cannot be a CSV header cell")
        a = as_signal(text, values, finite=False) if sources is None else values
        if sources is None and getattr(a, "ndim", 1) != 1:
            raise LpvidValueError(f"{text} has shape {a.shape}: a column of data is one channel (1-D)")
        cells = a.tolist() if hasattr(a, "tolist") else list(a)
        if first is None:
            first = (text, len(cells))
        elif len(cells) != first[1]:
            raise LpvidValueError(f"{first[0]} has {first[1]} samples, {text} has {len(cells)}")
        columns.append((name, text, cells))
    names = [c[0] for c in columns]
    if len(set(names)) != len(names):
        raise LpvidValueError(f"data: two columns are both named {next(n for n in names if names.count(n) > 1)!r}")
    lines = [",".join(names)]
    for k in range(first[1] if first else 0):
        lines.append(",".join(number_text(c[2][k]) for c in columns))
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    register_source(path, getattr(table, "label", "data"),
                    sources if sources is not None else {name: (text, None) for name, text, _ in columns})
    return path


class SignalTable(dict):
    """{column: values} of arrays given as arguments, with where each column
    came from (sources: {column: (argument text, channel)}) so that a
    message about a column names the argument."""

    def __init__(self, columns, sources, label):
        super().__init__(columns)
        self.sources = sources
        self.label = label


def signal_table(u=None, y=None, rho=None, names=None):
    """generic_table(u, y, rho) after checking the arrays together, named
    as the caller wrote them (names: signal_names(); default u, y, rho):
    types, dimensions, NaN and inf, transposed arrays, equal lengths. Use
    it, not generic_table, for the signals a caller passed as arrays."""
    names = names or signal_names()
    arrays = {role: as_signal(names[role], v) for role, v in (("u", u), ("y", y), ("rho", rho)) if v is not None}
    check_signals(arrays, names)
    table, sources = {}, {}
    given = {"u": u, "y": y, "rho": rho}
    for role, a in arrays.items():
        part = generic_table(*(given[r] if r == role else None for r in ("u", "y", "rho")), taken=table)
        for j, column in enumerate(part):
            sources[column] = (names[role], j if a.ndim == 2 else None)
        table.update(part)
    return SignalTable(table, sources, names["label"])


def record_names(record, k, label="records"):
    """signal_names of entry k of records= (a dict or a tuple)."""
    return signal_names(f"{label}[{k}]", dict if isinstance(record, dict) else tuple)


def _record_signals(record, k):
    """(u, y, rho) of one entry of records=."""
    if isinstance(record, dict):
        unknown = set(record) - {"u", "y", "rho"}
        if unknown:
            raise LpvidTypeError(f"records[{k}]: unknown key(s) {sorted(unknown)} (expected u, y, rho)")
        return record.get("u"), record.get("y"), record.get("rho")
    if isinstance(record, (tuple, list)) and len(record) in (2, 3):
        return record[0], record[1], record[2] if len(record) == 3 else None
    raise LpvidTypeError(f"records[{k}]: expected a dict with u, y (and rho) or a tuple (u, y[, rho]), not "
                         f"{type(record).__name__}" + (f" of {len(record)}" if isinstance(record, (tuple, list))
                                                       else ""))


def _given(u, y, rho):
    return u is not None or y is not None or rho is not None


def _data_paths(data):
    """The files of data= when it names files (a path or a list of paths),
    each checked to exist; None when data is a table."""
    if isinstance(data, (str, os.PathLike)):
        return [existing_path(data, "data")]
    if isinstance(data, (list, tuple)) and data and all(isinstance(p, (str, os.PathLike)) for p in data):
        return [existing_path(p, f"data[{k}]") for k, p in enumerate(data)]
    return None


def data_files(folder, model_doc, u, y, rho, data=None, records=None, stem="data"):
    """The data file(s) of a call in `folder`: a list of paths."""
    given = [name for name, v in (("u, y, rho", _given(u, y, rho) or None), ("data", data),
                                  ("records", records)) if v is not None]
    if len(given) > 1:
        raise LpvidTypeError("give the signals one way: as arrays (u, y, rho), as data (a file, a DataFrame or "
                             f"a dict of columns) or as records=, not {' and '.join(given)}")
    if not given:
        raise LpvidTypeError("no signals: give u, y (and rho) arrays, data= or records=")
    if data is not None:
        return _data_paths(data) or [write_table(os.path.join(folder, f"{stem}.csv"), data)]
    if records is not None:
        if isinstance(records, (str, bytes, dict)) or not hasattr(records, "__len__"):
            raise LpvidTypeError(f"records: expected a list of records (dicts or tuples), not "
                                 f"{type(records).__name__}")
        if len(records) == 0:
            raise LpvidValueError("records: no records")
        paths = []
        for k, record in enumerate(records):
            paths.append(os.path.join(folder, f"{stem}{k + 1}.csv"))
            write_data(paths[-1], model_doc, *_record_signals(record, k), names=record_names(record, k))
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


def _usable_name(name, taken):
    return isinstance(name, str) and name and name not in taken and not any(ch in name for ch in ',"\n\r') \
        and name.strip() == name


def generic_names(prefix, values, taken=()):
    """Column names for the channels of a signal: a pandas Series' name or a
    DataFrame's column names, when each can be a CSV header cell and none is
    already `taken` (by another signal of the call); otherwise prefix1,
    prefix2, ... (u1, u2, ...)."""
    if values is None:
        return []
    if hasattr(values, "columns"):
        own = [c if isinstance(c, str) else None for c in values.columns]
    else:
        own = [getattr(values, "name", None)] if hasattr(values, "to_numpy") else [None]
    seen = set(taken)
    if len(own) == width(values) and all(_usable_name(n, seen) for n in own) and len(set(own)) == len(own):
        return list(own)
    return [f"{prefix}{k + 1}" for k in range(width(values))]


def generic_table(u, y, rho, taken=()):
    """{name: column}: arrays as named columns (for the commands that take
    the column names as options), named by generic_names: u, then y (not
    reusing u's names), then rho; none of them one of `taken`."""
    table = {}
    for prefix, values in (("u", u), ("y", y), ("rho", rho)):
        if values is None:
            continue
        names = generic_names(prefix, values, taken=set(taken) | set(table))
        if hasattr(values, "to_numpy"):
            values = values.to_numpy()
        rows = values.tolist() if hasattr(values, "tolist") else list(values)
        for j, name in enumerate(names):
            table[name] = [r[j] if isinstance(r, (list, tuple)) else r for r in rows]
    return table


def is_names(x):
    """True for a column name or a list of column names (not numbers)."""
    if isinstance(x, str):
        return True
    return isinstance(x, (list, tuple)) and len(x) > 0 and all(isinstance(v, str) for v in x)


def as_names(x):
    return [x] if isinstance(x, str) else list(x)
