"""Models on records: fit_linear (an LTI model by least squares), simulate
(a model's free run), compare (models scored on one record), each one
`lpvid` command run in-process."""

from __future__ import annotations

import os
from typing import Any, Optional, Sequence, Union

import numpy as np

from ._command_files import read_figures, read_report
from ._docs import shared_doc
from ._errors import LpvidTypeError, LpvidValueError
from ._files import existing_path, number_text, read_table, signal_names, write_model
from ._inputs import (_record_signals, as_names, data_files, generic_names, is_names, record_names, signal_table, width,
                      write_table)
from ._invoke import raise_unless_answer, run
from ._signature import model_first
from ._types import ArrayLike, Data, ModelLike, ModelsLike, PathLike, Progress, Signals
from ._workspace import workspace
from .model import Model, as_model
from .results import Comparison, ModelScore, Simulation


# -- models on records ----------------------------------------------------------------
@shared_doc
def fit_linear(u: Optional[Union[ArrayLike, str, Sequence[str]]] = None,
               y: Optional[Union[ArrayLike, str, Sequence[str]]] = None, *, data: Optional[Data] = None,
               records: Optional[Sequence[Signals]] = None, order: Optional[Union[int, str]] = None,
               validation: Any = None, out_dir: Optional[PathLike] = None, progress: Optional[Progress] = None,
               quiet: bool = False, **options: Any) -> Model:
    """A linear (LTI) state-space model by least squares (`lpvid
    fit-linear`).

    Parameters
    ----------
    u, y : array_like, or column name(s) with data=
        The input and output signals (1-D or samples × channels). A pandas
        Series or DataFrame gives its name(s) to the model's columns. With
        data=, u and y are the column names to use.
    data : path, list of paths, DataFrame or dict, optional
        A data file (several: several records), DataFrame or dict of
        columns, with u=/y= the column names.
    records : list of (u, y) tuples or dicts, optional
        Several records of one plant: one model, each record its own
        initial state (Model.report["records"] lists them).
    order : int >= 1 or "auto", optional
        The state dimension (default: chosen by the command).
    validation : (u_val, y_val) or path, optional
        A record scored after the fit (a file's path with
        validation_columns=["uVal", "yVal"] naming its columns).
    {run}
    {options}
        For fit_linear: offset=True, sample_time=4, units={{"uEst": "V"}},
        init_samples=5, rows=(0, 700), ...

    Returns
    -------
    Model
        The fitted model; its fit report in Model.report.

    {raises}
    """
    with workspace("fit-linear", out_dir) as ws:
        words = []
        if records is not None:
            if u is not None or y is not None or data is not None:
                raise LpvidTypeError("fit_linear(): give the signals one way: u, y arrays, data= or records=")
            record_words, (u, y) = _record_words(ws, records)
            words += record_words
        elif data is not None:
            for path in data_files(ws, {}, None, None, None, data):
                words += ["--data", path]
            if u is not None:
                words += ["--u"] + as_names(u)
            if y is not None:
                words += ["--y"] + as_names(y)
        else:
            if u is None or y is None or is_names(u) or is_names(y):
                raise LpvidTypeError("fit_linear(): give u and y arrays, or data= with u=/y= column names")
            words += ["--data", write_table(os.path.join(ws, "data.csv"), signal_table(u, y))]
            names = _column_names(u, y)
            u, y = names["u"], names["y"]  # from here on: the columns' names
            words += ["--u"] + u + ["--y"] + y
        if validation is not None:
            words += _validation_words(ws, validation, u or "u", y or "y")
        if order is not None:
            words += ["--order", number_text(order)]
        report_path, out_model = os.path.join(ws, "fit-linear.json"), os.path.join(ws, "fit-linear.model.json")
        code, output, messages = run("fit_linear", "fit-linear", words + ["--model-out", out_model, "--report",
                                                                          report_path], options, progress=progress,
                                      quiet=quiet)
        raise_unless_answer(code, output, messages)
        model = Model.from_file(out_model)
        model.report = read_report(report_path)
        return model


