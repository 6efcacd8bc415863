"""Parameter descriptions shared by the package's docstrings (numpydoc
style), filled into each function's docstring by `shared_doc`, so that one
description serves every function that takes the parameter."""

PARTS = {
    "model": """model : Model, dict or path
        The model: an lpvid.Model, a model dict (format lpvid-model/1) or a
        model file's path.""",
    "signals": """u, y, rho : array_like, optional
        The record's input, output and scheduling signals (keyword only):
        1-D for one channel, 2-D samples × channels, in the order of the
        model's columns; rho is None for a model without scheduling. A
        pandas Series or DataFrame is taken by its values.
    data : path, list of paths, DataFrame or dict, optional
        Instead of u, y, rho: a data file's path (several paths: several
        records of one system), or a DataFrame / dict {column: array} whose
        columns are named as the model's columns.
    records : list, optional
        Several records of one system under one Delta: a list of
        (u, y[, rho]) tuples or dicts with keys u, y, rho.
    x0 : sequence of numbers, optional
        The initial state (one per record for several records); default the
        model's x0.""",
    "bounds": """delta, dmax : exact number, optional
        Bounds to decide: both given: is the model consistent at them (code
        0 consistent, 1 invalidated)? One given: the smallest other one.
        Neither: the smallest lambda_*delta^2 + (1 - lambda_)*dmax^2.
        Exact numbers: 0.1 means the double 0.1; "1/10" means one tenth.
    lambda_ : exact number in [0, 1], optional
        The weight of delta^2 when both bounds are minimised.""",
    "run": """out_dir : path, optional
        Keep the run's files (report, certificates with their data, model,
        plot tables) in this folder; default: a private folder, removed when
        the call returns.
    progress : callable, optional
        Called with each progress line (they also go to the logger "lpvid"
        at level INFO).
    quiet : bool, default False
        No progress lines.""",
    "options": """**options
        Any other option of the command, named as on the command line with
        '_' for '-' (max_taps=0, solver="sdpa"). Python values are
        translated: True is the flag, False leaves it out (or gives its
        --no- form when the command has one), a (begin, end) tuple is a row
        window "B:E", a dict {"u1": "V"} gives "u1=V" values. A keyword the
        command does not have raises TypeError.""",
    "raises": """Raises
    ------
    LpvidValueError (a ValueError)
        Bad signals or options (NaN, lengths, shapes, values out of range).
    LpvidTypeError (a TypeError)
        An argument of the wrong type or an unknown keyword.
    LpvidFileNotFoundError (a FileNotFoundError)
        A named file that is not there.
    LpvidError
        Any other run without an answer (solver failure, exact check
        refused, timeout), with the command line's exit code in .code.""",
}


def shared_doc(function):
    """Fills {model}, {signals}, {bounds}, {run}, {options}, {raises} in the
    function's docstring."""
    if function.__doc__:
        function.__doc__ = function.__doc__.format(**PARTS)
    return function
