"""One function per command of `lpvid`, on arrays, DataFrames, Model
objects and files.

Each call checks its keyword options against the command's own options
(with "did you mean"), writes its inputs into a private folder (or the
caller's out_dir), runs the same code as the command line in this process,
reads what the run wrote (report, model, certificates with their data,
plot tables) into the result, and removes the private folder. Exit codes 0
and 1 are answers; any other code raises LpvidError with lpvid's message.
"""

import os

import numpy as np

from ._errors import EXIT_CODES, LpvidError
from ._files import number_text, read_json, read_table, write_data, write_model
from ._inputs import _record_signals, as_names, data_files, generic_names, generic_table, is_names, width, write_table
from ._invoke import FILES, raise_unless_answer, run
from ._simulate import simulate_document
from ._workspace import read_bytes, workspace
from .certificate import Certificate
from .model import Model, as_model
from .results import (BasisSelection, Bounds, Comparison, Diagnosis, Generated, Identification, Interval, ModelScore,
                      OracleRun, Result, Simulation, Tradeoff, TradeoffPoint, exact)

# -- running -------------------------------------------------------------------


def _report(path):
    return read_json(path) if os.path.isfile(path) else {}


def _certificates(report, keep):
    """{path as the report names it: Certificate} for every certificate file
    the report names (keys mentioning "certificate"), in report order."""
    found = {}
    for path in _certificate_paths(report):
        if os.path.isfile(path):
            found[path] = Certificate.load(path)
            if not keep:
                found[path].path = None
    return found


def _remove_earlier_outputs(report_path, *others):
    """In a kept out_dir: removes what an earlier run of the same command
    wrote there (its report, the certificates in that folder the report
    names, its model): a run that fails must not leave them looking like its
    own results. Files elsewhere are left alone."""
    folder = os.path.dirname(report_path)
    if os.path.isfile(report_path):
        try:
            earlier = read_json(report_path)
        except ValueError:
            earlier = {}
        for path in _certificate_paths(earlier):
            if os.path.dirname(os.path.abspath(path)) == folder and os.path.isfile(path):
                os.remove(path)
        os.remove(report_path)
    for p in others:
        if p and os.path.isfile(p):
            os.remove(p)


def _certificate_paths(report):
    found = []

    def walk(node, key=""):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, k)
        elif isinstance(node, list):
            for v in node:
                walk(v, key)
        elif isinstance(node, str) and "certificate" in key and node not in found:
            found.append(node)

    walk(report)
    return found


def _plots(folder):
    """The plots a run wrote into `folder`, in memory (lpvid.plots)."""
    if not os.path.isdir(folder):
        return {}
    try:
        from .plots import read_plots
    except ImportError:
        return {}
    return read_plots(folder)


def _model_file(folder, model, name="model.json"):
    """The model's file: a path given stays; a Model or dict is written."""
    if isinstance(model, (str, os.PathLike)):
        return os.path.abspath(os.fspath(model))
    path = os.path.join(folder, name)
    write_model(as_model(model).document, path)
    return path


def _x0_text(x0):
    return ",".join(number_text(v) for v in x0)


def _data_words(paths, x0=None):
    """--data P [--x0 V,..] per record; x0: one state vector (one record) or
    one per record."""
    words = []
    per_record = x0 is not None and len(paths) > 1
    for k, path in enumerate(paths):
        words += ["--data", path]
        if x0 is not None and (per_record or k == 0):
            words += ["--x0", _x0_text(x0[k] if per_record else x0)]
    return words


def _bound_words(delta, dmax, lambda_):
    words = []
    for name, value in (("delta", delta), ("dmax", dmax), ("lambda", lambda_)):
        if value is not None:
            words += [f"--{name}", number_text(value)]
    return words


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
        model_path = _model_file(ws, model)
        model_doc = read_json(model_path)
        paths = data_files(ws, model_doc, u, y, rho, data, records)
        report_path = os.path.join(ws, f"{command}.json")
        words = _data_words(paths, x0) + ["--model", model_path, "--report", report_path,
                                          "--certificate", os.path.join(ws, f"{command}.cert.json")]
        out_model = os.path.join(ws, f"{command}.model.json") if model_out else None
        _remove_earlier_outputs(report_path, out_model)
        if out_model:
            words += ["--model-out", out_model]
        code, output, messages = run(function, command, words + _bound_words(*bounds), options, progress=progress,
                                      quiet=quiet)
        report = _report(report_path)
        result = cls(command=command, code=code, report=report, output=output, messages=messages,
                     out_dir=ws if keep else None)
        certs = _certificates(report, keep)
        _fill_bounds(result, report, certs)
        if out_model and os.path.isfile(out_model):
            result.model = Model.from_file(out_model)
            result.model.report = report
        raise_unless_answer(code, output, messages, result if report else None)
        return result