def _record_words(ws, records):
    """--data per record of fit_linear(records=...), then --u/--y: every
    record written with the first record's column names (pandas names, or
    u1.., y1..)."""
    if len(records) == 0:
        raise LpvidValueError("records=: no records")
    words, names = [], None
    for k, record in enumerate(records):
        ru, ry, rrho = _record_signals(record, k)
        if ru is None or ry is None or rrho is not None:
            raise LpvidValueError(f"records[{k}]: fit_linear() takes u and y (no rho) in every record")
        checked = signal_table(ru, ry, names=record_names(record, k))  # NaN, shapes, lengths, as the caller wrote
        names = names or _column_names(ru, ry)
        if (width(ru), width(ry)) != (len(names["u"]), len(names["y"])):
            raise LpvidValueError(f"records[{k}]: {width(ru)} input(s) and {width(ry)} output(s), records[0] has "
                                  f"{len(names['u'])} and {len(names['y'])}")
        table = dict(zip(names["u"] + names["y"], checked.values()))
        words += ["--data", write_table(os.path.join(ws, f"data{k + 1}.csv"), table)]
    return words + ["--u"] + names["u"] + ["--y"] + names["y"], (names["u"], names["y"])


def _validation_words(ws, validation, u_names, y_names):
    """--validation: a file's path, or (u_val, y_val) arrays written with the
    estimation columns' names."""
    if isinstance(validation, (str, os.PathLike)):
        return ["--validation", existing_path(validation, "validation")]
    if not isinstance(validation, (tuple, list)) or len(validation) != 2:
        raise LpvidTypeError("validation=: expected (u_val, y_val) arrays or a data file's path")
    checked = signal_table(*validation, names=signal_names("validation", tuple))
    table = dict(zip(as_names(u_names) + as_names(y_names), checked.values()))
    return ["--validation", write_table(os.path.join(ws, "validation.csv"), table)]


def _column_names(u, y, rho=None):
    """{"u": [...], "y": [...], "rho": [...]}: the column names the package
    writes the arrays under (generic_names, each signal avoiding the names
    before it), the same as generic_table's and signal_table's keys."""
    names, taken = {}, []
    for role, values in (("u", u), ("y", y), ("rho", rho)):
        names[role] = generic_names(role, values, taken=taken)
        taken += names[role]
    return names


def _columns(values):
    a = np.asarray(values, dtype=float)
    return [a] if a.ndim == 1 else [a[:, j] for j in range(a.shape[1])]


@model_first(("model", "u", "rho"))
@shared_doc
def simulate(model: ModelLike, *, u: Optional[ArrayLike] = None, rho: Optional[ArrayLike] = None,
             data: Optional[Data] = None, x0: Optional[Sequence] = None, out_dir: Optional[PathLike] = None,
             **options: Any) -> Simulation:
    """The model's free-run output along inputs u and scheduling rho
    (`lpvid simulate`), from the model's x0 or x0=[...].

    Parameters
    ----------
    {model}
    u, rho : array_like, optional
        Input and scheduling signals (keyword only; 1-D or samples ×
        channels).
    data : path, DataFrame or dict, optional
        Instead of u and rho: a data file or table with the model's columns.
    x0 : sequence of numbers, optional
        The initial state (default the model's).
    out_dir : path, optional
        Keep the run's files there.
    {options}

    Returns
    -------
    Simulation
        y (samples × outputs, the offset included), z (the uncertainty
        channel's input), .to_pandas().

    {raises}
    """
    return as_model(model).simulate(u, rho, data=data, x0=x0, out_dir=out_dir, **options)


def _model_files(ws, models):
    """(name, path) per model: models is a list (Models, dicts, paths) or a
    dict {name: model}."""
    one_model = isinstance(models, dict) and "format" in models  # a model dict, not {name: model}
    items = list(models.items()) if isinstance(models, dict) and not one_model else \
        [(None, m) for m in (models if isinstance(models, (list, tuple)) else [models])]
    files, used = [], set()
    for k, (name, m) in enumerate(items):
        if isinstance(m, (str, os.PathLike)) and name is None:
            path = existing_path(m, f"models[{k}]")
            name = os.path.splitext(os.path.basename(path))[0]
        else:
            # the program names a model by its file's stem: a named model's file is ws/<name>.json
            name = name or f"model{k + 1}"
            path = os.path.join(ws, f"{name}.json")
            write_model(as_model(m).document, path)
        if name in used:
            raise LpvidValueError(f"compare(): two models are named {name!r}: give models={{name: model, ...}}")
        used.add(name)
        files.append((name, path))
    return files


