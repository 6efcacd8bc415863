"""The model's output along inputs u and scheduling rho (`lpvid simulate`)
for a model document: the one run behind both lpvid.simulate and
Model.simulate. It works on the model's document (a dict), not on the Model
class, so that model.py can use it without a circle of imports."""

import os

import numpy as np

from ._files import as_signal, model_columns, number_text, read_table, write_model
from ._inputs import data_files
from ._invoke import raise_unless_answer, run
from ._workspace import workspace
from .results import Simulation


def simulate_document(document, u=None, rho=None, *, data=None, x0=None, out_dir=None, **options):
    """A Simulation (y with the offset, z) of the model document along u and
    rho (or the data file `data`), from the document's x0 or x0=[...]."""
    if x0 is not None:
        document = dict(document)
        document["x0"] = [number_text(v) for v in x0]
    with workspace("simulate", out_dir) as ws:
        model_path = os.path.join(ws, "model.json")
        write_model(document, model_path)
        u_names, y_names, rho_names = model_columns(document)
        if data is None:
            zeros = None if u is None else np.zeros((len(as_signal("u", u)), len(y_names)))
            paths = data_files(ws, document, u, zeros, rho)
        else:
            paths = data_files(ws, document, None, None, None, data)
        out = os.path.join(ws, "simulate.csv")
        code, output, messages = run("simulate", "simulate", ["--data", paths[0], "--model", model_path, "--out", out],
                                     options)
        raise_unless_answer(code, output, messages)
        table = read_table(out)
    ys = [k for k in table if k.endswith("_hat")]
    zs = [k for k in table if k not in ys]
    stack = (lambda keys: np.column_stack([table[k] for k in keys]) if keys else np.zeros((0, 0)))
    return Simulation(y=stack(ys), z=stack(zs), columns=list(table))
