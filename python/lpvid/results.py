"""What the functions return: typed results.

Every result keeps the command's whole JSON report (`report`), its exit
code and what it printed (`output`, `messages`); the typed fields are read
from that report. Certified numbers come in two forms: a float for
plotting and printing (`delta`, `dmax`, the upper ends) and an exact
`fractions.Fraction` of the certified square (`delta2`, `dmax2`, interval
ends), the number the certificate states and the verifier checked.

A result shows itself in one line (repr: its key numbers, never the whole
report) and, in Jupyter, as a small table of the same numbers
(_repr_html_). Simulation, Comparison, Tradeoff, Generated and Diagnosis
give their numbers as a pandas DataFrame (to_pandas(); pandas is imported
only then).
"""

import dataclasses
import html
from fractions import Fraction
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from ._errors import LpvidValueError
from ._exact import exact




# -- how a result shows itself: one line (repr) or a small table (Jupyter) -------------------------
_SHOWN_TEXT = 48  # longest text of one value in a summary


def shown(value) -> str:
    """One value of a summary as short text: a float or Fraction with 4
    significant digits, None as "n/a", a list as [item, ...], text longer
    than _SHOWN_TEXT characters cut with "..."."""
    if value is None:
        return "n/a"
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value))
    if isinstance(value, (float, Fraction, np.floating)):
        return f"{float(value):.4g}"
    if isinstance(value, (list, tuple)):
        value = "[" + ", ".join(shown(v) for v in value) + "]"
    text = str(value)
    return text if len(text) <= _SHOWN_TEXT else text[:_SHOWN_TEXT - 3] + "..."


def summary_repr(name: str, pairs: Sequence[Tuple[str, object]]) -> str:
    """`<lpvid.Name label=value, ...>` on one line."""
    return f"<lpvid.{name} " + ", ".join(f"{k}={shown(v)}" for k, v in pairs) + ">"


def summary_html(name: str, pairs: Sequence[Tuple[str, object]]) -> str:
    """The same pairs as a small HTML table (Jupyter's _repr_html_)."""
    rows = "".join(f"<tr><th style=\"text-align:left\">{html.escape(k)}</th><td>{html.escape(shown(v))}</td></tr>"
                   for k, v in pairs)
    return f"<table><caption>lpvid.{html.escape(name)}</caption>{rows}</table>"


class Summarised:
    """A compact repr (one line of key numbers, never the whole report) and
    a small HTML table of the same numbers for Jupyter, both made from the
    (label, value) pairs of _summary(); labels are attribute names."""

    def _summary(self) -> List[Tuple[str, object]]:
        return []

    def __repr__(self) -> str:
        return summary_repr(type(self).__name__, self._summary())

    def _repr_html_(self) -> str:
        return summary_html(type(self).__name__, self._summary())


def _pandas(what: str):
    """pandas, imported when a to_pandas() needs it."""
    try:
        import pandas
    except ImportError:
        raise ImportError(f"{what} needs pandas, which is not installed (pip install pandas; Debian: "
                          f"apt install python3-pandas)") from None
    return pandas


def _range(values: Sequence[Optional[float]]) -> Optional[str]:
    """"lo..hi" of the values that are not None (one value: itself)."""
    have = [float(v) for v in values if v is not None]
    if not have:
        return None
    lo, hi = min(have), max(have)
    return f"{lo:.4g}" if lo == hi else f"{lo:.4g}..{hi:.4g}"


