"""The package's calling conventions (docs/python.md) against answers known
by construction, and its numbers against the lpvid program's on the same
files.

- model first, signals by keyword: the new call and the old positional
  order (with a DeprecationWarning naming the new call) give the same
  exact bounds; a model followed by positional signals is refused with a
  TypeError showing the new call;
- Python values for options: rows=(0, 60) is the window 0:60 (the fit sees
  60 samples), units={"uEst": "V"} reaches the model file, offset=False is
  left out;
- pandas names become the model's column names (u and y distinct);
- type hints resolve (typing.get_type_hints) and py.typed ships beside the
  package;
- everything a command prints comes back in result.output, none of it on
  the process's stdout (compare's table was printed around the capture);
- the numbers are the program's: the same invalidate, compare and
  fit-linear run by the lpvid program on the files the package wrote give
  the same exact bounds, RMS and model file.

Usage: conventions_test.py LPVID_PROGRAM SCRATCH_DIR (the package on PYTHONPATH).
"""

import json
import os
import shutil
import subprocess
import sys
import typing
import unittest
import warnings
from fractions import Fraction

import numpy as np

import lpvid

PROGRAM = None
SCRATCH = None
N = 80


def first_order_record(gain=0.5, n=N, seed=7):
    """y_{k+1} = gain*y_k + u_k, y_0 = 0: in the class of a 1-state LTI model."""
    rng = np.random.default_rng(seed)
    u = rng.standard_normal(n)
    y = np.zeros(n)
    for k in range(n - 1):
        y[k + 1] = gain * y[k] + u[k]
    return u, y


def model_with_gain(a):
    return {"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1,
            "columns": {"u": ["u"], "y": ["y"]},
            "initial": {"A": [{"basis": "1", "value": [[str(a)]]}], "B": [{"basis": "1", "value": [["1"]]}],
                        "C": [{"basis": "1", "value": [["1"]]}]}}


def program(*words):
    return subprocess.run([PROGRAM, *words], capture_output=True, text=True)


