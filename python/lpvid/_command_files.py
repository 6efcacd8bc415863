"""What every command function does around its run: the model and data
files it writes into its folder, the words that name them, the report and
certificates it reads back, the earlier outputs it removes from a kept
out_dir, the figures' descriptions it reads."""

from __future__ import annotations

import os

from ._files import existing_path, number_text, read_json, write_model
from .certificate import Certificate
from .model import as_model


# -- running -------------------------------------------------------------------


def read_report(path):
    return read_json(path) if os.path.isfile(path) else {}


def read_certificates(report, keep):
    """{path as the report names it: Certificate} for every certificate file
    the report names (keys mentioning "certificate"), in report order."""
    found = {}
    for path in _certificate_paths(report):
        if os.path.isfile(path):
            found[path] = Certificate.load(path)
            if not keep:
                found[path].path = None
    return found


def remove_earlier_outputs(report_path, *others):
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


def read_figures(folder):
    """The plots a run wrote into `folder`, in memory (lpvid.plots)."""
    if not os.path.isdir(folder):
        return {}
    try:
        from .plots import read_plots
    except ImportError:
        return {}
    return read_plots(folder)


def model_file(folder, model, name="model.json"):
    """The model's file: a path given stays; a Model or dict is written."""
    if isinstance(model, (str, os.PathLike)):
        return existing_path(model, "model")
    path = os.path.join(folder, name)
    write_model(as_model(model).document, path)
    return path


def _x0_text(x0):
    return ",".join(number_text(v) for v in x0)


def data_words(paths, x0=None):
    """--data P [--x0 V,..] per record; x0: one state vector (one record) or
    one per record."""
    words = []
    per_record = x0 is not None and len(paths) > 1
    for k, path in enumerate(paths):
        words += ["--data", path]
        if x0 is not None and (per_record or k == 0):
            words += ["--x0", _x0_text(x0[k] if per_record else x0)]
    return words


def bound_words(delta, dmax, lambda_):
    words = []
    for name, value in (("delta", delta), ("dmax", dmax), ("lambda", lambda_)):
        if value is not None:
            words += [f"--{name}", number_text(value)]
    return words
