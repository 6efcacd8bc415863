"""invalidate, identify, diagnose and verify on arrays and model dicts.

Each call writes its inputs into one folder (data.csv, model.json), runs
the same code as the command line in this process, and reads back the JSON
report it wrote there. The folder is kept: the certificates in it name
data.csv by path and SHA-256, and `lpvid-verify` rechecks them later.
"""

import dataclasses
import os
import tempfile
from fractions import Fraction
from typing import Optional

from ._errors import EXIT_CODES, LpvidError
from ._files import number_text, read_json, write_data, write_model
from ._run import error_message, option_words, run_captured


def exact(text):
    """An exact number of a report ("0.0123" or "p/q") as a Fraction."""
    return None if text is None else Fraction(text)


@dataclasses.dataclass
class Result:
    """What a run of invalidate / identify / diagnose answered.

    code: the exit code (0 consistent / bounds verified, 1 invalidated).
    verdict: the report's verdict or status ("consistent", "invalidated", ...).
    delta, dmax: the certified bounds as the report gives them (floats, the
      upper ends), None when the run certified none.
    delta2_exact, dmax2_exact: the same bounds squared, as the report's exact
      decimal or p/q text (`lpvid.exact` turns them into Fractions).
    interval: the certified interval of the objective (a minimisation), with
      its exact ends (upper_exact, lower_exact), or None.
    certificate, lower_certificate: the certificate of the answer and of the
      interval's lower end (paths), when written.
    certificates: every certificate file the report names.
    report: the whole JSON report; report_path, data_path, model_path and
      out_dir say where the files are; output and messages hold what the run
      printed on stdout and stderr. model: the model the run wrote
      (identify and diagnose, --model-out), as a dict.
    """

    command: str
    code: int
    verdict: Optional[str]
    delta: Optional[float]
    dmax: Optional[float]
    delta2_exact: Optional[str]
    dmax2_exact: Optional[str]
    interval: Optional[dict]
    certificate: Optional[str]
    lower_certificate: Optional[str]
    certificates: list
    report: dict
    report_path: str
    data_path: str
    model_path: str
    out_dir: str
    output: str
    messages: str
    model: Optional[dict] = None

    @property
    def consistent(self):
        return self.code == 0

    @property
    def invalidated(self):
        return self.code == 1


@dataclasses.dataclass
class Verification:
    """What lpvid-verify said of a certificate: ok (the claim holds, exit
    0) or not (exit 1, the reason in output). bool(v) is v.ok."""

    ok: bool
    code: int
    certificate: str
    data: Optional[str]
    output: str
    messages: str

    def __bool__(self):
        return self.ok


def _certificates_in(report, base):
    """Every existing file a report names under a key that mentions a
    certificate, in the order they appear, relative paths resolved against
    the folder the run was started from (`base`)."""
    found = []

    def walk(node, key=""):
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, k)
        elif isinstance(node, list):
            for v in node:
                walk(v, key)
        elif isinstance(node, str) and "certificate" in key:
            path = node if os.path.isabs(node) else os.path.join(base, node)
            if os.path.isfile(path) and path not in found:
                found.append(path)

    walk(report)
    return found


def _folder(command, out_dir):
    """The run's folder, created if needed (None: a new temporary folder,
    kept after the call: the certificates in it must outlive it)."""
    if out_dir is None:
        return tempfile.mkdtemp(prefix=f"lpvid-{command}-")
    os.makedirs(out_dir, exist_ok=True)
    return os.path.abspath(out_dir)


def _model_dict(model, model_path):
    """The model as a dict (for the column names; lpvid itself reads and checks the file)."""
    if isinstance(model, dict):
        return model
    try:
        return read_json(model_path)
    except (OSError, ValueError) as e:
        raise LpvidError(6 if isinstance(e, OSError) else 2, f"{model_path}: {e}") from None


def _record_signals(record, k):
    """(u, y, rho) of one entry of records=: a dict with keys u, y (and rho) or a tuple (u, y[, rho])."""
    if isinstance(record, dict):
        unknown = set(record) - {"u", "y", "rho"}
        if unknown:
            raise LpvidError(2, f"records[{k}]: unknown key(s) {sorted(unknown)} (expected u, y, rho)")
        return record.get("u"), record.get("y"), record.get("rho")
    if isinstance(record, (tuple, list)) and len(record) in (2, 3):
        return record[0], record[1], record[2] if len(record) == 3 else None
    raise LpvidError(2, f"records[{k}]: expected a dict with u, y (and rho) or a tuple (u, y[, rho])")


