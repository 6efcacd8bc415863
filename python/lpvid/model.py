"""The model (format lpvid-model/1, docs/model.schema.json) as an object.

A Model wraps the model file's JSON document: the LPV state-space model
(eq. 1 of "Robust identification and invalidation of LPV systems"), its
column names, uncertainty channel, correction basis, static blocks, sample
time and units. Numbers stay as the file writes them (exact text such as
"0.3" or "1/10" is kept), so a model read and written again is the same
model. matrices(rho) evaluates the matrices at a scheduling value as float
arrays (each number the nearest double of its exact value, as lpvid's
floating path reads it); to_scipy() gives an LTI model as a
scipy.signal.StateSpace.
"""

import copy
import dataclasses
import json
import math
import numbers
import os
from fractions import Fraction
from typing import Iterator, List, Optional, Sequence, Tuple

import numpy as np

from ._errors import LpvidError, LpvidTypeError, LpvidValueError
from ._files import model_columns, read_model_file, write_model
from ._model_check import check_model
from ._simulate import simulate_document
from .results import Summarised, summary_html


class Model:
    """An lpvid model. Model(dict) wraps a model document;
    Model.from_file(path) reads one; to_file / to_dict / to_json write it;
    simulate(u, rho) runs it (lpvid simulate); matrices(rho) gives its
    matrices at a scheduling value, to_scipy() an LTI model as a scipy
    StateSpace."""

    def __init__(self, document):
        if isinstance(document, Model):
            document = document.document
        check_model(document)  # LpvidTypeError / LpvidValueError naming the field (_model_check.py)
        self.document = copy.deepcopy(document)
        self.report = None  # the report of the run that made it, when a run did

    @classmethod
    def from_file(cls, path):
        """The model in a model file: LpvidFileNotFoundError when there is
        none, LpvidValueError when it is not JSON or not a valid model."""
        return cls(read_model_file(path))

    @classmethod
    def from_json(cls, text):
        return cls(json.loads(text))

    def to_dict(self):
        return copy.deepcopy(self.document)

    def to_json(self):
        return json.dumps(self.document, indent=2)

    def to_file(self, path):
        write_model(self.document, os.fspath(path))
        return os.fspath(path)

    # -- what it is ------------------------------------------------------------
    @property
    def states(self):
        return self.document.get("states")

    @property
    def inputs(self):
        return self.document.get("inputs")

    @property
    def outputs(self):
        return self.document.get("outputs")

    @property
    def columns(self):
        """(u, y, rho) column names the model reads from a data file."""
        return model_columns(self.document)

    @property
    def sample_time(self):
        """Seconds between samples, when the model file says (None otherwise)."""
        return self.document.get("sample_time")

    @property
    def units(self):
        return dict(self.document.get("units") or {})

    @property
    def description(self):
        return self.document.get("description")

    def __eq__(self, other):
        return isinstance(other, Model) and self.document == other.document

    def __repr__(self):
        u, y, rho = self.columns
        return (f"<lpvid.Model {self.states} states, u={_names(u)}, y={_names(y)}"
                + (f", rho={_names(rho)}" if rho else "") + ">")

    def _repr_html_(self) -> str:
        u, y, rho = self.columns
        pairs = [("states", self.states), ("u", u), ("y", y)] + ([("rho", rho)] if rho else [])
        pairs += [("sample_time", self.sample_time)] if self.sample_time is not None else []
        try:
            pairs += [("static", sorted(self.static_blocks))] if self.has_static_blocks else []
        except LpvidError:
            pass
        return summary_html("Model", pairs)

    def simulate(self, u=None, rho=None, *, data=None, x0=None, **options):
        """The model's free-run output (lpvid simulate) for inputs u (and
        scheduling rho), from the model's x0 (or x0=[...]). Returns a
        Simulation with y (samples x outputs) and z (the uncertainty
        channel's input). See lpvid.simulate."""
        simulation = simulate_document(self.document, u, rho, data=data, x0=x0, **options)
        if simulation.sample_time is None and self.sample_time is not None:
            simulation.sample_time = _float(self.sample_time, "sample_time")
        return simulation

    # -- its matrices ----------------------------------------------------------
    @property
    def scheduling(self) -> List[str]:
        """The names of the scheduling variables ρ ([] for an LTI model)."""
        return list(self.document.get("scheduling") or [])

    @property
    def x0(self) -> np.ndarray:
        """The initial state x_0 as floats (zeros when the model gives none)."""
        nx = _count(self.document, "states", 0)
        x0 = self.document.get("x0")
        return np.zeros(nx) if x0 is None else _vector(x0, nx, "x0")

    @property
    def static_blocks(self) -> dict:
        """The static blocks that act around the LPV part: a dict with
        "input_delay" (samples), "input" and "output" (the maps as the file
        writes them), each only when it does something (identity maps and a
        zero delay are left out); {} when there are none. They are not
        matrices: matrices() and to_scipy() leave them out."""
        static = self.document.get("static") or {}
        out = {}
        delay = static.get("input_delay")
        if delay is not None and _float(delay, "static.input_delay") != 0:
            out["input_delay"] = int(_float(delay, "static.input_delay"))
        for key in ("input", "output"):
            block = static.get(key)
            if isinstance(block, dict) and block.get("kind", "identity") != "identity":
                out[key] = copy.deepcopy(block)
        return out

    @property
    def has_static_blocks(self) -> bool:
        """True when the model has an input delay or a static input or output map."""
        return bool(self.static_blocks)

    def matrices(self, rho=None) -> "Matrices":
        """The model's matrices at one scheduling value (eq. 1), the ones
        `lpvid simulate` uses.

        Parameters
        ----------
        rho : float, sequence of floats or dict, optional
            The value of the scheduling variables: a number (one variable),
            one number per variable in the order of `scheduling`, or a dict
            {name: value}. None (the default) for a model without
            scheduling variables.

        Returns
        -------
        Matrices
            A, B (with the correction's fixed A_i, B_i of eq. 10 added), C,
            D, the uncertainty channel's C1, D1, the output offset Φ(ρ) and
            the state offset E(ρ), as float arrays; unpacks as A, B, C, D.
            Static blocks are not matrices (see static_blocks).

        Raises
        ------
        LpvidValueError
            rho missing for a scheduled model or of the wrong length; an
            unknown name in a basis function; a matrix of the wrong size.
        """
        doc, names = self.document, self.scheduling
        value = _scheduling_value(rho, names)
        nx, nu, ny = _count(doc, "states", 0), _count(doc, "inputs", 1), _count(doc, "outputs", 1)
        initial = doc.get("initial") or {}
        parts = {}
        for key, rows, cols in (("A", nx, nx), ("B", nx, nu), ("C", ny, nx), ("D", ny, nu)):
            parts[key] = _terms(initial.get(key), rows, cols, names, value, f"initial.{key}")
            if key in "AB":  # A(ρ) = A_0(ρ) + Σ_i f_i(ρ) A_i, likewise B (eq. 10)
                _terms(_correction_terms(doc, key, names), rows, cols, names, value, f"correction.{key}",
                       into=parts[key])
        structure, c1, d1 = _uncertainty(doc, (nx, nu, ny), names, value)
        return Matrices(A=parts["A"], B=parts["B"], C=parts["C"], D=parts["D"], C1=c1, D1=d1,
                        offset=_basis_sum(doc.get("offset"), ny, names, value, "offset"),
                        state_offset=_basis_sum(doc.get("state_offset"), nx, names, value, "state_offset"),
                        rho=np.array(value, dtype=float), uncertainty=structure)

    def to_scipy(self):
        """The model as a discrete-time scipy.signal.StateSpace, for an LTI
        model: matrices that do not depend on the scheduling, no static
        blocks, no output or state offset.

        Returns
        -------
        scipy.signal.StateSpace
            StateSpace(A, B, C, D, dt=sample_time), dt=True when the model
            states no sample time. The initial state is not part of it:
            pass x0=model.x0 to scipy.signal.dlsim.

        Raises
        ------
        LpvidValueError
            The model is not LTI in that sense (the message says why).
        """
        reason = self._not_lti()
        if reason:
            raise LpvidValueError(f"to_scipy(): {reason}; only an LTI model is a scipy StateSpace "
                                  f"(use matrices(rho) for the matrices at one scheduling value)")
        try:
            import scipy.signal
        except ImportError:
            raise ImportError("to_scipy() needs scipy, which is not installed (pip install scipy; Debian: "
                              "apt install python3-scipy)") from None
        m = self.matrices([0.0] * len(self.scheduling) if self.scheduling else None)
        dt = True if self.sample_time is None else _float(self.sample_time, "sample_time")
        return scipy.signal.StateSpace(m.A, m.B, m.C, m.D, dt=dt)

    def _not_lti(self) -> Optional[str]:
        """Why the model is not a linear time-invariant system, or None."""
        doc, names = self.document, self.scheduling
        lists = [(f"initial.{k}", (doc.get("initial") or {}).get(k)) for k in "ABCD"]
        lists += [(f"correction.{k}", (doc.get("correction") or {}).get(k)) for k in "AB"]
        for where, terms in lists:
            for j, term in enumerate(terms or []):
                if any(_monomial(term.get("basis") if isinstance(term, dict) else None, names, f"{where}[{j}]")):
                    return f"{where}[{j}] depends on the scheduling (basis {term['basis']!r})"
        if self.has_static_blocks:
            return f"it has static blocks ({', '.join(sorted(self.static_blocks))})"
        for key, what in (("offset", "an output offset"), ("state_offset", "a state offset")):
            values = (doc.get(key) or {}).get("values") or []
            if any(_float(x, f"{key}.values") != 0 for v in values for x in v):
                return f"it adds {what} ({key}.values), which a StateSpace cannot hold"
        return None


