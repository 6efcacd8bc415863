"""Model first, signals by keyword: the calling convention of the package's
functions, and the older positional orders kept working for one release.

Since version 0.2 every function that takes a model takes it first and the
signals by keyword, as scipy and scikit-learn functions do:

    lpvid.invalidate(model, u=u, y=y, rho=rho, delta="1/100")
    lpvid.diagnose(model, u=u, y=y, test=(u_test, y_test))
    lpvid.compare({"before": m1, "after": m2}, u=u, y=y)
    lpvid.simulate(model, u=u, rho=rho)

The orders of earlier versions (invalidate(u, y, rho, model),
compare(u, y, models, rho), simulate(model, u, rho)) still work and give a
DeprecationWarning naming the new call; they will be removed in the next
release. A call that mixes the two (a model first, then signals by
position) is refused with a TypeError that shows the new call.
"""

import functools
import os
import warnings

from ._errors import LpvidTypeError

ModelLikeTypes = (dict, str, os.PathLike)

# The positional order of the functions that take a model, before version 0.2.
LEGACY = ("u", "y", "rho", "model")


def is_model_like(value):
    """A Model, a model dict or a model file's path."""
    from .model import Model  # late: model.py imports this package's modules
    return isinstance(value, (Model,) + ModelLikeTypes)


def is_models_like(value):
    """compare()'s models: one model, a dict {name: model} or a list of models."""
    if is_model_like(value):
        return True
    return isinstance(value, (list, tuple)) and len(value) > 0 and all(is_model_like(v) for v in value)


def _legacy_call(name, legacy, args, kwargs, first):
    """kwargs with the old positional order's arguments, after a warning."""
    if len(args) > len(legacy):
        raise LpvidTypeError(f"{name}() takes at most {len(legacy)} positional arguments in its old form "
                             f"({', '.join(legacy)}); call {name}({first}, u=..., y=...)")
    for key, value in zip(legacy, args):
        if key in kwargs:
            raise LpvidTypeError(f"{name}() got multiple values for argument '{key}'")
        kwargs[key] = value
    shown = ", ".join(f"{k}={k}" if k != first else k for k in [first] + [k for k in legacy if k != first]
                      if k in kwargs)
    warnings.warn(f"{name}({', '.join(legacy[:len(args)])}) is deprecated: give the {first} first and the signals "
                  f"by keyword, {name}({shown}); the old order goes in version 0.3",
                  DeprecationWarning, stacklevel=3)
    return kwargs


def model_first(legacy, first="model"):
    """Decorates a function whose signature is `f(model, *, u=, y=, ...)`
    (or `f(models, *, ...)`) so that it also accepts the positional order
    `legacy` of earlier versions, with a DeprecationWarning."""
    def decorate(function):
        recognise = is_models_like if first == "models" else is_model_like

        @functools.wraps(function)
        def call(*args, **kwargs):
            if not args:
                return function(**kwargs)
            if recognise(args[0]) and len(args) == 1:
                if first in kwargs:
                    raise LpvidTypeError(f"{function.__name__}() got multiple values for argument '{first}'")
                return function(args[0], **kwargs)
            if recognise(args[0]) and legacy[0] != first:
                raise LpvidTypeError(f"{function.__name__}() takes the {first} as its only positional argument; "
                                     f"give the signals by keyword: {function.__name__}({first}, u=..., y=...)")
            return function(**_legacy_call(function.__name__, legacy, args, dict(kwargs), first))
        return call
    return decorate