def _prepare(out_dir, u, y, rho, model, data, records=None):
    """The run's input files in out_dir: (data paths, model path). One
    record: u, y, rho arrays or data=PATH. Several records under one Delta:
    records=[{"u": .., "y": .., "rho": ..}, ...] or data=[PATH, PATH, ...]."""
    given = [name for name, v in (("u, y, rho", u if u is not None else y if y is not None else rho),
                                  ("data", data), ("records", records)) if v is not None]
    if len(given) > 1:
        raise LpvidError(2, "give the signals one way: as arrays (u, y, rho), as data file(s) (data=) or as "
                            f"records=, not {' and '.join(given)}")
    if isinstance(model, dict):
        model_path = os.path.join(out_dir, "model.json")
        write_model(model, model_path)
    else:
        model_path = os.path.abspath(os.fspath(model))
    if data is not None:
        paths = data if isinstance(data, (list, tuple)) else [data]
        return [os.path.abspath(os.fspath(p)) for p in paths], model_path
    model_dict = _model_dict(model, model_path)
    if records is not None:
        if len(records) == 0:
            raise LpvidError(2, "records=: no records")
        paths = []
        for k, record in enumerate(records):
            ru, ry, rrho = _record_signals(record, k)
            paths.append(os.path.join(out_dir, f"data{k + 1}.csv"))
            write_data(paths[-1], model_dict, ru, ry, rrho)
        return paths, model_path
    data_path = os.path.join(out_dir, "data.csv")
    write_data(data_path, model_dict, u, y, rho)
    return [data_path], model_path


def _remove_earlier_outputs(out_dir, report_path, model_out_path):
    """Removes what an earlier run of the same command wrote into this
    folder (its report, the certificates in the folder the report names,
    its model): a run that fails must not leave them looking like its own
    results. Files elsewhere (a certificate= given then) are left alone."""
    if os.path.isfile(report_path):
        try:
            earlier = read_json(report_path)
        except ValueError:
            earlier = {}
        for path in _certificates_in(earlier, os.getcwd()):
            if os.path.dirname(os.path.abspath(path)) == out_dir:
                os.remove(path)
        os.remove(report_path)
    if model_out_path and os.path.isfile(model_out_path):
        os.remove(model_out_path)


def _run_bounds_command(command, u, y, rho, model, *, data, out_dir, quiet, bounds, extra, model_out=False,
                        records=None):
    out_dir = _folder(command, out_dir)
    report_path = os.path.join(out_dir, f"{command}.json")
    model_out_path = os.path.join(out_dir, f"{command}.model.json") if model_out else None
    _remove_earlier_outputs(out_dir, report_path, model_out_path)
    data_paths, model_path = _prepare(out_dir, u, y, rho, model, data, records)
    data_path = data_paths[0]
    args = [command]
    for path in data_paths:
        args += ["--data", path]
    args += ["--model", model_path, "--report", report_path]
    if model_out_path:
        args += ["--model-out", model_out_path]
    for name, value in bounds.items():
        if value is not None:
            args += [f"--{name}", number_text(value)]
    if quiet:
        args.append("--quiet")
    args += option_words(extra)
    code, output, messages = run_captured("lpvid", args, echo=not quiet)
    report = read_json(report_path) if os.path.isfile(report_path) else {}
    result = _result(command, code, report, report_path, data_path, model_path, out_dir, output, messages)
    if model_out_path and os.path.isfile(model_out_path):
        result.model = read_json(model_out_path)
    if code not in (0, 1):
        raise LpvidError(code, error_message(output, messages, EXIT_CODES.get(code, "")),
                         result if report else None)
    return result


def _result(command, code, report, report_path, data_path, model_path, out_dir, output, messages):
    interval = report.get("interval")
    certificates = _certificates_in(report, os.getcwd())
    lower = interval.get("lower_certificate") if isinstance(interval, dict) else None
    return Result(command=command, code=code, verdict=report.get("verdict", report.get("status")),
                  delta=report.get("delta"), dmax=report.get("dmax"), delta2_exact=report.get("delta2_exact"),
                  dmax2_exact=report.get("dmax2_exact"), interval=interval, certificate=report.get("certificate"),
                  lower_certificate=lower, certificates=certificates, report=report, report_path=report_path,
                  data_path=data_path, model_path=model_path, out_dir=out_dir, output=output, messages=messages)