def invalidate(u=None, y=None, rho=None, model=None, *, delta=None, dmax=None, lambda_=None, data=None, records=None,
               x0=None, out_dir=None, progress=None, quiet=False, **options):
    """Theorem 2.1 for a fixed model (`lpvid invalidate`): is the model,
    with an uncertainty ||Delta|| <= delta and a noise of RMS <= dmax,
    consistent with the data?

    u, y, rho: arrays, 1-D (one channel) or 2-D (samples x channels), in
    the order of the model's columns (rho None without scheduling). Or
    data= a data file's path, a DataFrame or a dict of columns named as the
    model's columns. Several records under one Delta: records=[{"u":..,
    "y":.., "rho":..}, ...] or data=[path, path, ...]. model: a Model, an
    lpvid-model/1 dict or a model file's path. x0: the initial state (one
    list; or one per record).
    delta and dmax given: decide consistency at those bounds (code 0
    consistent, 1 invalidated); one of them: minimise the other; neither:
    minimise lambda_*delta^2 + (1-lambda_)*dmax^2. Numbers are exact text:
    0.1 means 1/10.
    options: the other options of `lpvid invalidate --help`, '_' for '-'
    (max_taps=0, solver="sdpa", rows="0:200", delta_norm="kyp").
    out_dir: keep the run's files there (default: nothing is left).
    progress: a function called with each progress line (they also go to
    the logger "lpvid" at level INFO); quiet: no progress lines.
    Returns Bounds. Exit codes other than 0 and 1 raise LpvidError.
    """
    return _bounds_command("invalidate", "invalidate", Bounds, u, y, rho, model, (delta, dmax, lambda_), data=data,
                           records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet, options=options)


def certify(u=None, y=None, rho=None, model=None, *, delta=None, dmax=None, lambda_=None, data=None, records=None,
            x0=None, out_dir=None, progress=None, quiet=False, **options):
    """`lpvid certify`: Theorem 2.1's bounds with the certificate written in
    the form chosen by the options (e.g. toeplitz="paper", dense_dual=True).
    Arguments and result as for invalidate."""
    return _bounds_command("certify", "certify", Bounds, u, y, rho, model, (delta, dmax, lambda_), data=data,
                           records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet, options=options)


def identify(u=None, y=None, rho=None, model=None, *, delta=None, dmax=None, lambda_=None, data=None, records=None,
             x0=None, out_dir=None, progress=None, quiet=False, **options):
    """Theorem 3.1 (`lpvid identify`): the correction S_C(rho) over the
    model's correction basis ("correction": {"basis": [...]}, or
    basis=["1", "rho1"]), with certified bounds of the identified model.

    Arguments as for invalidate; options are those of `lpvid identify
    --help` (iterate=True, method="alternating", free_x0=True, ...).
    Returns an Identification: model (the identified Model, exact, the one
    the bounds are about), theta, class_interval, and the bounds."""
    r = _bounds_command("identify", "identify", Identification, u, y, rho, model, (delta, dmax, lambda_), data=data,
                        records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet, options=options,
                        model_out=True)
    r.theta = r.report.get("theta")
    r.class_interval = r.report.get("class_interval")
    return r


def select_basis(u=None, y=None, rho=None, model=None, *, delta=None, dmax=None, data=None, records=None, x0=None,
                 out_dir=None, progress=None, quiet=False, **options):
    """The basis-selection algorithm of the paper's Appendix (`lpvid
    select-basis`): grow the correction basis until the model is consistent
    at (delta, dmax), then prune. Arguments as for invalidate; options of
    `lpvid select-basis --help` (degree=2, iterate=True, ...). Returns
    a BasisSelection (basis: the final basis; steps: every step)."""
    r = _bounds_command("select_basis", "select-basis", BasisSelection, u, y, rho, model, (delta, dmax, None),
                        data=data, records=records, x0=x0, out_dir=out_dir, progress=progress, quiet=quiet,
                        options=options)
    r.basis = r.report.get("final_basis")
    r.steps = r.report.get("steps") or []
    return r


