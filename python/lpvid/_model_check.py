"""A model document (lpvid-model/1, docs/model.schema.json) checked when a
Model is made from a dict, so that a mistake is named where the caller
made it ("model: initial.A[1].value is 2×3; A is states × states = 2×2")
rather than at a line of a file the package wrote.

The check covers what a caller most often gets wrong: the format tag, the
dimensions, the column lists, and the type and shape of every matrix and
vector (initial A, B, C, D; correction A, B; the uncertainty channel's C1,
D1; offset and state_offset values; x0). Everything else (basis texts as
monomials, exact number texts, static maps, unknown keys, limits) is left
to lpvid's own reader, which refuses it with the JSON path.
"""

import math
import numbers
import re
from fractions import Fraction

from ._errors import LpvidTypeError, LpvidValueError

FORMAT = "lpvid-model/1"
LARGEST = 1000  # the reader's largest dimension

# What each dimension counts, for messages.
DIMENSIONS = {"states": "states", "inputs": "inputs", "outputs": "outputs", "nz": "rows of the uncertainty channel"}


def check_model(document):
    """Raises LpvidTypeError (not a dict, a value of the wrong type) or
    LpvidValueError (a wrong shape or value) for a model document that
    lpvid would refuse; returns None for one it can read."""
    if not isinstance(document, dict):
        raise LpvidTypeError(f"a model is an lpvid-model/1 dict, not {type(document).__name__}")
    if document.get("format") != FORMAT:
        got = "missing" if "format" not in document else repr(document["format"])
        raise LpvidValueError(f"model: format is {got}; a model has \"format\": \"{FORMAT}\"")
    nx = _integer(document, "states", 0, "model")
    nu = _integer(document, "inputs", 1, "model")
    ny = _integer(document, "outputs", 1, "model")
    scheduling = _names(document.get("scheduling", []), "scheduling")
    _columns(document, nu, ny, len(scheduling))
    shapes = {"A": ((nx, nx), "states × states"), "B": ((nx, nu), "states × inputs"),
              "C": ((ny, nx), "outputs × states"), "D": ((ny, nu), "outputs × inputs")}
    initial = _part(document, "initial", required=True)
    for key in "ABCD":
        _terms(initial.get(key), f"initial.{key}", key, *shapes[key])
    correction = _part(document, "correction")
    if correction is not None:
        _names(correction.get("basis", []), "correction.basis")
        for key in "AB":
            _terms(correction.get(key), f"correction.{key}", key, *shapes[key])
    _uncertainty(_part(document, "uncertainty"), nx, nu)
    _vectors(_part(document, "offset"), "offset", ny, "outputs")
    _vectors(_part(document, "state_offset"), "state_offset", nx, "states")
    if document.get("x0") is not None:
        _vector(document["x0"], "x0", nx, "states")


def _integer(part, key, low, where):
    """A dimension: a whole number in low..1000, written as a number or a
    number's text ("2")."""
    if key not in part:
        raise LpvidValueError(f"{where}: {key} is missing (the number of {DIMENSIONS[key]})")
    v = part[key]
    if hasattr(v, "item") and not isinstance(v, (list, dict)):
        v = v.item()  # a numpy integer
    if isinstance(v, bool) or not isinstance(v, (numbers.Real, str)):
        raise LpvidTypeError(f"{where}: {key} is {v!r}, not a whole number")
    try:
        q = Fraction(re.sub(r"\s*/\s*", "/", v.strip())) if isinstance(v, str) else Fraction(v)
    except (ValueError, ZeroDivisionError, OverflowError):
        q = None
    if q is None or q.denominator != 1 or not low <= q <= LARGEST:
        raise LpvidValueError(f"{where}: {key} is {v!r}; expected a whole number in {low}..{LARGEST}")
    return int(q)


def _part(document, key, required=False):
    """A sub-object of the model (None when absent and not required)."""
    value = document.get(key)
    if value is None:
        if required:
            raise LpvidValueError(f"model: {key} is missing" +
                                  (" ({} for a model whose A, B, C, D are all zero)" if key == "initial" else ""))
        return None
    if not isinstance(value, dict):
        raise LpvidTypeError(f"model: {key} is {type(value).__name__}, not a dict")
    return value


def _plain(value):
    """numpy arrays and scalars as lists and Python numbers."""
    return value.tolist() if hasattr(value, "tolist") else value


def _names(value, path):
    """A list of texts (scheduling names, basis functions)."""
    value = _plain(value)
    if not isinstance(value, (list, tuple)):
        raise LpvidTypeError(f"model: {path} is {type(value).__name__}, not a list of names")
    for i, name in enumerate(value):
        if not isinstance(name, str):
            raise LpvidTypeError(f"model: {path}[{i}] is {name!r}, not a name (a string)")
    return list(value)


def _columns(document, nu, ny, nrho):
    """columns.u, .y (and .rho): one non-empty name per input, output and
    scheduling variable."""
    columns = _part(document, "columns", required=True)
    for key, count, what in (("u", nu, "inputs"), ("y", ny, "outputs"), ("rho", nrho, "scheduling variables")):
        if key not in columns:
            if key == "rho":
                continue
            raise LpvidValueError(f"model: columns.{key} is missing (the data columns of the {what})")
        names = _names(columns[key], f"columns.{key}")
        if len(names) != count:
            raise LpvidValueError(f"model: columns.{key} has {len(names)} name(s); the model has {count} {what}")
        for i, name in enumerate(names):
            if not name:
                raise LpvidValueError(f"model: columns.{key}[{i}] is an empty name")