class Conventions(unittest.TestCase):
    def folder(self, name):
        path = os.path.join(SCRATCH, name)
        shutil.rmtree(path, ignore_errors=True)
        return path

    def test_model_first_and_the_old_order_agree(self):
        u, y = first_order_record()
        model = model_with_gain("2/5")  # the wrong gain: d_max > 0 at delta = 0
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # the new call warns about nothing
            new = lpvid.invalidate(model, u=u, y=y, delta=0)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            old = lpvid.invalidate(u, y, None, model, delta=0)
        deprecations = [w for w in caught if issubclass(w.category, DeprecationWarning)]
        self.assertEqual(len(deprecations), 1)
        self.assertIn("invalidate(model, u=u, y=y", str(deprecations[0].message))
        self.assertEqual(deprecations[0].filename, __file__)  # points at the caller's line
        self.assertEqual((new.code, new.dmax2), (old.code, old.dmax2))
        self.assertGreater(new.dmax2, 0)

    def test_compare_and_simulate_take_the_model_first(self):
        u, y = first_order_record()
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            c = lpvid.compare({"true": model_with_gain("1/2"), "wrong": model_with_gain("2/5")}, u=u, y=y,
                              figures=False)
            s = lpvid.simulate(model_with_gain("1/2"), u=u)
        self.assertLess(c.score("true").rms, 1e-12)
        self.assertGreater(c.score("wrong").rms, 0.01)
        np.testing.assert_allclose(s.y[:, 0], y, atol=1e-12)
        with self.assertWarns(DeprecationWarning):
            old = lpvid.compare(u, y, [model_with_gain("1/2")], figures=False)
        self.assertEqual(old.scores[0].rms, c.score("true").rms)
        path = os.path.join(self.folder("named"), "m.json")
        os.makedirs(os.path.dirname(path))
        lpvid.Model(model_with_gain("1/2")).to_file(path)
        named = lpvid.compare({"before": path}, u=u, y=y, figures=False)  # the key names it, not the file
        self.assertEqual([s.name for s in named.scores], ["before"])

    def test_positional_signals_after_the_model_are_refused(self):
        u, y = first_order_record()
        with self.assertRaises(TypeError) as e:
            lpvid.diagnose(model_with_gain("1/2"), u, y)
        self.assertIn("diagnose(model, u=", str(e.exception))
        self.assertIsInstance(e.exception, lpvid.LpvidError)

    def test_python_values_for_options(self):
        u, y = first_order_record()
        m = lpvid.fit_linear(u=u, y=y, order=1, rows=(0, 60), units={"u1": "V"}, offset=False)
        self.assertEqual(m.units.get("u1"), "V")
        self.assertNotIn("offset", m.document)  # offset=False: no offset fitted
        out = self.folder("rows")
        lpvid.fit_linear(u=u, y=y, order=1, rows=(0, 60), out_dir=out)
        with open(os.path.join(out, "fit-linear.model.json")) as f:
            self.assertEqual(json.load(f)["initial"], m.document["initial"])
        full = lpvid.fit_linear(u=u, y=y, order=1)
        # a window of 60 samples is another least-squares problem than all 80, on noise-free data the
        # same system: the gain agrees to the fit's precision, the model file's digits differ
        a60 = float(Fraction(m.document["initial"]["A"][0]["value"][0][0]))
        a80 = float(Fraction(full.document["initial"]["A"][0]["value"][0][0]))
        self.assertAlmostEqual(a60, 0.5, places=6)
        self.assertAlmostEqual(a80, 0.5, places=6)
        with self.assertRaises(TypeError):
            lpvid.fit_linear(u=u, y=y, order=1, rowz=(0, 60))

    def test_pandas_names_become_the_models_columns(self):
        import pandas as pd
        u, y = first_order_record()
        m = lpvid.fit_linear(pd.Series(u, name="uEst"), pd.Series(y, name="yEst"), order=1)
        self.assertEqual(m.columns[:2], (["uEst"], ["yEst"]))
        same = lpvid.fit_linear(pd.Series(u, name="v"), pd.Series(y, name="v"), order=1)
        self.assertEqual(same.columns[:2], (["v"], ["y1"]))  # y may not reuse u's name
        plain = lpvid.fit_linear(u, y, order=1)
        self.assertEqual(plain.columns[:2], (["u1"], ["y1"]))

    def test_type_hints_resolve_and_py_typed_ships(self):
        for f in (lpvid.invalidate, lpvid.certify, lpvid.identify, lpvid.select_basis, lpvid.tradeoff,
                  lpvid.diagnose, lpvid.compare, lpvid.simulate, lpvid.fit_linear, lpvid.generate, lpvid.oracle):
            hints = typing.get_type_hints(f)
            self.assertIn("return", hints, f.__name__)
            self.assertIn("Parameters\n    ----------", f.__doc__, f.__name__)
            for part in ("signals", "bounds", "run", "options", "raises") + (("model",) if f is not lpvid.oracle else ()):
                self.assertNotIn("{" + part + "}", f.__doc__, f.__name__)  # every shared description filled in
        self.assertTrue(os.path.isfile(os.path.join(os.path.dirname(lpvid.__file__), "py.typed")))

    def test_output_comes_back_and_nothing_reaches_stdout(self):
        code = ("import numpy as np, lpvid\n"
                "u = np.arange(20.0) % 3; y = 0.5 * u\n"
                "m = {'format': 'lpvid-model/1', 'states': 1, 'inputs': 1, 'outputs': 1,\n"
                "     'columns': {'u': ['u'], 'y': ['y']},\n"
                "     'initial': {'A': [{'basis': '1', 'value': [['0']]}], 'B': [{'basis': '1', 'value': [['0']]}],\n"
                "                 'C': [{'basis': '1', 'value': [['0']]}], 'D': [{'basis': '1', 'value': [['1/2']]}]}}\n"
                "c = lpvid.compare(m, u=u, y=y, figures=False)\n"
                "assert 'RMS(y - yhat)' in c.output, c.output\n")
        run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stdout, "")

    def test_gnuplot_runs_only_for_kept_files(self):
        """Without out_dir= the figures are drawn from their descriptions
        when .plot() asks, so gnuplot never runs; with out_dir= the PNGs
        are written as the program writes them. A gnuplot stand-in logs
        every start."""
        folder = self.folder("gnuplot")
        os.makedirs(folder)
        log, stand_in = os.path.join(folder, "starts.log"), os.path.join(folder, "gnuplot")
        with open(stand_in, "w") as f:
            f.write(f"#!/bin/sh\necho started >> {log}\nexec gnuplot \"$@\"\n")
        os.chmod(stand_in, 0o755)
        code = ("import sys, numpy as np, lpvid\n"
                "u = np.arange(30.0) % 4; y = 0.5 * u\n"
                "m = {'format': 'lpvid-model/1', 'states': 0, 'inputs': 1, 'outputs': 1,\n"
                "     'columns': {'u': ['u'], 'y': ['y']}, 'initial': {'D': [{'basis': '1', 'value': [['1/2']]}]}}\n"
                "c = lpvid.compare(m, u=u, y=y, out_dir=sys.argv[1] if len(sys.argv) > 1 else None)\n"
                "assert 'compare' in c.plots, c.plots\n")
        env = dict(os.environ, LPVID_GNUPLOT=stand_in)
        run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertFalse(os.path.exists(log))  # not one gnuplot start without out_dir
        kept = os.path.join(folder, "kept")
        run = subprocess.run([sys.executable, "-c", code, kept], capture_output=True, text=True, env=env)
        self.assertEqual(run.returncode, 0, run.stderr)
        if shutil.which("gnuplot"):
            self.assertTrue(os.path.exists(log))
            self.assertTrue(os.path.isfile(os.path.join(kept, "compare.png")))

    def test_the_numbers_are_the_programs(self):
        u, y = first_order_record()
        y = y + 0.01 * np.random.default_rng(3).standard_normal(N)
        out = self.folder("same")
        r = lpvid.invalidate(model_with_gain("1/2"), u=u, y=y, delta="1/1000", out_dir=out)
        cli = program("invalidate", "--data", os.path.join(out, "data.csv"), "--model", os.path.join(out, "model.json"),
                      "--delta", "1/1000", "--report", os.path.join(out, "cli.json"),
                      "--certificate", os.path.join(out, "cli.cert.json"))
        self.assertEqual(cli.returncode, r.code, cli.stderr)
        with open(os.path.join(out, "cli.json")) as f:
            report = json.load(f)
        self.assertEqual(lpvid.exact(report["dmax2_exact"]), r.dmax2)
        c = lpvid.compare({"m": model_with_gain("2/5")}, u=u, y=y, out_dir=self.folder("cmp"), figures=False)
        cli = program("compare", "--data", os.path.join(out, "data.csv"), "--model",
                      os.path.join(SCRATCH, "cmp", "m.json"), "--report", os.path.join(out, "cmp.json"))
        self.assertEqual(cli.returncode, 0, cli.stderr)
        with open(os.path.join(out, "cmp.json")) as f:
            self.assertEqual(json.load(f)["rms"], c.scores[0].rms)


if __name__ == "__main__":
    PROGRAM, SCRATCH = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    os.makedirs(SCRATCH, exist_ok=True)
    unittest.main(argv=sys.argv[:1], verbosity=2)