@model_first(("u", "y", "models", "rho"), first="models")
@shared_doc
def compare(models: Optional[ModelsLike] = None, *, u: Any = None, y: Any = None, rho: Any = None,
            data: Optional[Data] = None, model: Optional[ModelLike] = None, predict: Optional[int] = None,
            warmup: Optional[int] = None, x0: Optional[str] = None, out_dir: Optional[PathLike] = None,
            progress: Optional[Progress] = None, quiet: bool = False, figures: bool = True,
            **options: Any) -> Comparison:
    """Scores models on a record (`lpvid compare`): each model's free-run
    output (or predict=K: K-step-ahead prediction) against the measured
    output, RMS and fit % per model and output.

    Parameters
    ----------
    models : Model, list of models or dict {{name: model}}
        The models (Models, dicts or model files); the names label the
        table, the series and the figure. model= for one.
    u, y, rho : array_like, or column name(s) with data=
        The record's signals (keyword only). With data=, the column names
        that play the models' input, output and scheduling columns (no
        model is edited).
    data : path, DataFrame or dict, optional
        The record as a file or table.
    predict : int, optional
        K-step-ahead prediction instead of the free run.
    warmup : int, optional
        Fit x0 on the first K rows and score the rest.
    x0 : "model" or "fit", optional
        The initial state: the model's (default) or fitted.
    {run}
    figures : bool, default True
        Keep the figure's data for .plot().
    {options}

    Returns
    -------
    Comparison
        scores (one ModelScore per model: name, rms, fit_percent, outputs,
        yhat), y (measured), .plot(), .to_pandas().

    {raises}
    """
    if models is None:
        models = [model] if model is not None else []
    if not models:
        raise LpvidTypeError("compare(): no model: give the models first, compare(models, u=..., y=...)")
    with workspace("compare", out_dir) as ws:
        words = []
        if data is not None:
            words += ["--data", data_files(ws, {}, None, None, None, data)[0]]
            for name, names in (("u", u), ("y", y), ("rho", rho)):
                if names is not None:
                    words += [f"--{name}"] + as_names(names)
        elif u is not None and y is not None:
            words += ["--data", write_table(os.path.join(ws, "data.csv"), signal_table(u, y, rho))]
            for name, columns in _column_names(u, y, rho).items():
                if columns:
                    words += [f"--{name}"] + columns
        else:
            raise LpvidTypeError("compare(): give u and y arrays, or data= (with u=/y= column names when they "
                                 "differ from the models')")
        named = _model_files(ws, models)
        for _, path in named:
            words += ["--model", path]
        for flag, value in (("--predict", predict), ("--warmup", warmup)):
            if value is not None:
                words += [flag, number_text(value)]
        if x0 is not None:
            if x0 not in ("model", "fit"):
                raise LpvidValueError(f"x0={x0!r}: compare() takes x0=\"model\" (the model's initial state) or "
                                      f"x0=\"fit\" (fitted on the record)")
            words += ["--x0", x0]
        report_path, series = os.path.join(ws, "compare.json"), os.path.join(ws, "compare.csv")
        words += ["--report", report_path, "--out", series]
        if figures:
            words += ["--plots", ws]  # the figure is ws/compare.png
        code, output, messages = run("compare", "compare", words, options, progress=progress, quiet=quiet,
                                      pngs=out_dir is not None)
        raise_unless_answer(code, output, messages)
        report = read_report(report_path)
        table = read_table(series) if os.path.isfile(series) else {}
        result = Comparison(command="compare", code=code, report=report, output=output, messages=messages,
                            out_dir=ws if out_dir is not None else None, table=table)
        _fill_scores(result, report, table, [n for n, _ in named])
        result._plots = read_figures(ws) if figures else {}
        return result


def _fill_scores(result, report, table, names):
    """Scores per model from the report (one model: the report itself;
    several: its "models" list) and their series from the CSV (measured
    column <out>; one model: <out>_model, several: <name>.yhat.<out>)."""
    entries = report.get("models") if isinstance(report.get("models"), list) else [report]
    one = len(entries) == 1
    outs = [o.get("name") for o in (entries[0].get("outputs") or [])] if entries else []
    stack = (lambda keys: np.column_stack([table[c] for c in keys]) if keys and all(c in table for c in keys)
             else None)
    result.y = stack(outs)
    for k, entry in enumerate(entries):
        name = entry.get("name") or (names[k] if k < len(names) else f"model{k + 1}")
        keys = [f"{o}_model" if one else f"{name}.yhat.{o}" for o in outs]
        result.scores.append(ModelScore(name=names[k] if one and k < len(names) else name, rms=entry.get("rms"),
                                        fit_percent=entry.get("fit_percent"), outputs=entry.get("outputs") or [],
                                        yhat=stack(keys)))