# -- the model's matrices at a scheduling value (eq. 1, 9, 10) ---------------------------------------
_MAX_POWER = 16  # the largest exponent of a basis function the program accepts


@dataclasses.dataclass(repr=False, eq=False)
class Matrices(Summarised):
    """The matrices of the model at one scheduling value ρ, as `lpvid
    simulate` uses them (eq. 1 with the correction's fixed A_i, B_i of
    eq. 10 folded in):

        x_{k+1} = A(ρ_k) x_k + B(ρ_k) u_k + state_offset(ρ_k)
        ŷ_k     = C(ρ_k) x_k + D(ρ_k) u_k,     y_k = ŷ_k + offset(ρ_k)
        z_k     = C1(ρ_k) x_k + D1(ρ_k) u_k    (the uncertainty channel)

    A: nx x nx, B: nx x nu, C: ny x nx, D: ny x nu, C1: nz x nx, D1: nz x
    nu (float arrays); offset Φ(ρ) (eq. 20; zero when its values are
    unknowns) and state_offset E(ρ): vectors; rho: the scheduling value;
    uncertainty: the channel's structure ("multiplicative": C1 = W·C,
    D1 = W·D; "additive": C1 = 0, D1 = W·I; "general": as given).
    The correction's C_i, D_i are unknowns of identify, not model data: an
    identified model (Identification.model) has them folded into C and D,
    so its matrices include them. Static blocks (Model.static_blocks) act
    outside these matrices. Unpacks as its first four:
    A, B, C, D = model.matrices(rho)."""

    A: np.ndarray
    B: np.ndarray
    C: np.ndarray
    D: np.ndarray
    C1: np.ndarray
    D1: np.ndarray
    offset: np.ndarray
    state_offset: np.ndarray
    rho: np.ndarray
    uncertainty: str

    def __iter__(self) -> Iterator[np.ndarray]:
        return iter((self.A, self.B, self.C, self.D))

    def _summary(self) -> List[Tuple[str, object]]:
        nx, nu = self.B.shape
        rho = [("rho", [float(r) for r in self.rho])] if self.rho.size else []
        return [("nx", nx), ("nu", nu), ("ny", self.C.shape[0]), ("nz", self.C1.shape[0])] + rho + [
            ("uncertainty", self.uncertainty)]


