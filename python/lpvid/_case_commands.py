"""Data sets with known answers (generate) and the oracle that judges an
outside program on them (oracle)."""

from __future__ import annotations

import os
from typing import Any, Optional

from ._command_files import read_report
from ._docs import shared_doc
from ._files import number_text, read_table
from ._invoke import raise_unless_answer, run
from ._types import PathLike, Progress
from ._workspace import read_bytes, workspace
from .model import Model
from .results import Generated, OracleRun


# -- data sets and the oracle ----------------------------------------------------------------
@shared_doc
def generate(which: str = "example1", *, out_dir: Optional[PathLike] = None, **options: Any) -> Generated:
    """A data set with a known answer (`lpvid generate`).

    Parameters
    ----------
    which : {{"example1", "example2", "effect-case", "random"}}
        Example 1 or 2 of "Robust identification and invalidation of LPV
        systems", a case with an effect the written model does not declare,
        or a random case.
    out_dir : path, optional
        Keep the files there.
    {options}

    Returns
    -------
    Generated
        data (dict column -> array), validation (effect-case), model (the
        initial Model), truth (the true Model, effect-case), files (every
        file written, as bytes).

    {raises}
    """
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


@shared_doc
def oracle(command: str, *, cases: Optional[int] = None, out_dir: Optional[PathLike] = None,
           progress: Optional[Progress] = None, **options: Any) -> OracleRun:
    """Judges an outside program against lpvid (`lpvid oracle`) on random
    cases with known answers.

    Parameters
    ----------
    command : str
        The program's command line with {{data}}, {{model}}, {{task}}, {{out}}
        placeholders.
    cases : int, optional
        How many cases.
    out_dir : path, optional
        Keep the files there.
    progress : callable, optional
        Called with each progress line.
    {options}

    Returns
    -------
    OracleRun
        cases (one entry per case), passed (every case judged right).

    {raises}
    """
    with workspace("oracle", out_dir) as ws:
        report_path = os.path.join(ws, "oracle.json")
        words = ["--command", command, "--report", report_path, "--work", os.path.join(ws, "work")]
        if cases is not None:
            words += ["--cases", number_text(cases)]
        code, output, messages = run("oracle", "oracle", words, options, own=("cases",), progress=progress)
        report = read_report(report_path)
        result = OracleRun(command="oracle", code=code, report=report, output=output, messages=messages,
                           out_dir=ws if out_dir is not None else None, cases=report.get("cases") or [])


        raise_unless_answer(code, output, messages, result if report else None)
        result.passed = code == 0
        return result