@dataclasses.dataclass(repr=False)
class Interval(Summarised):
    """The certified interval [lower, upper] of a minimisation's optimum
    (`of`: "dmax^2", "delta^2" or the weighted objective). Ends are exact;
    an end that could not be certified is None."""

    of: str
    lower: Optional[Fraction]
    upper: Optional[Fraction]
    lower_verified: bool
    upper_verified: bool
    relative_gap: Optional[float]
    lower_certificate: Optional[object] = None  # a Certificate
    note: str = ""

    @classmethod
    def from_report(cls, d, certificates):
        if not isinstance(d, dict):
            return None
        lower = exact(d.get("lower_exact")) if d.get("lower_verified") else None
        upper = exact(d.get("upper_exact")) if d.get("upper_verified") else None
        return cls(of=d.get("of", ""), lower=lower, upper=upper, lower_verified=bool(d.get("lower_verified")),
                   upper_verified=bool(d.get("upper_verified")), relative_gap=d.get("relative_gap"),
                   lower_certificate=certificates.get(d.get("lower_certificate")), note=d.get("note", ""))

    def __contains__(self, x):
        x = Fraction(x)
        return (self.lower is None or self.lower <= x) and (self.upper is None or x <= self.upper)

    def _summary(self) -> List[Tuple[str, object]]:
        return [("of", self.of), ("lower", self.lower), ("upper", self.upper),
                ("lower_verified", self.lower_verified), ("upper_verified", self.upper_verified),
                ("relative_gap", self.relative_gap)]


@dataclasses.dataclass(repr=False)
class Result(Summarised):
    """Common to every result: the command, its exit code (0 or 1: an
    answer), its report and the text it printed. out_dir: the folder the
    files were kept in (None: the call's private folder, removed)."""

    command: str
    code: int
    report: dict
    output: str
    messages: str
    out_dir: Optional[str]

    def _summary(self) -> List[Tuple[str, object]]:
        return [("code", self.code)]

    @property
    def plots(self):
        return getattr(self, "_plots", {})

    def plot(self, name=None):
        """The run's figures as matplotlib Figures, drawn from the same numbers
        as the command line's plots: a dict {plot name: Figure}, or one Figure
        when `name` is given."""
        plots = self.plots
        if not plots:
            raise ValueError(f"{self.command}: this run has no plots")
        if name is not None:
            if name not in plots:
                raise KeyError(f"no plot {name!r}; the plots are {sorted(plots)}")
            return plots[name].figure()
        return {k: p.figure() for k, p in plots.items()}


@dataclasses.dataclass(repr=False)
class Bounds(Result):
    """invalidate / certify: Theorem 2.1 for a fixed model.

    verdict: "consistent" (code 0) or "invalidated" (code 1), or the
    report's status. delta, dmax: certified upper bounds (floats); delta2,
    dmax2: their exact squares (Fractions). interval: the certified
    interval of the minimised objective. certificate: the Certificate of
    the answer; certificates: every certificate the run wrote."""

    verdict: Optional[str] = None
    delta: Optional[float] = None
    dmax: Optional[float] = None
    delta2: Optional[Fraction] = None
    dmax2: Optional[Fraction] = None
    verified: bool = False
    interval: Optional[Interval] = None
    certificate: Optional[object] = None
    certificates: List[object] = dataclasses.field(default_factory=list)

    def _summary(self) -> List[Tuple[str, object]]:
        pairs = [("verdict", self.verdict), ("delta", self.delta), ("dmax", self.dmax), ("verified", self.verified)]
        if self.interval is not None:  # the ends of the certified interval of the objective (interval.of)
            pairs.append(("interval", f"[{shown(self.interval.lower)}, {shown(self.interval.upper)}]"))
        return pairs + [("certificates", len(self.certificates))]

    @property
    def consistent(self):
        return self.code == 0

    @property
    def invalidated(self):
        return self.code == 1


@dataclasses.dataclass(repr=False)
class Identification(Bounds):
    """identify: Theorem 3.1. model: the identified model (a Model, exact,
    the one the bounds are about); theta: the identified correction as the
    report gives it; class_interval: the certified interval over the whole
    model class, when computed."""

    model: Optional[object] = None
    theta: Optional[dict] = None
    class_interval: Optional[dict] = None