def _terms(terms, path, name, shape, shape_words):
    """A parameter-varying matrix: a list of {"basis": text, "value":
    matrix}, every value of `shape`."""
    if terms is None:
        return
    terms = _plain(terms)
    if not isinstance(terms, (list, tuple)):
        raise LpvidTypeError(f"model: {path} is {type(terms).__name__}, not a list of terms "
                             f"[{{\"basis\": \"1\", \"value\": [[...]]}}, ...]")
    for i, term in enumerate(terms):
        where = f"{path}[{i}]"
        if not isinstance(term, dict):
            raise LpvidTypeError(f"model: {where} is {type(term).__name__}, not a term "
                                 f"{{\"basis\": \"1\", \"value\": [[...]]}}")
        if not isinstance(term.get("basis"), str):
            got = "missing" if "basis" not in term else f"{term['basis']!r}, not a text"
            raise LpvidValueError(f"model: {where}.basis is {got} (a basis function such as \"1\" or \"rho1\")")
        if "value" not in term:
            raise LpvidValueError(f"model: {where}.value is missing")
        _matrix(term["value"], f"{where}.value", f"{name} is {shape_words}", shape)


def _matrix(value, path, what, shape):
    """A matrix of `shape` as a list of rows ([] for one without entries)."""
    rows = _plain(value)
    if not isinstance(rows, (list, tuple)):
        raise LpvidTypeError(f"model: {path} is {type(rows).__name__}, not a matrix (a list of rows)")
    if not rows and shape[0] * shape[1] == 0:
        return
    for i, row in enumerate(rows):
        if not isinstance(row, (list, tuple)):
            raise LpvidValueError(f"model: {path}[{i}] is {row!r}, not a row (a list of numbers); "
                                  f"{what} = {shape[0]}×{shape[1]}")
        if len(row) != len(rows[0]):
            raise LpvidValueError(f"model: {path} is ragged: row {i} has {len(row)} entries, row 0 has "
                                  f"{len(rows[0])}")
    got = (len(rows), len(rows[0]) if rows else 0)
    if got != shape:
        raise LpvidValueError(f"model: {path} is {got[0]}×{got[1]}; {what} = {shape[0]}×{shape[1]}")
    for i, row in enumerate(rows):
        for j, v in enumerate(row):
            _number(v, f"{path}[{i}][{j}]")


def _vector(value, path, length, what):
    values = _plain(value)
    if not isinstance(values, (list, tuple)):
        raise LpvidTypeError(f"model: {path} is {type(values).__name__}, not a list of numbers")
    if len(values) != length:
        raise LpvidValueError(f"model: {path} has {len(values)} number(s); the model has {length} {what}")
    for i, v in enumerate(values):
        _number(v, f"{path}[{i}]")


def _vectors(part, path, length, what):
    """offset / state_offset: one vector of `length` per basis function."""
    if part is None:
        return
    basis = _names(part.get("basis", []), f"{path}.basis")
    if part.get("values") is None:
        return
    values = _plain(part["values"])
    if not isinstance(values, (list, tuple)):
        raise LpvidTypeError(f"model: {path}.values is {type(values).__name__}, not a list of vectors")
    if len(values) != len(basis):
        raise LpvidValueError(f"model: {path}.values has {len(values)} vector(s); {path}.basis has {len(basis)} "
                              f"function(s), one vector each")
    for i, v in enumerate(values):
        _vector(v, f"{path}.values[{i}]", length, what)


def _uncertainty(part, nx, nu):
    """The general uncertainty channel's C1 (nz × states) and D1 (nz ×
    inputs); nz given, or the row count of the first term's value."""
    if part is None or part.get("structure") != "general":
        return
    if "nz" in part:
        nz = _integer(part, "nz", 1, "model: uncertainty")
    else:
        nz = None
        for key in ("C1", "D1"):
            terms = _plain(part.get(key))
            if nz is None and isinstance(terms, list) and terms and isinstance(terms[0], dict):
                value = _plain(terms[0].get("value"))
                nz = len(value) if isinstance(value, list) and value else None
        if nz is None:
            raise LpvidValueError("model: uncertainty: structure \"general\" needs nz (or a C1/D1 term with at "
                                  "least one row)")
    _terms(part.get("C1"), "uncertainty.C1", "C1", (nz, nx), "nz × states")
    _terms(part.get("D1"), "uncertainty.D1", "D1", (nz, nu), "nz × inputs")


def _number(v, path):
    """A number of the model: a finite number, or a number's text (read by
    lpvid, which refuses a text that is not one)."""
    if isinstance(v, str):
        return
    if isinstance(v, bool) or not isinstance(v, numbers.Real):
        raise LpvidTypeError(f"model: {path} is {v!r}, not a number")
    if not isinstance(v, numbers.Rational) and not math.isfinite(float(v)):
        raise LpvidValueError(f"model: {path} is {float(v)}; a model's numbers are finite")
