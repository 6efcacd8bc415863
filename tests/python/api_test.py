"""The Python API (one function per command, Model, Certificate, options,
folders, progress, Ctrl-C) against answers known by construction.

- fit_linear on a noise-free first-order record returns a Model whose
  simulation reproduces the record (the system is in the model class);
- compare scores two models on columns named differently from theirs: the
  true model's RMS is 0 and the wrong gain's RMS equals the one computed
  here with numpy;
- diagnose with test arrays finds the undeclared output offset of a
  generated effect case (the error on the test record drops);
- an in-memory certificate verifies, survives save/load, and a changed
  claim is refused; no call leaves a folder behind;
- a misspelt option is refused with "did you mean";
- with logging.basicConfig (a handler on sys.stderr) a run finishes and
  stderr holds each progress line once, in order;
- Ctrl-C (SIGINT) during a run raises KeyboardInterrupt, leaves nothing,
  and the next call answers as before.

Usage: api_test.py SCRATCH_DIR (with the package on PYTHONPATH).
"""

import json
import logging
import os
import re
import signal
import subprocess
import sys
import tempfile
import textwrap
import threading
import time
import unittest

import numpy as np

import lpvid

SCRATCH = None


def first_order(u, a=0.5, b=1.0):
    """y_k = x_k, x_{k+1} = a x_k + b u_k, x_0 = 0."""
    x, y = 0.0, []
    for uk in u:
        y.append(x)
        x = a * x + b * uk
    return np.array(y)


def lti_model(a, b, u_name="u", y_name="y"):
    """The first-order system as an lpvid model (no scheduling)."""
    return {"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": [],
            "columns": {"u": [u_name], "y": [y_name], "rho": []},
            "initial": {"A": [{"basis": "1", "value": [[str(a)]]}], "B": [{"basis": "1", "value": [[str(b)]]}],
                        "C": [{"basis": "1", "value": [["1"]]}]},
            "uncertainty": {"structure": "additive", "weight": "1/10"}}


def leftovers():
    return sorted(n for n in os.listdir(tempfile.gettempdir()) if n.startswith("lpvid-"))