@dataclasses.dataclass(repr=False)
class BasisSelection(Bounds):
    """select-basis (the paper's Appendix): the final basis and the steps."""

    basis: Optional[List[str]] = None
    steps: List[dict] = dataclasses.field(default_factory=list)

    def _summary(self) -> List[Tuple[str, object]]:
        return [("basis", self.basis), ("steps", len(self.steps))] + super()._summary()


@dataclasses.dataclass(repr=False)
class TradeoffPoint(Summarised):
    lambda_: float
    delta: Optional[float]
    dmax: Optional[float]
    verified: bool
    certificate: Optional[object] = None

    def _summary(self) -> List[Tuple[str, object]]:
        return [("lambda_", self.lambda_), ("delta", self.delta), ("dmax", self.dmax), ("verified", self.verified)]


@dataclasses.dataclass(repr=False)
class Tradeoff(Result):
    """tradeoff: certified (delta, dmax) for each lambda."""

    points: List[TradeoffPoint] = dataclasses.field(default_factory=list)
    certificates: List[object] = dataclasses.field(default_factory=list)

    def _summary(self) -> List[Tuple[str, object]]:
        p = self.points
        return [("points", len(p)), ("lambda_", _range([q.lambda_ for q in p])),
                ("delta", _range([q.delta for q in p])), ("dmax", _range([q.dmax for q in p])),
                ("verified", f"{sum(bool(q.verified) for q in p)}/{len(p)}")]

    def to_pandas(self):
        """The points as a pandas DataFrame, one row per point.

        Returns
        -------
        pandas.DataFrame
            Columns lambda, delta, dmax (floats; NaN where a point has no
            bound) and verified (bool), in the order of the points.
        """
        pd = _pandas("Tradeoff.to_pandas()")
        nan = (lambda v: np.nan if v is None else float(v))
        return pd.DataFrame({"lambda": [nan(q.lambda_) for q in self.points],
                             "delta": [nan(q.delta) for q in self.points],
                             "dmax": [nan(q.dmax) for q in self.points],
                             "verified": [bool(q.verified) for q in self.points]})


@dataclasses.dataclass(repr=False)
class Diagnosis(Result):
    """diagnose: residual -> missing effect -> re-fitted model.

    model: the model after diagnosis (a Model); effects: the effects added
    (the report's list); rms_before / rms_after and fit_before / fit_after:
    the test record's free-run RMS error and fit % (None without a test
    record); after_worse: the model after scores a larger test RMS than the
    model before (stated, never used to choose); test_range: per signal of
    the test record, its range against the estimation record's (the
    report's list: signal, role, estimation_range, test_range,
    samples_below, samples_above, outside_percent, beyond_width); delta,
    dmax: the after model's certified bounds (largest over the bound
    windows); certificates: every certificate written."""

    model: Optional[object] = None
    effects: list = dataclasses.field(default_factory=list)
    rms_before: Optional[float] = None
    rms_after: Optional[float] = None
    fit_before: Optional[float] = None
    fit_after: Optional[float] = None
    after_worse: Optional[bool] = None
    test_range: list = dataclasses.field(default_factory=list)
    delta: Optional[float] = None
    dmax: Optional[float] = None
    verified: bool = False
    certificates: List[object] = dataclasses.field(default_factory=list)

    def effect_kinds(self) -> List[str]:
        """The kind of each effect added, in order ("output_offset", ...)."""
        return [str(e.get("kind", "?")) if isinstance(e, dict) else str(e) for e in self.effects]

    def _summary(self) -> List[Tuple[str, object]]:
        return [("effects", self.effect_kinds() or "none"), ("rms_before", self.rms_before),
                ("rms_after", self.rms_after), ("fit_before", self.fit_before), ("fit_after", self.fit_after),
                ("delta", self.delta), ("dmax", self.dmax), ("verified", self.verified),
                ("after_worse", self.after_worse), ("certificates", len(self.certificates))]

    def to_pandas(self):
        """A one-row summary as a pandas DataFrame (the report of diagnose
        holds no per-sample series: its plots' data are in plot()).

        Returns
        -------
        pandas.DataFrame
            One row, columns effects (the kinds joined by ", "),
            rms_before, rms_after, fit_before, fit_after (the test record's
            free-run RMS and fit %; NaN without a test record), delta, dmax
            (the after model's certified bounds), verified, after_worse.
        """
        pd = _pandas("Diagnosis.to_pandas()")
        nan = (lambda v: np.nan if v is None else float(v))
        row = {"effects": ", ".join(self.effect_kinds()), "rms_before": nan(self.rms_before),
               "rms_after": nan(self.rms_after), "fit_before": nan(self.fit_before),
               "fit_after": nan(self.fit_after), "delta": nan(self.delta), "dmax": nan(self.dmax),
               "verified": bool(self.verified), "after_worse": self.after_worse}
        return pd.DataFrame([row])


