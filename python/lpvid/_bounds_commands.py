"""Theorem 2.1 and 3.1 of "Robust identification and invalidation of LPV
systems" as functions: invalidate, certify, identify, select_basis,
tradeoff (one `lpvid` command each, run in-process on the caller's arrays,
tables or files)."""

from __future__ import annotations

import os
from typing import Any, Optional, Sequence

from ._command_files import (bound_words, data_words, model_file, read_certificates, read_figures, read_report,
                             remove_earlier_outputs)
from ._docs import shared_doc
from ._files import number_text, read_json
from ._inputs import data_files
from ._invoke import raise_unless_answer, run
from ._signature import LEGACY, model_first
from ._types import ArrayLike, Data, ExactNumber, ModelLike, PathLike, Progress, Signals
from ._workspace import workspace
from .model import Model
from .results import BasisSelection, Bounds, Identification, Interval, Tradeoff, TradeoffPoint, exact


# -- Theorem 2.1 and 3.1 ----------------------------------------------------------
def _fill_bounds(result, report, certs):
    result.verdict = report.get("verdict", report.get("status"))
    result.delta, result.dmax = report.get("delta"), report.get("dmax")
    result.delta2, result.dmax2 = exact(report.get("delta2_exact")), exact(report.get("dmax2_exact"))
    result.verified = bool(report.get("verified"))
    result.interval = Interval.from_report(report.get("interval"), certs)
    result.certificate = certs.get(report.get("certificate"))
    result.certificates = list(certs.values())


def _bounds_command(function, command, cls, u, y, rho, model, bounds, *, data, records, x0, out_dir, progress,
                    quiet, options, model_out=False):
    keep = out_dir is not None
    with workspace(command, out_dir) as ws:
        report_path = os.path.join(ws, f"{command}.json")
        out_model = os.path.join(ws, f"{command}.model.json") if model_out else None
        remove_earlier_outputs(report_path, out_model)  # first: a refused call leaves no earlier result
        model_path = model_file(ws, model)
        model_doc = read_json(model_path)
        paths = data_files(ws, model_doc, u, y, rho, data, records)
        words = data_words(paths, x0) + ["--model", model_path, "--report", report_path,
                                          "--certificate", os.path.join(ws, f"{command}.cert.json")]
        if out_model:
            words += ["--model-out", out_model]
        code, output, messages = run(function, command, words + bound_words(*bounds), options, progress=progress,
                                      quiet=quiet)
        report = read_report(report_path)
        result = cls(command=command, code=code, report=report, output=output, messages=messages,
                     out_dir=ws if keep else None)
        certs = read_certificates(report, keep)
        _fill_bounds(result, report, certs)
        if out_model and os.path.isfile(out_model):
            result.model = Model.from_file(out_model)
            result.model.report = report
        raise_unless_answer(code, output, messages, result if report else None)
        return result


@model_first(LEGACY)
@shared_doc
def invalidate(model: Optional[ModelLike] = None, *, u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
               rho: Optional[ArrayLike] = None, delta: Optional[ExactNumber] = None, dmax: Optional[ExactNumber] = None,
               lambda_: Optional[ExactNumber] = None, data: Optional[Data] = None,
               records: Optional[Sequence[Signals]] = None,
               x0: Optional[Sequence] = None, out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
               quiet: bool = False, **options: Any) -> Bounds:
    """Theorem 2.1 for a fixed model (`lpvid invalidate`): is the model,
    with an uncertainty ||Delta|| <= delta and a noise of RMS <= dmax,
    consistent with the data (eq. 8-9 of "Robust identification and
    invalidation of LPV systems")?

    Parameters
    ----------
    {model}
    {signals}
    {bounds}
    {run}
    {options}

    Returns
    -------
    Bounds
        verdict, delta, dmax (floats: the certified upper ends), delta2,
        dmax2 (exact Fractions), interval, certificate. code 0: consistent
        (bounds found and verified), 1: invalidated (checked exactly).

    {raises}

    Examples
    --------
    >>> r = lpvid.invalidate(model, u=u, y=y, rho=rho, delta="1/100")  # doctest: +SKIP
    >>> r.dmax, lpvid.verify(r.certificate).ok                          # doctest: +SKIP
    """
    return _bounds_command("invalidate", "invalidate", Bounds, u, y, rho, model, (delta, dmax, lambda_), data=data,
                           records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet, options=options)


@model_first(LEGACY)
@shared_doc
def certify(model: Optional[ModelLike] = None, *, u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
            rho: Optional[ArrayLike] = None, delta: Optional[ExactNumber] = None, dmax: Optional[ExactNumber] = None,
            lambda_: Optional[ExactNumber] = None, data: Optional[Data] = None,
            records: Optional[Sequence[Signals]] = None,
            x0: Optional[Sequence] = None, out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
            quiet: bool = False, **options: Any) -> Bounds:
    """`lpvid certify`: Theorem 2.1's bounds with the certificate written in
    the form the options choose (toeplitz="paper", dense_dual=True, ...).

    Parameters
    ----------
    {model}
    {signals}
    {bounds}
    {run}
    {options}

    Returns
    -------
    Bounds
        As for invalidate.

    {raises}
    """
    return _bounds_command("certify", "certify", Bounds, u, y, rho, model, (delta, dmax, lambda_), data=data,
                           records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet, options=options)