def tradeoff(u=None, y=None, rho=None, model=None, *, lambdas=None, data=None, records=None, x0=None, out_dir=None,
             progress=None, quiet=False, **options):
    """The certified trade-off between delta and dmax (`lpvid tradeoff`):
    one identification per lambda in `lambdas` (each in [0, 1]). Returns a
    Tradeoff: points (lambda_, delta, dmax, verified, certificate) and
    .plot() (the curve)."""
    keep = out_dir is not None
    with workspace("tradeoff", out_dir) as ws:
        model_path = _model_file(ws, model)
        paths = data_files(ws, read_json(model_path), u, y, rho, data, records)
        report_path = os.path.join(ws, "tradeoff.json")
        _remove_earlier_outputs(report_path)
        words = _data_words(paths, x0) + ["--model", model_path, "--report", report_path,
                                          "--certificate", os.path.join(ws, "tradeoff.cert.json"),
                                          "--csv", os.path.join(ws, "tradeoff.csv"),
                                          "--plots", ws]
        if lambdas is not None:
            words += ["--lambdas"] + [number_text(v) for v in lambdas]
        code, output, messages = run("tradeoff", "tradeoff", words, options, own=("lambdas",), progress=progress,
                                      quiet=quiet)
        report = _report(report_path)
        certs = _certificates(report, keep)
        result = Tradeoff(command="tradeoff", code=code, report=report, output=output, messages=messages,
                          out_dir=ws if keep else None, certificates=list(certs.values()))
        for p in report.get("points") or []:
            result.points.append(TradeoffPoint(lambda_=p.get("lambda"), delta=p.get("delta"), dmax=p.get("dmax"),
                                               verified=bool(p.get("verified")),
                                               certificate=certs.get(p.get("certificate"))))
        result._plots = _plots(ws)
        raise_unless_answer(code, output, messages, result if report else None)
        return result


# -- diagnose -----------------------------------------------------------------------
def _test_files(ws, model_doc, test):
    """The test record(s) of diagnose: (u, y[, rho]) arrays or a list of
    them, a path or a list of paths."""
    if test is None:
        return []
    if isinstance(test, (str, os.PathLike)):
        return [os.path.abspath(os.fspath(test))]
    if isinstance(test, tuple):
        test = [test]
    paths = []
    for k, t in enumerate(test):
        if isinstance(t, (str, os.PathLike)):
            paths.append(os.path.abspath(os.fspath(t)))
            continue
        if not isinstance(t, (tuple, list)) or len(t) not in (2, 3):
            raise LpvidError(2, f"test[{k}]: expected (u, y) or (u, y, rho) arrays or a data file's path")
        paths.append(os.path.join(ws, f"test{k + 1}.csv"))
        write_data(paths[-1], model_doc, t[0], t[1], t[2] if len(t) == 3 else None)
    return paths


