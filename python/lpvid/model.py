"""The model (format lpvid-model/1, docs/model.schema.json) as an object.

A Model wraps the model file's JSON document: the LPV state-space model
(eq. 1 of "Robust identification and invalidation of LPV systems"), its
column names, uncertainty channel, correction basis, static blocks, sample
time and units. Numbers stay as the file writes them (exact text such as
"0.3" or "1/10" is kept), so a model read and written again is the same
model.
"""

import copy
import json
import os

from ._errors import LpvidError
from ._files import model_columns, read_json, write_model
from ._simulate import simulate_document


class Model:
    """An lpvid model. Model(dict) wraps a model document;
    Model.from_file(path) reads one; to_file / to_dict / to_json write it;
    simulate(u, rho) runs it (lpvid simulate)."""

    def __init__(self, document):
        if isinstance(document, Model):
            document = document.document
        if not isinstance(document, dict):
            raise LpvidError(2, f"a model is an lpvid-model/1 dict, not {type(document).__name__}")
        self.document = copy.deepcopy(document)
        self.report = None  # the report of the run that made it, when a run did

    @classmethod
    def from_file(cls, path):
        try:
            return cls(read_json(os.fspath(path)))
        except OSError as e:
            raise LpvidError(6 if os.path.exists(path) else 2, f"{path}: {e.strerror}") from None
        except ValueError as e:
            raise LpvidError(2, f"{path}: not JSON: {e}") from None

    @classmethod
    def from_json(cls, text):
        return cls(json.loads(text))

    def to_dict(self):
        return copy.deepcopy(self.document)

    def to_json(self):
        return json.dumps(self.document, indent=2)

    def to_file(self, path):
        write_model(self.document, os.fspath(path))
        return os.fspath(path)

    # -- what it is ------------------------------------------------------------
    @property
    def states(self):
        return self.document.get("states")

    @property
    def inputs(self):
        return self.document.get("inputs")

    @property
    def outputs(self):
        return self.document.get("outputs")

    @property
    def columns(self):
        """(u, y, rho) column names the model reads from a data file."""
        return model_columns(self.document)

    @property
    def sample_time(self):
        """Seconds between samples, when the model file says (None otherwise)."""
        return self.document.get("sample_time")

    @property
    def units(self):
        return dict(self.document.get("units") or {})

    @property
    def description(self):
        return self.document.get("description")

    def __eq__(self, other):
        return isinstance(other, Model) and self.document == other.document

    def __repr__(self):
        u, y, rho = self.columns
        return (f"<lpvid.Model {self.states} states, u={u}, y={y}"
                + (f", rho={rho}" if rho else "") + ">")

    def simulate(self, u=None, rho=None, *, data=None, x0=None, **options):
        """The model's free-run output (lpvid simulate) for inputs u (and
        scheduling rho), from the model's x0 (or x0=[...]). Returns a
        Simulation with y (samples x outputs) and z (the uncertainty
        channel's input). See lpvid.simulate."""
        return simulate_document(self.document, u, rho, data=data, x0=x0, **options)


def as_model(model):
    """A Model from a Model, a dict or a model file's path."""
    if isinstance(model, Model):
        return model
    if isinstance(model, dict):
        return Model(model)
    if isinstance(model, (str, os.PathLike)):
        return Model.from_file(model)
    raise LpvidError(2, f"model: expected an lpvid.Model, a model dict or a model file's path, not "
                        f"{type(model).__name__}")