def _float(x, where: str) -> float:
    """One number of a model document as the program's floating reader
    takes it: the nearest double of its exact value (a JSON number, text
    "0.1", "-2.5e-3" or "p/q", a Fraction, a numpy scalar)."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (str, numbers.Real)):
        raise LpvidTypeError(f"{where}: {x!r} is not a number")
    try:
        if isinstance(x, str):
            p, slash, q = x.strip().partition("/")
            value = float(Fraction(p.strip()) / Fraction(q.strip()) if slash else Fraction(p))
        else:
            value = float(x)
    except (ValueError, ZeroDivisionError, OverflowError):
        raise LpvidValueError(f"{where}: {x!r} is not a finite number") from None
    if not math.isfinite(value):
        raise LpvidValueError(f"{where}: {x!r} is not a finite number")
    return value


def _count(document: dict, key: str, lowest: int) -> int:
    """An integer of the document (states, inputs, outputs, nz), in any of
    the format's spellings (2, 2.0, "2")."""
    value = document.get(key)
    number = _float(value, key) if value is not None else None
    if number is None or number != int(number) or number < lowest:
        raise LpvidValueError(f"{key}: expected an integer >= {lowest}, got {value!r}")
    return int(number)


def _matrix(value, rows: int, cols: int, where: str) -> np.ndarray:
    """A rows x cols matrix written as a list of rows ([] when it has no entries)."""
    value = value.tolist() if hasattr(value, "tolist") else value
    if not isinstance(value, (list, tuple)):
        raise LpvidValueError(f"{where}: expected a {rows}x{cols} matrix (a list of rows), got {value!r}")
    out = np.zeros((rows, cols))
    if len(value) == 0 and rows * cols == 0:
        return out
    shape = [len(r) if isinstance(r, (list, tuple)) else None for r in value]
    if len(value) != rows or any(c != cols for c in shape):
        raise LpvidValueError(f"{where}: expected a {rows}x{cols} matrix, got {len(value)} row(s) of "
                              f"{sorted(set(map(str, shape)))} entries")
    for i, row in enumerate(value):
        for j, x in enumerate(row):
            out[i, j] = _float(x, f"{where}[{i}][{j}]")
    return out


