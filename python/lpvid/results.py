"""What the functions return: typed results.

Every result keeps the command's whole JSON report (`report`), its exit
code and what it printed (`output`, `messages`); the typed fields are read
from that report. Certified numbers come in two forms: a float for
plotting and printing (`delta`, `dmax`, the upper ends) and an exact
`fractions.Fraction` of the certified square (`delta2`, `dmax2`, interval
ends), the number the certificate states and the verifier checked.
"""

import dataclasses
from fractions import Fraction
from typing import Dict, List, Optional

import numpy as np


def exact(text):
    """An exact number of a report ("0.0123" or "p/q") as a Fraction."""
    return None if text is None else Fraction(str(text))


@dataclasses.dataclass
class Interval:
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


@dataclasses.dataclass
class Result:
    """Common to every result: the command, its exit code (0 or 1: an
    answer), its report and the text it printed. out_dir: the folder the
    files were kept in (None: the call's private folder, removed)."""

    command: str
    code: int
    report: dict
    output: str
    messages: str
    out_dir: Optional[str]

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


@dataclasses.dataclass
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

    @property
    def consistent(self):
        return self.code == 0

    @property
    def invalidated(self):
        return self.code == 1


@dataclasses.dataclass
class Identification(Bounds):
    """identify: Theorem 3.1. model: the identified model (a Model, exact,
    the one the bounds are about); theta: the identified correction as the
    report gives it; class_interval: the certified interval over the whole
    model class, when computed."""

    model: Optional[object] = None
    theta: Optional[dict] = None
    class_interval: Optional[dict] = None


@dataclasses.dataclass
class BasisSelection(Bounds):
    """select-basis (the paper's Appendix): the final basis and the steps."""

    basis: Optional[List[str]] = None
    steps: List[dict] = dataclasses.field(default_factory=list)


@dataclasses.dataclass
class TradeoffPoint:
    lambda_: float
    delta: Optional[float]
    dmax: Optional[float]
    verified: bool
    certificate: Optional[object] = None


@dataclasses.dataclass
class Tradeoff(Result):
    """tradeoff: certified (delta, dmax) for each lambda."""

    points: List[TradeoffPoint] = dataclasses.field(default_factory=list)
    certificates: List[object] = dataclasses.field(default_factory=list)


@dataclasses.dataclass
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


@dataclasses.dataclass
class ModelScore:
    """One model's score in a comparison."""

    name: str
    rms: float
    fit_percent: float
    outputs: List[dict]
    yhat: Optional[np.ndarray] = None


@dataclasses.dataclass
class Comparison(Result):
    """compare: each model's free-run (or k-step) output against the
    measured output. scores: one ModelScore per model, in the given order;
    y: the measured output (samples x outputs)."""

    scores: List[ModelScore] = dataclasses.field(default_factory=list)
    y: Optional[np.ndarray] = None
    table: Optional[Dict[str, np.ndarray]] = None

    def score(self, name):
        return next(s for s in self.scores if s.name == name)


@dataclasses.dataclass
class Simulation:
    """simulate: the model's output y (samples x outputs, the offset
    included) and the uncertainty channel's input z (samples x nz)."""

    y: np.ndarray
    z: np.ndarray
    columns: List[str]


@dataclasses.dataclass
class Generated(Result):
    """generate: the data set (a dict column -> array), and when written
    the validation record, the initial model and the true model."""

    data: Optional[Dict[str, np.ndarray]] = None
    validation: Optional[Dict[str, np.ndarray]] = None
    model: Optional[object] = None
    truth: Optional[object] = None
    files: Dict[str, bytes] = dataclasses.field(default_factory=dict)


@dataclasses.dataclass
class OracleRun(Result):
    """oracle: the outside command judged against lpvid on random cases."""

    cases: List[dict] = dataclasses.field(default_factory=list)
    passed: Optional[bool] = None
