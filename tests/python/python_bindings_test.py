"""The Python module lpvid against answers known by construction.

Data come from a small SISO LPV model written here, with noise of a known
RMS. At delta = 0 the model explains the data only through the noise, so the
smallest d_max is the RMS of y - y_model, which this test computes exactly
(Fractions, from the very text of data.csv) and holds against the certified
interval; a model with three times the output gain must be invalidated; every
certificate must be accepted by lpvid.verify and by the lpvid-verify program,
and refused once one digit is changed; bad arrays raise LpvidError and leave
no certificate.

Usage: python_bindings_test.py LPVID_VERIFY_PROGRAM SCRATCH_DIR
(with the package on PYTHONPATH: <build>/python).
"""

import copy
import csv
import glob
import os
import shutil
import subprocess
import sys
import unittest
from fractions import Fraction

import numpy as np

import lpvid

VERIFY_PROGRAM = None
SCRATCH = None

N = 120           # samples
NOISE_RMS = 0.02  # RMS of the added noise, exactly (before rounding y to doubles)

# x+ = A(rho) x + B u, y = C(rho) x with A(rho) = A0 + rho A1, C(rho) = C0 + rho C1:
# poles inside the unit circle for every |rho| <= 1.
A0 = [[0, 1], [Fraction(-3, 25), Fraction(7, 10)]]
A1 = [[0, 0], [Fraction(1, 20), Fraction(-1, 10)]]
B0 = [[1], [1]]
C0 = [[Fraction(1, 4), Fraction(1, 2)]]
C1 = [[Fraction(1, 10), 0]]


def text_matrix(m):
    return [[str(v) for v in row] for row in m]


def true_model():
    return {
        "format": "lpvid-model/1",
        "description": "SISO LPV test model of the Python bindings' test",
        "states": 2, "inputs": 1, "outputs": 1,
        "scheduling": ["rho1"],
        "columns": {"u": ["u"], "y": ["y"], "rho": ["p"]},
        "initial": {
            "A": [{"basis": "1", "value": text_matrix(A0)}, {"basis": "rho1", "value": text_matrix(A1)}],
            "B": [{"basis": "1", "value": text_matrix(B0)}],
            "C": [{"basis": "1", "value": text_matrix(C0)}, {"basis": "rho1", "value": text_matrix(C1)}],
        },
        "uncertainty": {"structure": "additive", "weight": "1/10"},
    }


def simulate(u, rho, scalar):
    """y_k = C(rho_k) x_k, x_{k+1} = A(rho_k) x_k + B u_k, x_0 = 0, in `scalar`
    arithmetic (float for the data, Fraction for the exact answer)."""
    S = scalar
    x = [S(0), S(0)]
    y = []
    for uk, rk in zip(u, rho):
        uk, rk = S(uk), S(rk)
        c = [S(C0[0][j]) + rk * S(C1[0][j]) for j in range(2)]
        y.append(c[0] * x[0] + c[1] * x[1])
        a = [[S(A0[i][j]) + rk * S(A1[i][j]) for j in range(2)] for i in range(2)]
        x = [a[i][0] * x[0] + a[i][1] * x[1] + S(B0[i][0]) * uk for i in range(2)]
    return y


def make_data():
    rng = np.random.default_rng(20261126)
    u = rng.standard_normal(N)
    rho = np.sin(np.arange(N) * 0.2) * 0.8
    noise = rng.standard_normal(N)
    noise *= NOISE_RMS / np.sqrt(np.mean(noise ** 2))
    y = np.array(simulate(u, rho, float)) + noise
    return u, y, rho


def exact_min_dmax2(data_csv):
    """min d_max^2 at delta = 0: mean of (y - y_model)^2, exactly, from the
    numbers as written in the data file."""
    with open(data_csv, newline="") as f:
        rows = list(csv.DictReader(f))
    u = [Fraction(r["u"]) for r in rows]
    y = [Fraction(r["y"]) for r in rows]
    rho = [Fraction(r["p"]) for r in rows]
    y_model = simulate(u, rho, Fraction)
    return sum((a - b) ** 2 for a, b in zip(y, y_model)) / len(y)


def program_verdict(certificate):
    return subprocess.run([VERIFY_PROGRAM, "certificate", certificate], capture_output=True, text=True).returncode