@dataclasses.dataclass(repr=False)
class ModelScore(Summarised):
    """One model's score in a comparison."""

    name: str
    rms: float
    fit_percent: float
    outputs: List[dict]
    yhat: Optional[np.ndarray] = None

    def _summary(self) -> List[Tuple[str, object]]:
        return [("name", self.name), ("rms", self.rms), ("fit_percent", self.fit_percent)]


@dataclasses.dataclass(repr=False)
class Comparison(Result):
    """compare: each model's free-run (or k-step) output against the
    measured output. scores: one ModelScore per model, in the given order;
    y: the measured output (samples x outputs)."""

    scores: List[ModelScore] = dataclasses.field(default_factory=list)
    y: Optional[np.ndarray] = None
    table: Optional[Dict[str, np.ndarray]] = None

    def score(self, name):
        return next(s for s in self.scores if s.name == name)

    @property
    def outputs(self) -> List[str]:
        """The names of the measured outputs, in the order of y's columns."""
        named = [o.get("name") for o in (self.scores[0].outputs if self.scores else []) if isinstance(o, dict)]
        width = 0 if self.y is None else self.y.shape[1]
        return named if len(named) == width and all(named) else [f"y{j + 1}" for j in range(width)]

    def _summary(self) -> List[Tuple[str, object]]:
        return [("models", len(self.scores)), ("samples", None if self.y is None else self.y.shape[0]),
                ("rms", [f"{s.name} {shown(s.rms)}" for s in self.scores]),
                ("fit_percent", [f"{s.name} {shown(s.fit_percent)}" for s in self.scores])]

    def to_pandas(self):
        """The measured output and each model's output as a pandas DataFrame.

        Returns
        -------
        pandas.DataFrame
            One row per sample of the record (index "sample": the data
            row), a column per measured output (named by the output) and a
            column "<model>:<output>" per model and output (its free-run or
            k-step output yhat).
        """
        pd = _pandas("Comparison.to_pandas()")
        if self.y is None:
            raise LpvidValueError("Comparison.to_pandas(): this comparison holds no series (the run wrote no table)")
        outs = self.outputs
        columns = {o: self.y[:, j] for j, o in enumerate(outs)}
        for s in self.scores:
            if s.yhat is not None:
                columns.update({f"{s.name}:{o}": s.yhat[:, j] for j, o in enumerate(outs)})
        rows = (self.table or {}).get("row")
        index = (np.asarray(rows, dtype=np.int64) if rows is not None and len(rows) == self.y.shape[0]
                 else np.arange(self.y.shape[0]))
        return pd.DataFrame(columns, index=pd.Index(index, name="sample"))


def _time_index(pd, samples: int, sample_time: Optional[float]):
    """Time in seconds (index "time [s]") when the sample time is known,
    else the sample number (index "sample")."""
    if sample_time is None:
        return pd.RangeIndex(samples, name="sample")
    return pd.Index(np.arange(samples) * float(sample_time), name="time [s]")