def _vector(value, size: int, where: str) -> np.ndarray:
    value = value.tolist() if hasattr(value, "tolist") else value
    if not isinstance(value, (list, tuple)) or len(value) != size:
        raise LpvidValueError(f"{where}: expected a list of {size} numbers, got {value!r}")
    return np.array([_float(x, f"{where}[{i}]") for i, x in enumerate(value)], dtype=float)


def _monomial(text, names: Sequence[str], where: str) -> Tuple[int, ...]:
    """The powers of a basis function ψ(ρ) = Π_k ρ_k^p_k (eq. 9, 10) read
    as the program reads its text: "1", or factors name or name^p (p =
    1..16) joined by "*", spaces allowed around every token, repeated names
    multiplying."""
    if not isinstance(text, str):
        raise LpvidTypeError(f"{where}: a basis function is text such as \"1\" or \"rho1*rho2^2\", not {text!r}")
    powers = [0] * len(names)
    known = f"known: {', '.join(names)}" if names else "the model has no scheduling variables"
    if text.strip() == "1":
        return tuple(powers)
    for factor in text.split("*"):
        name, caret, exponent = (part.strip() for part in factor.partition("^"))
        if not name:
            raise LpvidValueError(f"{where}: basis function {text!r}: an empty factor (powers are written rho^2)")
        if name not in names:
            raise LpvidValueError(f"{where}: basis function {text!r}: unknown scheduling name {name!r} ({known})")
        if caret and not (exponent.isdigit() and exponent.isascii() and 1 <= int(exponent) <= _MAX_POWER):
            raise LpvidValueError(f"{where}: basis function {text!r}: exponent {exponent!r} is not an integer "
                                  f"1..{_MAX_POWER}")
        powers[names.index(name)] += int(exponent) if caret else 1
        if powers[names.index(name)] > _MAX_POWER:
            raise LpvidValueError(f"{where}: basis function {text!r}: total power of {name!r} above {_MAX_POWER}")
    return tuple(powers)


def _psi(powers: Sequence[int], rho: Sequence[float]) -> float:
    """ψ(ρ) = Π_k ρ_k^p_k, multiplied out factor by factor as the program does."""
    value = 1.0
    for k, p in enumerate(powers):
        for _ in range(p):
            value = value * rho[k]
    return value


def _terms(terms, rows: int, cols: int, names: Sequence[str], rho: Sequence[float], where: str,
           scale: float = 1.0, into: Optional[np.ndarray] = None) -> np.ndarray:
    """Σ_j ψ_j(ρ)·(scale·M_j) (eq. 9) of a list of terms {"basis", "value"},
    added term by term to `into` (the program's order of sums) or to zero;
    absent or [] is the zero matrix."""
    out = np.zeros((rows, cols)) if into is None else into
    if terms is None:
        return out
    if not isinstance(terms, (list, tuple)):
        raise LpvidValueError(f"{where}: expected a list of terms {{\"basis\": ..., \"value\": ...}}")
    for j, term in enumerate(terms):
        if not isinstance(term, dict) or "basis" not in term or "value" not in term:
            raise LpvidValueError(f"{where}[{j}]: a term is {{\"basis\": text, \"value\": matrix}}, got {term!r}")
        value = _matrix(term["value"], rows, cols, f"{where}[{j}].value")
        out += _psi(_monomial(term["basis"], names, f"{where}[{j}].basis"), rho) * (scale * value)
    return out


def _correction_terms(document: dict, key: str, names: Sequence[str]) -> list:
    """The correction's fixed A_i or B_i terms (eq. 10), in the order of
    correction.basis (the order the program adds them in)."""
    correction = document.get("correction") or {}
    basis = [_monomial(f, names, f"correction.basis[{i}]") for i, f in enumerate(correction.get("basis") or [])]
    terms = correction.get(key) or []
    where = {}
    for j, term in enumerate(terms):
        f = _monomial(term.get("basis") if isinstance(term, dict) else None, names, f"correction.{key}[{j}].basis")
        if f not in basis:
            raise LpvidValueError(f"correction.{key}[{j}].basis: {term['basis']!r} is not one of correction.basis")
        where[j] = basis.index(f)
    return [terms[j] for j in sorted(where, key=where.get)]