@model_first(LEGACY)
@shared_doc
def identify(model: Optional[ModelLike] = None, *, u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
             rho: Optional[ArrayLike] = None, delta: Optional[ExactNumber] = None, dmax: Optional[ExactNumber] = None,
             lambda_: Optional[ExactNumber] = None, data: Optional[Data] = None,
             records: Optional[Sequence[Signals]] = None,
             x0: Optional[Sequence] = None, out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
             quiet: bool = False, **options: Any) -> Identification:
    """Theorem 3.1 (`lpvid identify`, eq. 13-16 of "Robust identification
    and invalidation of LPV systems"): the correction S_C(rho) over the
    model's correction basis ("correction": {{"basis": [...]}}, or
    basis=["1", "rho1"]), with certified bounds of the identified model.

    Parameters
    ----------
    {model}
    {signals}
    {bounds}
    {run}
    {options}

    Returns
    -------
    Identification
        model (the identified Model, exact: the one the bounds are about),
        theta, class_interval (a dict, when computed) and the bounds as for
        invalidate.

    {raises}
    """
    r = _bounds_command("identify", "identify", Identification, u, y, rho, model, (delta, dmax, lambda_), data=data,
                        records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet, options=options,
                        model_out=True)
    r.theta = r.report.get("theta")
    r.class_interval = r.report.get("class_interval")
    return r


@model_first(LEGACY)
@shared_doc
def select_basis(model: Optional[ModelLike] = None, *, u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
                 rho: Optional[ArrayLike] = None, delta: Optional[ExactNumber] = None,
                 dmax: Optional[ExactNumber] = None, data: Optional[Data] = None,
                 records: Optional[Sequence[Signals]] = None, x0: Optional[Sequence] = None,
                 out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
                 quiet: bool = False, **options: Any) -> BasisSelection:
    """The basis-selection algorithm of the Appendix of "Robust
    identification and invalidation of LPV systems" (`lpvid select-basis`):
    grow the correction basis until the model is consistent at (delta,
    dmax), then prune.

    Parameters
    ----------
    {model}
    {signals}
    delta, dmax : exact number
        The bounds the selected basis must reach.
    {run}
    {options}

    Returns
    -------
    BasisSelection
        basis (the final basis), steps (every step), and the bounds.

    {raises}
    """
    r = _bounds_command("select_basis", "select-basis", BasisSelection, u, y, rho, model, (delta, dmax, None),
                        data=data, records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet,
                        options=options)
    r.basis = r.report.get("final_basis")
    r.steps = r.report.get("steps") or []
    return r


@model_first(LEGACY)
@shared_doc
def tradeoff(model: Optional[ModelLike] = None, *, u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
             rho: Optional[ArrayLike] = None, lambdas: Optional[Sequence[ExactNumber]] = None,
             data: Optional[Data] = None, records: Optional[Sequence[Signals]] = None,
             x0: Optional[Sequence] = None, out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
             quiet: bool = False, **options: Any) -> Tradeoff:
    """The certified trade-off between delta and dmax (`lpvid tradeoff`):
    one identification per weight lambda.

    Parameters
    ----------
    {model}
    {signals}
    lambdas : sequence of exact numbers in [0, 1], optional
        The weights of delta^2 (default: the command's own grid).
    {run}
    {options}

    Returns
    -------
    Tradeoff
        points (lambda_, delta, dmax, verified, certificate), .plot() (the
        curve), .to_pandas().

    {raises}
    """
    keep = out_dir is not None
    with workspace("tradeoff", out_dir) as ws:
        report_path = os.path.join(ws, "tradeoff.json")
        remove_earlier_outputs(report_path)
        model_path = model_file(ws, model)
        paths = data_files(ws, read_json(model_path), u, y, rho, data, records)
        words = data_words(paths, x0) + ["--model", model_path, "--report", report_path,
                                          "--certificate", os.path.join(ws, "tradeoff.cert.json"),
                                          "--csv", os.path.join(ws, "tradeoff.csv"),
                                          "--plots", ws]
        if lambdas is not None:
            words += ["--lambdas"] + [number_text(v) for v in lambdas]
        code, output, messages = run("tradeoff", "tradeoff", words, options, own=("lambdas",), progress=progress,
                                      quiet=quiet, pngs=keep)
        report = read_report(report_path)
        certs = read_certificates(report, keep)
        result = Tradeoff(command="tradeoff", code=code, report=report, output=output, messages=messages,
                          out_dir=ws if keep else None, certificates=list(certs.values()))
        for p in report.get("points") or []:
            result.points.append(TradeoffPoint(lambda_=p.get("lambda"), delta=p.get("delta"), dmax=p.get("dmax"),
                                               verified=bool(p.get("verified")),
                                               certificate=certs.get(p.get("certificate"))))


        result._plots = read_figures(ws)
        raise_unless_answer(code, output, messages, result if report else None)
        return result