class Api(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rng = np.random.default_rng(7)
        cls.u = rng.standard_normal(150)
        cls.y = first_order(cls.u)

    def setUp(self):
        self.before = leftovers()

    def tearDown(self):
        self.assertEqual(leftovers(), self.before, "a call left a folder behind")

    def test_fit_linear_returns_a_model_that_reproduces_the_record(self):
        m = lpvid.fit_linear(u=self.u, y=self.y, order=1)
        self.assertIsInstance(m, lpvid.Model)
        self.assertEqual((m.states, m.inputs, m.outputs), (1, 1, 1))
        sim = m.simulate(self.u)
        self.assertEqual(sim.y.shape, (150, 1))
        np.testing.assert_allclose(sim.y[:, 0], self.y, atol=1e-8)
        self.assertIsNotNone(m.report)

    def test_fit_linear_on_two_records_gives_each_its_own_initial_state(self):
        # the second record starts from x0 = 3 (the first from rest): one
        # first-order model reproduces both only from each one's own state
        u2 = np.random.default_rng(8).standard_normal(120)
        x, y2 = 3.0, []
        for uk in u2:
            y2.append(x)
            x = 0.5 * x + uk
        m = lpvid.fit_linear(records=[(self.u, self.y), (u2, np.array(y2))], order=1)
        records = m.report["records"]
        self.assertEqual([r["samples"] for r in records], [150, 120])
        for r in records:
            self.assertLess(r["rms_estimation"], 1e-8)
        self.assertNotAlmostEqual(records[0]["x0"][0], records[1]["x0"][0], delta=0.1)
        with self.assertRaises(lpvid.LpvidError):
            lpvid.fit_linear(records=[(self.u, self.y), (u2, np.column_stack([y2, y2]))], order=1)

    def test_pandas_frame_in_series_in(self):
        try:
            import pandas as pd
        except ImportError:
            self.skipTest("pandas (Debian: python3-pandas) is not installed")
        frame = pd.DataFrame({"uEst": self.u, "yEst": self.y})
        m = lpvid.fit_linear(data=frame, u="uEst", y="yEst", order=1)
        self.assertEqual(m.columns[:2], (["uEst"], ["yEst"]))
        np.testing.assert_allclose(m.simulate(frame["uEst"]).y[:, 0], self.y, atol=1e-8)

    def test_compare_scores_two_models_on_other_columns(self):
        table = {"uVal": self.u, "yVal": self.y}
        true, wrong = lti_model("1/2", 1), lti_model("1/2", 2)
        c = lpvid.compare(data=table, u="uVal", y="yVal", models={"true": true, "wrong": wrong})
        self.assertEqual([s.name for s in c.scores], ["true", "wrong"])
        self.assertLess(c.score("true").rms, 1e-12)
        expected = np.sqrt(np.mean((first_order(self.u, 0.5, 2.0) - self.y) ** 2))
        self.assertAlmostEqual(c.score("wrong").rms, expected, delta=1e-9 * expected)
        # the same with arrays (the models' own column names do not matter)
        c2 = lpvid.compare(u=self.u, y=self.y, models=[true, wrong])
        self.assertAlmostEqual(c2.scores[1].rms, expected, delta=1e-9 * expected)

    def test_certificate_in_memory_save_load_verify(self):
        # a gain twice the true one: at delta = 0 the smallest d_max is the RMS of y (the error is y itself)
        rms = float(np.sqrt(np.mean(self.y ** 2)))
        self.assertTrue(0.2 < rms < 2.5, rms)
        r = lpvid.invalidate(lti_model("1/2", 2), u=self.u, y=self.y, delta=0, dmax="5/2")
        self.assertTrue(r.consistent)
        cert = r.certificate
        self.assertIsInstance(cert, lpvid.Certificate)
        self.assertIsNone(cert.path)
        self.assertEqual(cert.dmax2, lpvid.exact("25/4"))
        self.assertTrue(lpvid.verify(cert))
        path = cert.save(os.path.join(SCRATCH, "saved", "c.json"))
        self.assertTrue(os.path.isfile(os.path.join(SCRATCH, "saved", "data.csv")))
        self.assertTrue(lpvid.Certificate.load(path).verify())
        self.assertTrue(lpvid.verify(path))
        # saving changes the data reference only: every number keeps its exact text
        crafted = lpvid.Certificate('{"format": "lpvid-certificate/1", "data": {"file": "sub/d.csv", '
                                    '"sha256": "00"}, "dmax2": 0.10000000000000001}', {"sub/d.csv": b"u,y\n"})
        crafted.save(os.path.join(SCRATCH, "crafted", "c.json"))
        with open(os.path.join(SCRATCH, "crafted", "c.json")) as f:
            self.assertEqual(f.read(), '{"format": "lpvid-certificate/1", "data": {"file": "d.csv", '
                                       '"sha256": "00"}, "dmax2": 0.10000000000000001}')
        with open(os.path.join(SCRATCH, "crafted", "d.csv"), "rb") as f:
            self.assertEqual(f.read(), b"u,y\n")
        # the same certificate claiming d_max = 0.1, far below the RMS of the error: false
        text, n = re.subn(r'"dmax2": [^,\n]+', '"dmax2": "1/100"', cert.text)
        self.assertEqual(n, 1)
        bad = lpvid.Certificate(text, cert.files)
        self.assertIsNone(bad.path)
        self.assertFalse(lpvid.verify(bad))

    def test_misspelt_and_managed_options_are_refused(self):
        with self.assertRaises(lpvid.LpvidError) as e:
            lpvid.diagnose(lti_model("1/2", 1), u=self.u, y=self.y, holdot=0.3)
        self.assertEqual(e.exception.code, 2)
        self.assertIn("did you mean holdout=", e.exception.message)
        with self.assertRaises(lpvid.LpvidError) as e:
            lpvid.invalidate(lti_model("1/2", 1), u=self.u, y=self.y, report="r.json")
        self.assertIn("out_dir=", e.exception.message)

    def test_progress_goes_to_logging_and_the_callback(self):
        lines = []
        with self.assertLogs("lpvid", level="INFO") as logs:
            lpvid.invalidate(lti_model("1/2", 1), u=self.u, y=self.y, delta=0, progress=lines.append)
        self.assertTrue(lines)
        self.assertEqual([r.getMessage() for r in logs.records if r.levelno == logging.INFO],
                         [ln for ln in lines if ln in [r.getMessage() for r in logs.records]])

    def test_logging_to_stderr_neither_blocks_nor_repeats_a_line(self):
        # logging.basicConfig's handler writes to sys.stderr: the run finishes, and
        # what reaches stderr is exactly the lines the progress callback got, in
        # order and each once (the handler's own output is never read back)
        code = textwrap.dedent("""
            import json, logging, lpvid
            logging.basicConfig(level=logging.INFO, format="%(message)s")
            lines = []
            g = lpvid.generate("effect-case", effect="output_offset", n=200)
            d = g.data
            lpvid.diagnose(g.model, u=d["u1"], y=d["y1"], rho=d["rho1"], max_effects=1, progress=lines.append)
            print(json.dumps(lines))
        """)
        p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600,
                           env=os.environ, cwd=SCRATCH)
        self.assertEqual(p.returncode, 0, p.stderr[-3000:])
        lines = json.loads(p.stdout.strip().splitlines()[-1])
        self.assertGreater(len([ln for ln in lines if ln.startswith("[diagnose")]), 5)
        self.assertEqual(p.stderr.splitlines(), lines)

    def test_diagnose_with_test_arrays_finds_the_offset(self):
        g = lpvid.generate("effect-case", effect="output_offset", n=200)
        d, v = g.data, g.validation
        lines = []
        r = lpvid.diagnose(g.model, u=d["u1"], y=d["y1"], rho=d["rho1"], test=(v["u1"], v["y1"], v["rho1"]),
                           max_effects=1, quiet=True, progress=lines.append)
        self.assertFalse([ln for ln in lines if ln.startswith("[diagnose")], "quiet=True: no progress lines")
        self.assertIsInstance(r.model, lpvid.Model)
        self.assertLess(r.rms_after, 0.5 * r.rms_before)
        self.assertIs(r.after_worse, False)
        # one entry per signal of the test record (u1, y1 and the scheduling column rho1), each
        # with its test range inside-or-not against the estimation range it states
        self.assertGreaterEqual(len(r.test_range), 3)
        for s in r.test_range:
            lo, hi = s["estimation_range"]
            tlo, thi = s["test_range"]
            self.assertEqual(s["samples_below"] > 0, tlo < lo, s)
            self.assertEqual(s["samples_above"] > 0, thi > hi, s)
        self.assertTrue(r.certificates)
        for c in r.certificates:
            self.assertTrue(lpvid.verify(c), c)

    def test_ctrl_c_stops_a_run_and_leaves_nothing(self):
        rng = np.random.default_rng(3)
        u = rng.standard_normal(1200)
        y = first_order(u) + 0.01 * rng.standard_normal(1200)
        model = lti_model("1/2", 1)
        sent = {}

        def interrupt():
            sent["at"] = time.monotonic()
            os.kill(os.getpid(), signal.SIGINT)

        lines = []
        timer = threading.Timer(1.0, interrupt)
        start = time.monotonic()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            # Theorem 3.1 with iterations on 1200 samples: far longer than a second
            lpvid.identify(dict(model, correction={"basis": ["1"]}), u=u, y=y, delta="1/100", iterate=True,
                           progress=lines.append)
        stopped = time.monotonic() - sent["at"]
        print(f"\n  Ctrl-C after {sent['at'] - start:.2f} s; KeyboardInterrupt {stopped:.3f} s later",
              file=sys.stderr)
        self.assertTrue(any("interrupted" in ln for ln in lines), lines[-3:])  # the run itself was stopped
        # the run after the interrupt answers as a run never interrupted
        a = lpvid.invalidate(model, u=self.u, y=self.y, delta=0, dmax="1/100")
        self.assertTrue(a.consistent)


if __name__ == "__main__":
    SCRATCH = sys.argv[1]
    os.makedirs(os.path.join(SCRATCH, "tmp"), exist_ok=True)
    os.environ["TMPDIR"] = os.path.join(SCRATCH, "tmp")
    tempfile.tempdir = None
    unittest.main(argv=sys.argv[:1], verbosity=2)
