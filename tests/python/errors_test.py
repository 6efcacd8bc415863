"""Errors in the caller's terms: every bad input raises the standard Python
class for that mistake (ValueError, TypeError, FileNotFoundError, each also
an lpvid.LpvidError) with a message that names the argument and the index
as the caller wrote them, never a file of the package's private folder
nor a line of a CSV file; no call leaves a folder behind, and the next good
call answers as if nothing had happened.

Known answers by construction:
- a NaN put at y[10] is reported as "y[10] is NaN", an inf at u[10, 1] as
  "u[10, 1] is inf", the text 'abc' at u[3] (which lpvid itself refuses,
  at line 5 of the CSV file the package wrote) as u[3];
- arrays of 150 and 149 samples, a transposed (1, 150) array, a 3-D array,
  two input channels for a one-input model: each message states it;
- a NaN in a column of data= that the model does not read is no error
  (lpvid reads only its columns), and the call answers as without it;
- max_effects=-1 (the command accepts 0..20) is told as max_effects=, a
  misspelt keyword as Python tells one;
- quiet=True: no progress line reaches the logger or the callback, also
  for a command without --quiet;
- SIGTERM during a run (diagnose, at its first progress line): the run
  stops, the folders are removed, and the process ends with exit code 143
  (or by the signal).

Usage: errors_test.py SCRATCH_DIR (with the package on PYTHONPATH).
"""

import os
import re
import select
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

import numpy as np

import lpvid
from lpvid import _run

SCRATCH = None
N = 150


def first_order(u, a=0.5, b=1.0):
    """y_k = x_k, x_{k+1} = a x_k + b u_k, x_0 = 0."""
    x, y = 0.0, []
    for uk in u:
        y.append(x)
        x = a * x + b * uk
    return np.array(y)


def lti_model(inputs=1):
    """The first-order system (the gain on u1; further inputs weigh 0)."""
    names = ["u"] if inputs == 1 else [f"u{k + 1}" for k in range(inputs)]
    return {"format": "lpvid-model/1", "states": 1, "inputs": inputs, "outputs": 1,
            "columns": {"u": names, "y": ["y"]},
            "initial": {"A": [{"basis": "1", "value": [["1/2"]]}],
                        "B": [{"basis": "1", "value": [[1] + [0] * (inputs - 1)]}],
                        "C": [{"basis": "1", "value": [[1]]}]},
            "uncertainty": {"structure": "additive", "weight": "1/10"}}


def leftovers():
    return sorted(n for n in os.listdir(tempfile.gettempdir()) if n.startswith("lpvid-"))