class Bindings(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.u, cls.y, cls.rho = make_data()
        cls.certificates = []  # every certificate returned, checked by test_z_every_certificate_verifies

    def out(self, name):
        path = os.path.join(SCRATCH, name)
        shutil.rmtree(path, ignore_errors=True)
        return path

    def test_consistent_at_the_true_noise_level(self):
        r = lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta=0, dmax=1.01 * NOISE_RMS,
                             out_dir=self.out("consistent"))
        self.assertEqual(r.code, 0, r.output + r.messages)
        self.assertEqual(r.verdict, "consistent")
        self.assertTrue(r.consistent)
        self.assertTrue(os.path.isfile(r.certificate))
        self.assertTrue(os.path.isfile(os.path.join(r.out_dir, "data.csv")))
        self.certificates.extend(r.certificates)

    def test_min_dmax_at_delta_zero_brackets_the_exact_answer(self):
        r = lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta=0, out_dir=self.out("min_dmax"))
        self.assertEqual(r.code, 0, r.output + r.messages)
        interval = r.interval
        self.assertEqual(interval.of, "dmax^2")
        self.assertTrue(interval.upper_verified and interval.lower_verified, interval)
        truth = exact_min_dmax2(os.path.join(r.out_dir, "data.csv"))
        # the written y differs from the float sum by rounding only
        self.assertAlmostEqual(float(truth) ** 0.5, NOISE_RMS, delta=NOISE_RMS * 1e-12)
        # exact comparisons: the certified interval contains the exact optimum
        lower, upper = interval.lower, interval.upper
        self.assertIsInstance(lower, Fraction)
        self.assertGreaterEqual(lower, 0)
        self.assertLessEqual(lower, truth)
        self.assertLessEqual(truth, upper)
        self.assertEqual(r.dmax2, upper)
        self.assertIn(truth, interval)
        # the reported bound: at least the optimum, at most the true noise RMS (to the solver's accuracy)
        self.assertGreaterEqual(r.dmax, float(truth) ** 0.5)
        self.assertLessEqual(r.dmax, NOISE_RMS * (1 + 1e-9))
        self.assertIsNotNone(r.interval.lower_certificate)
        self.assertIn(r.certificate, r.certificates)
        self.assertIn(r.interval.lower_certificate, r.certificates)
        self.certificates.extend(r.certificates)

        # A Delta allowed (delta > 0) can only lower the smallest d_max:
        # both certified ends at delta = 0.01 lie below the answer at 0.
        r = lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta="0.01", out_dir=self.out("min_dmax_001"))
        self.assertEqual(r.code, 0, r.output + r.messages)
        lower, upper = r.interval.lower, r.interval.upper
        self.assertTrue(0 < lower <= upper <= truth, (lower, upper, truth))
        self.certificates.extend(r.certificates)

    def test_two_records_pool_the_noise_bound_exactly(self):
        # Two records of one system (the halves of the data), each simulated
        # from rest: at delta = 0 the smallest d_max^2 is the mean of
        # (y - y_model)^2 over every sample of both records, exactly.
        h = N // 2
        records = [{"u": self.u[:h], "y": self.y[:h], "rho": self.rho[:h]},
                   (self.u[h:], self.y[h:], self.rho[h:])]
        r = lpvid.invalidate(None, None, None, true_model(), delta=0, records=records, out_dir=self.out("two_records"))
        self.assertEqual(r.code, 0, r.output + r.messages)
        paths = [os.path.join(r.out_dir, "data1.csv"), os.path.join(r.out_dir, "data2.csv")]
        per_record = [exact_min_dmax2(p) for p in paths]
        truth = (per_record[0] * h + per_record[1] * (N - h)) / N
        lower, upper = r.interval.lower, r.interval.upper
        self.assertLessEqual(lower, truth)
        self.assertLessEqual(truth, upper)
        self.assertEqual([e["samples"] for e in r.report["records"]], [h, N - h])
        # record 2 starts from rest although the data ran on: its transient makes it worse than the noise
        self.assertGreater(per_record[1], per_record[0])
        self.assertTrue(lpvid.verify(r.certificate))
        self.certificates.extend(r.certificates)
        with self.assertRaises(lpvid.LpvidError):
            lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta=0, records=records)

    def test_wrong_gain_is_invalidated(self):
        wrong = copy.deepcopy(true_model())
        wrong["initial"]["C"] = [{"basis": "1", "value": text_matrix([[3 * c for c in C0[0]]])},
                                 {"basis": "rho1", "value": text_matrix([[3 * c for c in C1[0]]])}]
        r = lpvid.invalidate(self.u, self.y, self.rho, wrong, delta="0.01", dmax=NOISE_RMS,
                             out_dir=self.out("wrong_gain"))
        self.assertEqual(r.code, 1, r.output + r.messages)
        self.assertEqual(r.verdict, "invalidated")
        self.assertTrue(r.invalidated)
        self.assertTrue(os.path.isfile(r.certificate))
        self.certificates.extend(r.certificates)

    def test_identify_finds_the_missing_gain(self):
        start = copy.deepcopy(true_model())
        start["initial"]["C"] = [{"basis": "1", "value": text_matrix(C0)}]  # the rho1 term is missing
        start["correction"] = {"basis": ["rho1"]}
        r = lpvid.identify(self.u, self.y, self.rho, start, delta=0, out_dir=self.out("identify"))
        self.assertEqual(r.code, 0, r.output + r.messages)
        self.assertEqual(r.model.document["format"], "lpvid-model/1")
        theta = r.report["theta"]["rho1"]["C"][0]
        self.assertAlmostEqual(theta[0], float(C1[0][0]), delta=0.02)
        self.assertAlmostEqual(theta[1], float(C1[0][1]), delta=0.02)
        # the least-squares theta explains the data at least as well as the true one
        self.assertLessEqual(r.dmax, NOISE_RMS * (1 + 1e-6))
        self.certificates.extend(r.certificates)

    def test_tampered_certificate_is_refused(self):
        r = lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta=0, dmax=1.01 * NOISE_RMS,
                             out_dir=self.out("tampered"))
        self.assertTrue(lpvid.verify(r.certificate))
        with open(r.certificate) as f:
            text = f.read()
        # the first digit of the claimed d_max^2 (0.00040804) drops by one:
        # 0.0003... is below the noise's mean square, so the claim is false
        key = '"dmax2": "'
        at = text.index(key)
        digit = next(i for i in range(at + len(key), len(text)) if text[i] in "123456789")
        bad = text[:digit] + str(int(text[digit]) - 1) + text[digit + 1:]
        tampered = os.path.join(r.out_dir, "tampered.cert.json")
        with open(tampered, "w") as f:
            f.write(bad)
        v = lpvid.verify(tampered)
        self.assertFalse(v)
        self.assertEqual(v.code, 1, v.output + v.messages)
        self.assertEqual(program_verdict(tampered), 1)
        # no certificate at all: not an answer but bad input
        with self.assertRaises(lpvid.LpvidError) as e:
            lpvid.verify(os.path.join(r.out_dir, "missing.cert.json"))
        self.assertEqual(e.exception.code, 2)

    def test_nan_in_y_is_refused_without_certificate(self):
        y = self.y.copy()
        y[7] = np.nan
        out = self.out("nan")
        # a finished run first: the failing run in the same folder must not
        # leave its certificate behind looking like its own
        good = lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta=0, dmax=1.01 * NOISE_RMS, out_dir=out)
        self.assertTrue(os.path.isfile(good.certificate))
        with self.assertRaises(lpvid.LpvidError) as e:
            lpvid.invalidate(self.u, y, self.rho, true_model(), delta=0, out_dir=out)
        self.assertEqual(e.exception.code, 2)
        self.assertIsInstance(e.exception, ValueError)
        self.assertEqual(e.exception.message, "y[7] is NaN")  # the argument and index, no file of the package
        self.assertEqual(glob.glob(os.path.join(out, "*cert*")), [])

    def test_mismatched_lengths_are_refused_without_certificate(self):
        out = self.out("lengths")
        with self.assertRaises(lpvid.LpvidError) as e:
            lpvid.invalidate(self.u, self.y[:-1], self.rho, true_model(), delta=0, out_dir=out)
        self.assertEqual(e.exception.code, 2)
        self.assertIn("samples", e.exception.message)
        self.assertEqual(glob.glob(os.path.join(out, "*cert*")), [])

    def test_bad_option_is_refused(self):
        with self.assertRaises(lpvid.LpvidError) as e:
            lpvid.invalidate(self.u, self.y, self.rho, true_model(), delta=0, out_dir=self.out("option"),
                             no_such_option=1)
        self.assertEqual(e.exception.code, 2)
        self.assertIn("no_such_option", e.exception.message)

    def test_z_every_certificate_verifies(self):
        # named to run last (unittest sorts by name): the other tests collect the certificates
        self.assertGreaterEqual(len(self.certificates), 7)
        for c in self.certificates:
            with self.subTest(certificate=c):
                v = lpvid.verify(c)
                self.assertTrue(v.ok, v.output + v.messages)
                self.assertEqual(program_verdict(c), 0)


if __name__ == "__main__":
    VERIFY_PROGRAM, SCRATCH = sys.argv[1], sys.argv[2]
    os.makedirs(SCRATCH, exist_ok=True)
    unittest.main(argv=sys.argv[:1], verbosity=2)