def invalidate(u, y, rho, model, *, delta=None, dmax=None, lambda_=None, data=None, records=None, out_dir=None,
               quiet=True, **options):
    """Theorem 2.1 for a fixed model (`lpvid invalidate`).

    u, y, rho: arrays, 1-D (one channel) or 2-D (samples x channels), in
    the order of the model's columns; rho None for a model without
    scheduling columns. Or data=PATH (an existing data file) and u, y, rho
    None. model: an lpvid-model/1 dict or a model file's path.
    Several records of one system under one Delta (one uncertainty and one
    noise bound for every record; each record starts from rest):
    records=[{"u": u1, "y": y1, "rho": rho1}, {"u": u2, "y": y2}, ...] (or
    tuples (u, y[, rho])), or data=[PATH1, PATH2, ...]; u, y, rho None.
    delta and dmax given: decide consistency at those bounds (code 0
    consistent, 1 invalidated); one of them: minimise the other; neither:
    minimise lambda_*delta^2 + (1-lambda_)*dmax^2 (--lambda, default 0.5).
    Numbers are passed as exact text: 0.1 means 1/10.
    out_dir: the folder for data.csv, model.json, the report and the
    certificates (None: a new temporary folder, kept).
    quiet: no progress lines, nothing printed (the text is in the Result).
    options: any other option of `lpvid invalidate --help`, '_' for '-'
    (max_taps=0, solver="sdpa", rows="0:200", delta_norm="kyp").
    Exit codes other than 0 and 1 raise LpvidError.
    """
    return _run_bounds_command("invalidate", u, y, rho, model, data=data, out_dir=out_dir, quiet=quiet,
                               bounds={"delta": delta, "dmax": dmax, "lambda": lambda_}, extra=options,
                               records=records)


def identify(u, y, rho, model, *, delta=None, dmax=None, lambda_=None, data=None, records=None, out_dir=None,
             quiet=True, **options):
    """Theorem 3.1 (`lpvid identify`): the correction S_C(rho) over the
    model's correction basis ("correction": {"basis": [...]}, or
    basis=["1", "rho1"]), with certified bounds of the identified model.

    Arguments as for invalidate; options are those of `lpvid identify
    --help` (iterate=True, method="alternating", free_x0=True, ...). The
    identified model (--model-out, exact, the one the bounds are about) is
    in Result.model and Result.report["model_out"].
    """
    return _run_bounds_command("identify", u, y, rho, model, data=data, out_dir=out_dir, quiet=quiet,
                               bounds={"delta": delta, "dmax": dmax, "lambda": lambda_}, extra=options,
                               model_out=True, records=records)


def diagnose(u, y, rho, model, *, delta=None, dmax=None, lambda_=None, data=None, records=None, out_dir=None,
             quiet=True, **options):
    """Residual -> missing effect -> re-fitted model (`lpvid diagnose`),
    with before/after RMS and verified bounds on windows of the record.

    Arguments as for invalidate; options are those of `lpvid diagnose
    --help` (holdout=0.3, max_effects=2, window_length=100, plots="dir",
    test_columns=[["uVal", "yVal"]], ...). The model after diagnosis is in
    Result.model; Result.certificates lists every certificate written.
    """
    return _run_bounds_command("diagnose", u, y, rho, model, data=data, out_dir=out_dir, quiet=quiet,
                               bounds={"delta": delta, "dmax": dmax, "lambda": lambda_}, extra=options,
                               model_out=True, records=records)


def verify(certificate, data=None, *, quiet=True, **options):
    """Checks a certificate exactly (`lpvid-verify certificate`), from the
    data file's bytes to the PSD decision. data: the data file to read
    instead of the recorded path (its SHA-256 must still match). options:
    the limits (max_file_mb=..., max_digits=...). Returns a Verification,
    true when the certificate's claim holds (exit 0), false when it does not
    (exit 1); a missing, malformed or unreadable certificate or data file
    (exit 2, 6) raises LpvidError."""
    path = os.fspath(certificate)
    args = ["certificate", path]
    if data is not None:
        args += ["--data", os.fspath(data)]
    args += option_words(options)
    code, output, messages = run_captured("lpvid-verify", args, echo=not quiet)
    if code not in (0, 1):
        raise LpvidError(code, error_message(output, messages, EXIT_CODES.get(code, "")))
    return Verification(ok=code == 0, code=code, certificate=path, data=None if data is None else os.fspath(data),
                        output=output, messages=messages)
