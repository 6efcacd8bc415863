"""diagnose: residual -> missing effect -> re-fitted model, with the error
before and after on a test record (`lpvid diagnose`, in-process)."""

from __future__ import annotations

import os
from typing import Any, Optional, Sequence

from ._command_files import (bound_words, data_words, model_file, read_certificates, read_figures, read_report,
                             remove_earlier_outputs)
from ._docs import shared_doc
from ._errors import LpvidTypeError
from ._files import existing_path, read_json, signal_names, write_data
from ._inputs import data_files
from ._invoke import raise_unless_answer, run
from ._signature import LEGACY, model_first
from ._types import ArrayLike, Data, ExactNumber, ModelLike, PathLike, Progress, Signals
from ._workspace import workspace
from .model import Model
from .results import Diagnosis


# -- diagnose -----------------------------------------------------------------------
def _test_files(ws, model_doc, test):
    """The test record(s) of diagnose: (u, y[, rho]) arrays or a list of
    them, a path or a list of paths."""
    if test is None:
        return []
    if isinstance(test, (str, os.PathLike)):
        return [existing_path(test, "test")]
    one = isinstance(test, tuple)
    if one:
        test = [test]
    elif not isinstance(test, list):
        raise LpvidTypeError(f"test: expected (u, y[, rho]) arrays, a data file's path or a list of them, not "
                             f"{type(test).__name__}")
    paths = []
    for k, t in enumerate(test):
        label = "test" if one else f"test[{k}]"
        if isinstance(t, (str, os.PathLike)):
            paths.append(existing_path(t, label))
            continue
        if not isinstance(t, (tuple, list)) or len(t) not in (2, 3):
            raise LpvidTypeError(f"{label}: expected (u, y) or (u, y, rho) arrays or a data file's path")
        paths.append(os.path.join(ws, f"test{k + 1}.csv"))
        write_data(paths[-1], model_doc, t[0], t[1], t[2] if len(t) == 3 else None,
                   names=signal_names(label, tuple))
    return paths


@model_first(LEGACY)
@shared_doc
def diagnose(model: Optional[ModelLike] = None, *, u: Optional[ArrayLike] = None, y: Optional[ArrayLike] = None,
             rho: Optional[ArrayLike] = None, test: Any = None,
             delta: Optional[ExactNumber] = None, dmax: Optional[ExactNumber] = None,
             lambda_: Optional[ExactNumber] = None, data: Optional[Data] = None,
             records: Optional[Sequence[Signals]] = None, x0: Optional[Sequence] = None,
             out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
             quiet: bool = False, figures: bool = True, **options: Any) -> Diagnosis:
    """Residual -> missing effect -> re-fitted model (`lpvid diagnose`),
    with the error before and after on a test record and verified bounds
    on windows of the estimation record.

    Parameters
    ----------
    {model}
    {signals}
    test : tuple, list of tuples, path or list of paths, optional
        The test record, scored once after the selection and never used to
        fit or choose: (u_test, y_test) or (u_test, y_test, rho_test)
        arrays, a list of such tuples, or a data file's path (with
        test_columns=[["uVal", "yVal"]] for other columns of it).
    {bounds}
    {run}
    figures : bool, default True
        Keep the figures' data (residual, autocorrelation, output, record,
        test) for .plot().
    {options}
        For diagnose: holdout=0.3, max_effects=2, window_length=100,
        warmup=50, benchmark="cascaded-tanks", threads=2, ...

    Returns
    -------
    Diagnosis
        model (the Model after), effects, rms_before/rms_after and
        fit_before/fit_after on the test record, after_worse, test_range,
        delta, dmax (the after model's certified bounds), certificates,
        plot(), to_pandas().

    {raises}
    """
    keep = out_dir is not None
    with workspace("diagnose", out_dir) as ws:
        report_path = os.path.join(ws, "diagnose.json")
        out_model = os.path.join(ws, "diagnose.model.json")
        remove_earlier_outputs(report_path, out_model)
        model_path = model_file(ws, model)
        model_doc = read_json(model_path)
        paths = data_files(ws, model_doc, u, y, rho, data, records)
        words = data_words(paths, x0) + ["--model", model_path, "--report", report_path, "--model-out", out_model]
        tests = _test_files(ws, model_doc, test)
        if tests:
            words += ["--test"] + tests
        if figures:
            words += ["--plots", os.path.join(ws, "plots")]
        code, output, messages = run("diagnose", "diagnose", words + bound_words(delta, dmax, lambda_), options,
                                      progress=progress, quiet=quiet, pngs=keep)
        report = read_report(report_path)
        certs = read_certificates(report, keep)
        result = Diagnosis(command="diagnose", code=code, report=report, output=output, messages=messages,
                           out_dir=ws if keep else None, certificates=list(certs.values()),
                           effects=report.get("effects") or [])


        _fill_diagnosis(result, report)
        if os.path.isfile(out_model):
            result.model = Model.from_file(out_model)
            result.model.report = report
        result._plots = read_figures(os.path.join(ws, "plots")) if figures else {}
        raise_unless_answer(code, output, messages, result if report else None)
        return result


def _fill_diagnosis(result, report):
    t = report.get("test") if isinstance(report.get("test"), dict) else None
    if t:
        result.rms_before, result.rms_after = t.get("rms_before"), t.get("rms_after")
        result.fit_before, result.fit_after = t.get("fit_percent_before"), t.get("fit_percent_after")
        result.after_worse, result.test_range = t.get("after_worse"), t.get("range") or []
    after = report.get("after") if isinstance(report.get("after"), dict) else {}
    result.delta, result.dmax = after.get("delta"), after.get("dmax")
    result.verified = bool(after.get("verified"))