def diagnose(u=None, y=None, rho=None, model=None, *, test=None, delta=None, dmax=None, lambda_=None, data=None,
             records=None, x0=None, out_dir=None, progress=None, quiet=False, figures=True, **options):
    """Residual -> missing effect -> re-fitted model (`lpvid diagnose`),
    with the error before and after on a test record and verified bounds
    on windows of the estimation record.

    Arguments as for invalidate. test: the test record, scored once after
    the selection and never used to fit or choose: (u_test, y_test) or
    (u_test, y_test, rho_test) arrays, a list of such tuples, or a data
    file's path (with test_columns=[["uVal", "yVal"]] for other columns of
    it). options: those of `lpvid diagnose --help` (holdout=0.3,
    max_effects=2, window_length=100, warmup=50, benchmark="cascaded-tanks",
    threads=2, ...). figures: draw the plots' data (residual,
    autocorrelation, output, record, test) for .plot().
    Returns a Diagnosis: model (the Model after), effects, rms/fit before
    and after on the test record, delta, dmax, certificates, plot()."""
    keep = out_dir is not None
    with workspace("diagnose", out_dir) as ws:
        model_path = _model_file(ws, model)
        model_doc = read_json(model_path)
        paths = data_files(ws, model_doc, u, y, rho, data, records)
        report_path = os.path.join(ws, "diagnose.json")
        out_model = os.path.join(ws, "diagnose.model.json")
        _remove_earlier_outputs(report_path, out_model)
        words = _data_words(paths, x0) + ["--model", model_path, "--report", report_path, "--model-out", out_model]
        tests = _test_files(ws, model_doc, test)
        if tests:
            words += ["--test"] + tests
        if figures:
            words += ["--plots", os.path.join(ws, "plots")]
        code, output, messages = run("diagnose", "diagnose", words + _bound_words(delta, dmax, lambda_), options,
                                      progress=progress, quiet=quiet)
        report = _report(report_path)
        certs = _certificates(report, keep)
        result = Diagnosis(command="diagnose", code=code, report=report, output=output, messages=messages,
                           out_dir=ws if keep else None, certificates=list(certs.values()),
                           effects=report.get("effects") or [])
        _fill_diagnosis(result, report)
        if os.path.isfile(out_model):
            result.model = Model.from_file(out_model)
            result.model.report = report
        result._plots = _plots(os.path.join(ws, "plots")) if figures else {}
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


# -- models on records ----------------------------------------------------------------
def fit_linear(u=None, y=None, *, data=None, records=None, order=None, validation=None, out_dir=None, progress=None,
               quiet=False, **options):
    """A linear (LTI) state-space model by least squares (`lpvid
    fit-linear`), as a Model (its fit report in Model.report).

    u, y: arrays (1-D or samples x channels); or data= a file, DataFrame
    or dict of columns (or a list of files: several records) with u=/y=
    the column names; or records=[(u1, y1), (u2, y2), ...] (or dicts with
    u, y): several records of one plant, one model, each record its own
    initial state (Model.report["records"] lists them). order: N >= 1 or
    "auto". validation: (u_val, y_val) arrays scored after the fit (or a
    file's path with validation_columns=["uVal", "yVal"] its columns, inputs
    then output).
    options: those of `lpvid fit-linear --help` (offset=True,
    sample_time=4, unit=["uEst=V"], init_samples=5, ...)."""
    with workspace("fit-linear", out_dir) as ws:
        words = []
        if records is not None:
            if u is not None or y is not None or data is not None:
                raise LpvidError(2, "fit_linear(): give the signals one way: u, y arrays, data= or records=")
            words += _record_words(ws, records)
        elif data is not None:
            for path in data_files(ws, {}, None, None, None, data):
                words += ["--data", path]
            if u is not None:
                words += ["--u"] + as_names(u)
            if y is not None:
                words += ["--y"] + as_names(y)
        else:
            if u is None or y is None or is_names(u) or is_names(y):
                raise LpvidError(2, "fit_linear(): give u and y arrays, or data= with u=/y= column names")
            words += ["--data", write_table(os.path.join(ws, "data.csv"), generic_table(u, None, None) |
                                            generic_table(None, y, None))]
            words += ["--u"] + generic_names("u", u) + ["--y"] + generic_names("y", y)
        if validation is not None:
            words += _validation_words(ws, validation, u, y, data)
        if order is not None:
            words += ["--order", number_text(order)]
        report_path, out_model = os.path.join(ws, "fit-linear.json"), os.path.join(ws, "fit-linear.model.json")
        code, output, messages = run("fit_linear", "fit-linear", words + ["--model-out", out_model, "--report",
                                                                          report_path], options, progress=progress,
                                      quiet=quiet)
        raise_unless_answer(code, output, messages)
        model = Model.from_file(out_model)
        model.report = _report(report_path)
        return model