@dataclasses.dataclass(repr=False)
class Simulation(Summarised):
    """simulate: the model's output y (samples x outputs, the offset
    included) and the uncertainty channel's input z (samples x nz);
    columns: the names of the run's table (<output>_hat, then z1, ...);
    sample_time: the model's seconds between samples, when it states it."""

    y: np.ndarray
    z: np.ndarray
    columns: List[str]
    sample_time: Optional[float] = None

    @property
    def outputs(self) -> List[str]:
        """The model's output names (the columns <output>_hat of the run)."""
        names = [c[:-len("_hat")] for c in self.columns if c.endswith("_hat")]
        return names if len(names) == self.y.shape[1] else [f"y{j + 1}" for j in range(self.y.shape[1])]

    def _summary(self) -> List[Tuple[str, object]]:
        nz = self.z.shape[1] if self.z.ndim == 2 else 0
        return [("samples", self.y.shape[0]), ("outputs", self.outputs), ("nz", nz),
                ("sample_time", self.sample_time)]

    def to_pandas(self, z: bool = False):
        """The simulated output as a pandas DataFrame.

        Parameters
        ----------
        z : bool
            Also give the uncertainty channel's input z (columns z1, ...).

        Returns
        -------
        pandas.DataFrame
            One column per output, named by the model's output names; the
            index is the time in seconds ("time [s]", sample k at
            k * sample_time) when the sample time is known, else the sample
            number ("sample").
        """
        pd = _pandas("Simulation.to_pandas()")
        frame = pd.DataFrame(self.y, columns=self.outputs, index=_time_index(pd, self.y.shape[0], self.sample_time))
        if z and self.z.size:
            names = [c for c in self.columns if not c.endswith("_hat")]
            names = names if len(names) == self.z.shape[1] else [f"z{j + 1}" for j in range(self.z.shape[1])]
            for j, name in enumerate(names):
                frame[name] = self.z[:, j]
        return frame


@dataclasses.dataclass(repr=False)
class Generated(Result):
    """generate: the data set (a dict column -> array), and when written
    the validation record, the initial model and the true model."""

    data: Optional[Dict[str, np.ndarray]] = None
    validation: Optional[Dict[str, np.ndarray]] = None
    model: Optional[object] = None
    truth: Optional[object] = None
    files: Dict[str, bytes] = dataclasses.field(default_factory=dict)

    def _summary(self) -> List[Tuple[str, object]]:
        data = self.data or {}
        samples = len(next(iter(data.values()))) if data else 0
        pairs = [("samples", samples), ("columns", list(data))]
        if self.validation:
            pairs.append(("validation", len(next(iter(self.validation.values())))))
        return pairs + [("model", self.model is not None), ("truth", self.truth is not None),
                        ("files", len(self.files))]

    def to_pandas(self, part: str = "data"):
        """The generated data set as a pandas DataFrame.

        Parameters
        ----------
        part : {"data", "validation"}
            The data set (default) or the validation record (effect-case).

        Returns
        -------
        pandas.DataFrame
            One column per column of the data file, one row per sample
            (index "sample").
        """
        pd = _pandas("Generated.to_pandas()")
        if part not in ("data", "validation"):
            raise LpvidValueError(f"Generated.to_pandas(part={part!r}): part is \"data\" or \"validation\"")
        table = self.data if part == "data" else self.validation
        if not table:
            raise LpvidValueError(f"Generated.to_pandas(part={part!r}): this run wrote no {part} file")
        samples = len(next(iter(table.values())))
        return pd.DataFrame(dict(table), index=pd.RangeIndex(samples, name="sample"))


@dataclasses.dataclass(repr=False)
class OracleRun(Result):
    """oracle: the outside command judged against lpvid on random cases."""

    cases: List[dict] = dataclasses.field(default_factory=list)
    passed: Optional[bool] = None

    def _summary(self) -> List[Tuple[str, object]]:
        return [("cases", len(self.cases)), ("passed", self.passed), ("code", self.code)]