def _basis_sum(block, size: int, names: Sequence[str], rho: Sequence[float], where: str) -> np.ndarray:
    """Σ_j h_j(ρ)·v_j of an offset block {"basis", "values"}; zero without values."""
    out = np.zeros(size)
    if not block or block.get("values") is None:
        return out
    basis, values = block.get("basis") or [], block["values"]
    if len(values) != len(basis):
        raise LpvidValueError(f"{where}.values: {len(values)} vectors for {len(basis)} basis functions")
    for j, (f, v) in enumerate(zip(basis, values)):
        out += _psi(_monomial(f, names, f"{where}.basis[{j}]"), rho) * _vector(v, size, f"{where}.values[{j}]")
    return out


def _uncertainty(document: dict, sizes: Tuple[int, int, int], names: Sequence[str], rho: Sequence[float]):
    """(structure, C1(ρ), D1(ρ)) of the uncertainty channel z = C1 x + D1 u."""
    nx, nu, ny = sizes
    block = document.get("uncertainty") or {}
    structure = block.get("structure", "multiplicative")
    if structure == "general":
        nz = _general_nz(block)
        return (structure, _terms(block.get("C1"), nz, nx, names, rho, "uncertainty.C1"),
                _terms(block.get("D1"), nz, nu, names, rho, "uncertainty.D1"))
    if structure not in ("multiplicative", "additive"):
        raise LpvidValueError(f"uncertainty.structure: {structure!r} is not multiplicative, additive or general")
    weight = _float(block.get("weight", 1), "uncertainty.weight")
    if structure == "additive":
        return structure, np.zeros((nu, nx)), 1.0 * (weight * np.eye(nu))
    initial = document.get("initial") or {}
    return (structure, _terms(initial.get("C"), ny, nx, names, rho, "initial.C", weight),
            _terms(initial.get("D"), ny, nu, names, rho, "initial.D", weight))


def _general_nz(block: dict) -> int:
    """nz of a general channel: its "nz", else the rows of the first C1 (or D1) term's value."""
    if block.get("nz") is not None:
        return _count(block, "nz", 1)
    for key in ("C1", "D1"):
        terms = block.get(key) or []
        if terms and isinstance(terms[0], dict) and len(terms[0].get("value") or []) > 0:
            return len(terms[0]["value"])
    raise LpvidValueError("uncertainty: structure \"general\" needs \"nz\" (or a C1/D1 term with at least one row)")


def _scheduling_value(rho, names: Sequence[str]) -> List[float]:
    """The scheduling value as one float per scheduling variable: a number
    (one variable), a sequence in the order of `scheduling`, or a dict by name."""
    if not names:
        if rho is not None and np.size(rho) != 0:
            raise LpvidValueError(f"rho: the model has no scheduling variables, got rho={rho!r}")
        return []
    if rho is None:
        raise LpvidValueError(f"rho: the model is scheduled on {', '.join(names)}: give rho, one value per "
                              f"scheduling variable")
    if isinstance(rho, dict):
        missing = [n for n in names if n not in rho]
        if missing or len(rho) != len(names):
            raise LpvidValueError(f"rho: expected the keys {list(names)}, got {list(rho)}")
        rho = [rho[n] for n in names]
    values = np.ravel(np.asarray(rho, dtype=object))
    if len(values) != len(names):
        raise LpvidValueError(f"rho: {len(values)} value(s) for {len(names)} scheduling variable(s) "
                              f"({', '.join(names)})")
    return [_float(v, f"rho[{k}]") for k, v in enumerate(values)]


def _names(names: Sequence[str], shown: int = 4) -> str:
    """A list of names as its repr, cut after `shown` names."""
    names = list(names)
    if len(names) <= shown:
        return repr(names)
    return "[" + ", ".join(repr(n) for n in names[:shown - 1]) + f", ... ({len(names)} names)]"


def as_model(model):
    """A Model from a Model, a dict or a model file's path."""
    if isinstance(model, Model):
        return model
    if isinstance(model, dict):
        return Model(model)
    if isinstance(model, (str, os.PathLike)):
        return Model.from_file(model)
    raise LpvidTypeError(f"model: expected an lpvid.Model, a model dict or a model file's path, not "
                         f"{type(model).__name__}")