def _record_words(ws, records):
    """--data per record of fit_linear(records=...), then --u/--y: each
    record written with the generic column names u1.., y1.."""
    if len(records) == 0:
        raise LpvidError(2, "records=: no records")
    words, widths = [], None
    for k, record in enumerate(records):
        ru, ry, rrho = _record_signals(record, k)
        if ru is None or ry is None or rrho is not None:
            raise LpvidError(2, f"records[{k}]: fit_linear() takes u and y (no rho) in every record")
        if widths is None:
            widths = (ru, ry)
        elif (width(ru), width(ry)) != (width(widths[0]), width(widths[1])):
            raise LpvidError(2, f"records[{k}]: {width(ru)} input(s) and {width(ry)} output(s), records[0] has "
                                f"{width(widths[0])} and {width(widths[1])}")
        path = os.path.join(ws, f"data{k + 1}.csv")
        words += ["--data", write_table(path, generic_table(ru, None, None) | generic_table(None, ry, None))]
    return words + ["--u"] + generic_names("u", widths[0]) + ["--y"] + generic_names("y", widths[1])


def _validation_words(ws, validation, u, y, data):
    if isinstance(validation, (str, os.PathLike)):
        return ["--validation", os.path.abspath(os.fspath(validation))]
    if not isinstance(validation, (tuple, list)) or len(validation) != 2:
        raise LpvidError(2, "validation=: expected (u_val, y_val) arrays or a data file's path")
    vu, vy = validation
    if data is not None:
        names_u, names_y = as_names(u or "u"), as_names(y or "y")
        table = dict(zip(names_u, _columns(vu))) | dict(zip(names_y, _columns(vy)))
    else:
        table = generic_table(vu, None, None) | generic_table(None, vy, None)
    return ["--validation", write_table(os.path.join(ws, "validation.csv"), table)]


def _columns(values):
    a = np.asarray(values, dtype=float)
    return [a] if a.ndim == 1 else [a[:, j] for j in range(a.shape[1])]


def simulate(model, u=None, rho=None, *, data=None, x0=None, out_dir=None, **options):
    """The model's output along inputs u and scheduling rho (`lpvid
    simulate`), from the model's x0 or x0=[...]. Returns a Simulation: y
    (samples x outputs, offset included) and z (the uncertainty channel's
    input)."""
    return simulate_document(as_model(model).document, u, rho, data=data, x0=x0, out_dir=out_dir, **options)


def _model_files(ws, models):
    """(name, path) per model: models is a list (Models, dicts, paths) or a
    dict {name: model}."""
    items = list(models.items()) if isinstance(models, dict) else \
        [(None, m) for m in (models if isinstance(models, (list, tuple)) else [models])]
    files, used = [], set()
    for k, (name, m) in enumerate(items):
        if isinstance(m, (str, os.PathLike)) and name is None:
            path = os.path.abspath(os.fspath(m))
            name = os.path.splitext(os.path.basename(path))[0]
        else:
            name = name or f"model{k + 1}"
            path = _model_file(ws, m, f"{name}.json")
        if name in used:
            raise LpvidError(2, f"compare(): two models are named {name!r}: give models={{name: model, ...}}")
        used.add(name)
        files.append((name, path))
    return files


def compare(u=None, y=None, models=None, rho=None, *, data=None, model=None, predict=None, warmup=None, x0=None,
            out_dir=None, progress=None, quiet=False, figures=True, **options):
    """Scores models on a record (`lpvid compare`): each model's free-run
    output (or predict=K: K-step-ahead prediction) against the measured
    output, RMS and fit % per model and output.

    u, y (and rho): arrays; or data= a file/DataFrame/dict with u=, y=
    (rho=) the column names that play the models' input, output and
    scheduling columns (no model is edited). models: a list of Models,
    dicts or model files, or a dict {name: model} (model= for one).
    warmup: fit x0 on the first K rows and score the rest. Returns a
    Comparison (scores per model, y, the table of series, plot())."""
    if models is None:
        models = [model] if model is not None else []
    if not models:
        raise LpvidError(2, "compare(): no model: give models=[...] (or model=)")
    with workspace("compare", out_dir) as ws:
        words = []
        if data is not None:
            words += ["--data", data_files(ws, {}, None, None, None, data)[0]]
            for name, names in (("u", u), ("y", y), ("rho", rho)):
                if names is not None:
                    words += [f"--{name}"] + as_names(names)
        elif u is not None and y is not None:
            table = generic_table(u, y, rho)
            words += ["--data", write_table(os.path.join(ws, "data.csv"), table)]
            for name, values in (("u", u), ("y", y), ("rho", rho)):
                if values is not None:
                    words += [f"--{name}"] + generic_names(name, values)
        else:
            raise LpvidError(2, "compare(): give u and y arrays, or data= (with u=/y= column names when they "
                                "differ from the models')")
        named = _model_files(ws, models)
        for _, path in named:
            words += ["--model", path]
        for flag, value in (("--predict", predict), ("--warmup", warmup)):
            if value is not None:
                words += [flag, number_text(value)]
        if x0 is not None:
            words += ["--x0", x0]
        report_path, series = os.path.join(ws, "compare.json"), os.path.join(ws, "compare.csv")
        words += ["--report", report_path, "--out", series]
        if figures:
            words += ["--plots", ws]  # the figure is ws/compare.png
        code, output, messages = run("compare", "compare", words, options, progress=progress, quiet=quiet)
        raise_unless_answer(code, output, messages)
        report = _report(report_path)
        table = read_table(series) if os.path.isfile(series) else {}
        result = Comparison(command="compare", code=code, report=report, output=output, messages=messages,
                            out_dir=ws if out_dir is not None else None, table=table)
        _fill_scores(result, report, table, [n for n, _ in named])
        result._plots = _plots(ws) if figures else {}
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