class Errors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.u = np.random.default_rng(11).standard_normal(N)
        cls.y = first_order(cls.u)

    def setUp(self):
        self.before = leftovers()

    def tearDown(self):
        self.assertEqual(leftovers(), self.before, "a call left a folder behind")

    def assertRefused(self, call, kind, message):
        """call() raises `kind` (also an LpvidError, code 2) with exactly
        `message` (or matching it, a compiled pattern), and the message
        names no file of the package."""
        with self.assertRaises(kind) as c:
            call()
        e = c.exception
        self.assertIsInstance(e, lpvid.LpvidError)
        self.assertEqual(e.code, 2)
        text = str(e)
        print(f"  {type(e).__name__}: {text}", file=sys.stderr)
        if isinstance(message, re.Pattern):
            self.assertRegex(text, message)
        else:
            self.assertEqual(text, message)
        self.assertIsNone(re.search(r"lpvid-[a-z-]+-\w{8}", text), text)  # a private folder's name
        self.assertNotIn(tempfile.gettempdir(), text)
        self.assertIsNone(re.search(r"\.(csv|json):\d+", text), text)
        self.assertNotIn("--help", text)
        return e

    def assertNextCallAnswers(self):
        # y is the model's own output: consistent at delta = 0 with any noise bound
        r = lpvid.invalidate(model=lti_model(), u=self.u, y=self.y, delta=0, dmax="1/100")
        self.assertTrue(r.consistent)

    def test_bad_signals(self):
        m, u, y = lti_model(), self.u, self.y
        nan_y = y.copy()
        nan_y[10] = np.nan
        inf_u = np.column_stack([u, u])
        inf_u[10, 1] = np.inf
        text_u = [repr(float(v)) for v in u]
        text_u[3] = "abc"
        table = [
            ("lengths", lambda: lpvid.invalidate(model=m, u=u, y=y[:-1]), ValueError,
             f"u has {N} samples, y has {N - 1}"),
            ("NaN", lambda: lpvid.invalidate(model=m, u=u, y=nan_y), ValueError, "y[10] is NaN"),
            ("inf", lambda: lpvid.invalidate(model=lti_model(2), u=inf_u, y=y), ValueError, "u[10, 1] is inf"),
            ("3-D", lambda: lpvid.invalidate(model=m, u=u.reshape(N // 2, 1, 2), y=y), ValueError,
             "u has 3 dimensions; give samples × channels"),
            ("transposed", lambda: lpvid.invalidate(model=m, u=u[None, :], y=y), ValueError,
             f"u has shape (1, {N}): give samples × channels (u.T?)"),
            ("channels", lambda: lpvid.invalidate(model=m, u=np.column_stack([u, u]), y=y), ValueError,
             "u has 2 channels; the model has 1 input (u)"),
            ("text", lambda: lpvid.invalidate(model=m, u="u", y=y), TypeError,
             "u: expected an array of numbers (samples × channels), not str"),
            ("lpvid's own refusal", lambda: lpvid.invalidate(model=m, u=text_u, y=y), ValueError,
             "u[3]: 'abc' is not a number"),
            ("records", lambda: lpvid.invalidate(model=m, records=[(u, y), {"u": u, "y": nan_y}]), ValueError,
             "records[1]['y'][10] is NaN"),
            ("data", lambda: lpvid.invalidate(model=m, data={"u": u, "y": nan_y}), ValueError,
             "data['y'][10] is NaN"),
            ("test", lambda: lpvid.diagnose(model=m, u=u, y=y, test=[(u, np.where(np.arange(N) == 10, np.inf, y))]),
             ValueError, "test[0][1][10] is inf"),
        ]
        for name, call, kind, message in table:
            with self.subTest(name):
                self.assertRefused(call, kind, message)
        self.assertNextCallAnswers()

    def test_a_column_the_model_does_not_read_may_hold_nan(self):
        r = lpvid.invalidate(model=lti_model(), data={"u": self.u, "y": self.y, "notes": np.full(N, np.nan)},
                             delta=0, dmax="1/100")
        self.assertTrue(r.consistent)

    def test_bad_model(self):
        two_states = dict(lti_model(), states=2)
        self.assertRefused(lambda: lpvid.invalidate(model=two_states, u=self.u, y=self.y), ValueError,
                           "model: initial.A[0].value is 1×1; A is states × states = 2×2")
        wide_b = lti_model()
        wide_b["initial"]["B"] = [{"basis": "1", "value": [[1, 0]]}]
        self.assertRefused(lambda: lpvid.Model(wide_b), ValueError,
                           "model: initial.B[0].value is 1×2; B is states × inputs = 1×1")
        few_names = dict(lti_model(), inputs=2)
        self.assertRefused(lambda: lpvid.Model(few_names), ValueError,
                           "model: columns.u has 1 name(s); the model has 2 inputs")
        self.assertRefused(lambda: lpvid.Model(dict(lti_model(), states="two")), ValueError,
                           "model: states is 'two'; expected a whole number in 0..1000")
        self.assertRefused(lambda: lpvid.Model([lti_model()]), TypeError,
                           "a model is an lpvid-model/1 dict, not list")
        # spellings the model format allows stay allowed
        lpvid.Model(dict(lti_model(), states="1", inputs=1.0, x0=[np.float64(0.5)]))
        self.assertNextCallAnswers()

    def test_missing_files(self):
        e = self.assertRefused(lambda: lpvid.invalidate(model=lti_model(), data="no_such_data.csv"),
                               FileNotFoundError, "data: no_such_data.csv: no such file")
        self.assertEqual(e.filename, "no_such_data.csv")
        self.assertRefused(lambda: lpvid.invalidate(model="no_such_model.json", u=self.u, y=self.y),
                           FileNotFoundError, re.compile(r"no_such_model\.json: no such file$"))
        self.assertNextCallAnswers()

    def test_keywords_and_option_values(self):
        m, u, y = lti_model(), self.u, self.y
        self.assertRefused(lambda: lpvid.diagnose(model=m, u=u, y=y, holdot=0.3), TypeError,
                           "diagnose() got an unexpected keyword argument 'holdot'; did you mean holdout=?")
        self.assertRefused(lambda: lpvid.invalidate(model=m, u=u, y=y, report="r.json"), TypeError,
                           re.compile(r"^invalidate\(\) got the keyword argument 'report', .* give out_dir="))
        self.assertRefused(lambda: lpvid.identify(model=m, u=u, y=y, iterate=1), TypeError,
                           "identify(): iterate=1: iterate= is a switch: give True or False")
        e = self.assertRefused(lambda: lpvid.diagnose(model=m, u=u, y=y, max_effects=-1), ValueError,
                               "max_effects=-1: must be between 0 and 20")
        self.assertIn("--max-effects", e.detail)  # lpvid's own words stay at hand
        self.assertRefused(lambda: lpvid.invalidate(model=m, u=u, y=y, solver="nope"), ValueError,
                           re.compile(r"^solver='nope': must be one of 'csdp', "))
        self.assertRefused(lambda: lpvid.invalidate(model=m, u=u, y=y, delta=-1), ValueError,
                           re.compile(r"^delta=-1: must be "))
        self.assertNextCallAnswers()

    def test_quiet_is_honoured_by_every_command(self):
        # the mechanism: a command's progress lines, then none with quiet (without --quiet)
        folder = os.path.join(SCRATCH, "quiet")
        r = lpvid.invalidate(model=lti_model(), u=self.u, y=self.y, delta=0, dmax="1/100", out_dir=folder)
        args = ["invalidate", "--data", os.path.join(folder, "data.csv"), "--model", os.path.join(folder, "model.json"),
                "--delta", "0", "--dmax", "1/100"]
        self.assertTrue(r.consistent)
        for quiet in (False, True):
            lines = []
            code, _, _ = _run.run_captured("lpvid", args, lines.append, quiet=quiet)
            self.assertEqual(code, 0)
            self.assertEqual(bool([ln for ln in lines if ln.startswith("[invalidate")]), not quiet, lines)
        # fit-linear has no --quiet: quiet=True is taken, and nothing reaches the logger or the callback
        lines = []
        with self.assertNoLogs("lpvid", level="INFO"):
            model = lpvid.fit_linear(u=self.u, y=self.y, order=1, quiet=True, progress=lines.append)
        self.assertEqual(lines, [])
        np.testing.assert_allclose(model.simulate(u=self.u).y[:, 0], self.y, atol=1e-8)

    def test_sigterm_handler_is_put_back(self):
        before = signal.getsignal(signal.SIGTERM)
        self.assertNextCallAnswers()
        self.assertIs(signal.getsignal(signal.SIGTERM), before)
        seen = []
        mine = lambda signum, frame: seen.append(signum)  # noqa: E731 - a caller's own handler
        signal.signal(signal.SIGTERM, mine)
        try:
            self.assertNextCallAnswers()
            self.assertIs(signal.getsignal(signal.SIGTERM), mine)
        finally:
            signal.signal(signal.SIGTERM, before)

    def test_sigterm_stops_the_run_and_leaves_nothing(self):
        folder = os.path.join(SCRATCH, "sigterm_tmp")
        os.makedirs(folder, exist_ok=True)
        child = textwrap.dedent("""
            import lpvid
            g = lpvid.generate("effect-case", effect="output_offset", n=600)
            d = g.data
            said = []

            def progress(line):
                if not said:
                    said.append(line)
                    print("running", flush=True)

            try:
                # the residual, the effect search and the refits of diagnose: seconds, SIGTERM comes at its first line
                lpvid.diagnose(model=g.model, u=d["u1"], y=d["y1"], rho=d["rho1"], max_effects=2, progress=progress)
            finally:
                print("unwound", flush=True)
            print("returned", flush=True)
        """)
        env = dict(os.environ, TMPDIR=folder)
        p = subprocess.Popen([sys.executable, "-c", child], env=env, stdout=subprocess.PIPE, text=True, cwd=SCRATCH)
        try:
            ready, _, _ = select.select([p.stdout], [], [], 120)
            self.assertTrue(ready, "no progress line within 120 s")
            self.assertEqual(p.stdout.readline().strip(), "running")
            self.assertTrue([n for n in os.listdir(folder) if n.startswith("lpvid-diagnose-")])
            sent = time.monotonic()
            p.send_signal(signal.SIGTERM)
            out, _ = p.communicate(timeout=60)
        finally:
            if p.poll() is None:
                p.kill()
                p.wait()
        took = time.monotonic() - sent
        print(f"\n  SIGTERM: exit code {p.returncode} {took:.3f} s later", file=sys.stderr)
        self.assertIn(p.returncode, (-signal.SIGTERM, 128 + signal.SIGTERM))
        self.assertLess(took, 20)
        self.assertEqual(out.split(), ["unwound"])  # the call unwound (finally ran), and went no further
        self.assertEqual([n for n in os.listdir(folder) if n.startswith("lpvid-")], [])


if __name__ == "__main__":
    SCRATCH = os.path.abspath(sys.argv[1])
    os.makedirs(os.path.join(SCRATCH, "tmp"), exist_ok=True)
    os.environ["TMPDIR"] = os.path.join(SCRATCH, "tmp")
    tempfile.tempdir = None
    unittest.main(argv=sys.argv[:1], verbosity=2)