# -- data sets and the oracle ----------------------------------------------------------------
def generate(which="example1", *, out_dir=None, **options):
    """A data set with a known answer (`lpvid generate`): "example1",
    "example2", "effect-case" (with an effect the written model does not
    declare) or "random". Returns Generated: data (dict column -> array),
    validation (effect-case), model (the initial Model), truth (the true
    Model, effect-case), files (every file written, as bytes)."""
    with workspace("generate", out_dir) as ws:
        data = os.path.join(ws, "data.csv") if which != "random" else os.path.join(ws, "case")
        words = [which, "--out", data]
        extra = {}
        if which == "effect-case":
            extra = {"validation-out": "validation.csv", "model-out": "model.json", "truth-out": "truth.json"}
        elif which in ("example1", "example2"):
            extra = {"model-out": "model.json"}
        for flag, name in extra.items():
            words += [f"--{flag}", os.path.join(ws, name)]
        code, output, messages = run("generate", "generate", words, options)
        raise_unless_answer(code, output, messages)
        result = Generated(command="generate", code=code, report={}, output=output, messages=messages,
                           out_dir=ws if out_dir is not None else None)
        for root, _, names in os.walk(ws):
            for n in names:
                p = os.path.join(root, n)
                result.files[os.path.relpath(p, ws)] = read_bytes(p)
        if os.path.isfile(data):
            result.data = read_table(data)
        if os.path.isfile(os.path.join(ws, "validation.csv")):
            result.validation = read_table(os.path.join(ws, "validation.csv"))
        for attr, name in (("model", "model.json"), ("truth", "truth.json")):
            if os.path.isfile(os.path.join(ws, name)):
                setattr(result, attr, Model.from_file(os.path.join(ws, name)))
        return result


def oracle(command, *, cases=None, out_dir=None, progress=None, **options):
    """Judges an outside program against lpvid (`lpvid oracle`) on random
    cases with known answers: `command` is the program's command line with
    {data}, {model}, {task}, {out} placeholders. Returns an OracleRun
    (cases: one entry per case; passed: every case judged right)."""
    with workspace("oracle", out_dir) as ws:
        report_path = os.path.join(ws, "oracle.json")
        words = ["--command", command, "--report", report_path, "--work", os.path.join(ws, "work")]
        if cases is not None:
            words += ["--cases", number_text(cases)]
        code, output, messages = run("oracle", "oracle", words, options, own=("cases",), progress=progress)
        report = _report(report_path)
        result = OracleRun(command="oracle", code=code, report=report, output=output, messages=messages,
                           out_dir=ws if out_dir is not None else None, cases=report.get("cases") or [])
        raise_unless_answer(code, output, messages, result if report else None)
        result.passed = code == 0
        return result


__all__ = ["invalidate", "certify", "identify", "select_basis", "tradeoff", "diagnose", "fit_linear", "simulate",
           "compare", "generate", "oracle", "read_table", "Result"]
