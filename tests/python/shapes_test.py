"""The shapes scientific Python users expect, against answers known by
construction or computed here independently (numpy, scipy):

- Model.matrices(rho) of a hand-written LPV model (basis functions 1, p,
  p*q, q^2, "p ^ 2 * q", two terms on one function, text numbers "1/10",
  a correction with fixed A_i, B_i, a general uncertainty channel, output
  and state offsets) equals the matrices written out here as formulas in
  p and q; a missing rho, a wrong length and an unknown basis name are
  refused with messages naming them;
- a numpy simulation with matrices(rho_k) along a scheduling trajectory
  reproduces `lpvid simulate`'s y and z (multiplicative and general
  channels) to 1e-12;
- to_scipy(): scipy.signal.dlsim of the StateSpace from the model's x0
  reproduces lpvid.simulate's y to 1e-10 on a 2-state SISO model, a MIMO
  model and a model from lpvid.fit_linear; scheduled models, static blocks
  and offsets are refused saying why;
- to_pandas() of Simulation, Comparison, Tradeoff, Generated and Diagnosis
  holds the arrays the results hold, with the names and index promised;
- every result's repr is one line under 300 characters even with a large
  report, and its _repr_html_ table holds the same numbers;
- benchmarks.Record unpacks as u, y and slices into a Record with the
  sampling time, names, units and warm-up known by construction.

Usage: shapes_test.py SCRATCH_DIR (with the package on PYTHONPATH).
"""

import copy
import os
import sys
import tempfile
import unittest
from fractions import Fraction

import numpy as np

import lpvid
from lpvid import benchmarks
from lpvid.results import (BasisSelection, Bounds, Comparison, Diagnosis, Generated, Identification, Interval,
                           ModelScore, OracleRun, Simulation, Tradeoff, TradeoffPoint)

SCRATCH = None

try:
    import pandas  # noqa: F401
    HAVE_PANDAS = True
except ImportError:
    HAVE_PANDAS = False


def lpv_model(uncertainty):
    """2 states, 2 inputs, 2 outputs, scheduled on p and q (see lpv_matrices)."""
    return {
        "format": "lpvid-model/1", "states": 2, "inputs": 2, "outputs": 2, "scheduling": ["p", "q"],
        "columns": {"u": ["u1", "u2"], "y": ["pos", "vel"], "rho": ["p", "q"]},
        "initial": {
            "A": [{"basis": "1", "value": [["1/2", "1/10"], [0, "0.3"]]},
                  {"basis": "p", "value": [["-1/5", 0], ["0.05", 0]]},
                  {"basis": "p*q", "value": [[0, "0.02"], [0, "-0.1"]]},
                  {"basis": "1", "value": [["0.01", 0], [0, 0]]}],
            "B": [{"basis": "1", "value": [[1, 0], [0, "1/2"]]}, {"basis": "q^2", "value": [["0.1", 0], [0, 0]]}],
            "C": [{"basis": "1", "value": [[1, 0], [0, 1]]}, {"basis": " p ^ 2 * q ", "value": [["0.2", 0], [0, 0]]}],
            "D": [{"basis": "q", "value": [["1/4", 0], [0, 0]]}]},
        "correction": {"basis": ["1", "q"], "A": [{"basis": "q", "value": [[0, 0], ["0.03", 0]]}],
                       "B": [{"basis": "1", "value": [[0, "0.2"], [0, 0]]}]},
        "uncertainty": uncertainty,
        "offset": {"basis": ["1", "p"], "values": [["0.5", -1], [0, "0.25"]]},
        "state_offset": {"basis": ["q"], "values": [["0.01", "-0.02"]]},
        "x0": ["0.1", "-0.2"]}


GENERAL = {"structure": "general", "C1": [{"basis": "p", "value": [[1, 2]]}],
           "D1": [{"basis": "1", "value": [[0, "1/3"]]}]}


def lpv_matrices(p, q):
    """The matrices of lpv_model written out by hand (exact, then floats)."""
    F = Fraction
    A = [[F(1, 2) + F(1, 100) - F(1, 5) * p, F(1, 10) + F(2, 100) * p * q],
         [F(5, 100) * p + F(3, 100) * q, F(3, 10) - F(1, 10) * p * q]]
    B = [[1 + F(1, 10) * q * q, F(1, 5)], [0, F(1, 2)]]
    C = [[1 + F(1, 5) * p * p * q, 0], [0, 1]]
    D = [[F(1, 4) * q, 0], [0, 0]]
    C1, D1 = [[p, 2 * p]], [[0, F(1, 3)]]
    offset = [F(1, 2), -1 + F(1, 4) * p]
    state_offset = [F(1, 100) * q, -F(2, 100) * q]
    as_float = (lambda m: np.array(m, dtype=float))
    return {k: as_float(v) for k, v in dict(A=A, B=B, C=C, D=D, C1=C1, D1=D1, offset=offset,
                                            state_offset=state_offset).items()}


def numpy_simulation(model, u, rho):
    """x_{k+1} = A x + B u + E, y = C x + D u + Φ, z = C1 x + D1 u with matrices(rho_k)."""
    x, ys, zs = model.x0, [], []
    for uk, rk in zip(u, rho):
        m = model.matrices(rk)
        ys.append(m.C @ x + m.D @ uk + m.offset)
        zs.append(m.C1 @ x + m.D1 @ uk)
        x = m.A @ x + m.B @ uk + m.state_offset
    return np.array(ys), np.array(zs)


def lti_model(A, B, C, D, x0, sample_time=None, names=None):
    nx, nu, ny = len(A), len(B[0]), len(C)
    doc = {"format": "lpvid-model/1", "states": nx, "inputs": nu, "outputs": ny,
           "columns": {"u": [f"u{j + 1}" for j in range(nu)], "y": names or [f"y{j + 1}" for j in range(ny)]},
           "initial": {"A": [{"basis": "1", "value": A}], "B": [{"basis": "1", "value": B}],
                       "C": [{"basis": "1", "value": C}], "D": [{"basis": "1", "value": D}]},
           "x0": x0}
    if sample_time is not None:
        doc["sample_time"] = sample_time
    return lpvid.Model(doc)


class Matrices(unittest.TestCase):
    def test_matrices_equal_the_model_written_out(self):
        model = lpvid.Model(lpv_model(GENERAL))
        for p, q in [(0, 0), (1, 0), (Fraction(1, 2), Fraction(-3, 4)), (-2, 3)]:
            got, expected = model.matrices([float(p), float(q)]), lpv_matrices(p, q)
            for name, value in expected.items():
                np.testing.assert_allclose(getattr(got, name), value, rtol=0, atol=1e-15, err_msg=name)
            self.assertEqual(got.uncertainty, "general")
            A, B, C, D = got
            self.assertIs(A, got.A)
            self.assertIs(D, got.D)
        by_name = model.matrices({"q": -0.75, "p": 0.5})
        np.testing.assert_array_equal(by_name.A, model.matrices([0.5, -0.75]).A)
        np.testing.assert_array_equal(model.x0, [0.1, -0.2])

    def test_uncertainty_structures(self):
        weighted = lpvid.Model(lpv_model({"structure": "multiplicative", "weight": "1/2"}))
        m = weighted.matrices([0.5, 0.25])
        np.testing.assert_allclose(m.C1, 0.5 * m.C, atol=1e-16)
        np.testing.assert_allclose(m.D1, 0.5 * m.D, atol=1e-16)
        additive = lpvid.Model(lpv_model({"structure": "additive", "weight": "0.1"})).matrices([0.5, 0.25])
        np.testing.assert_array_equal(additive.C1, np.zeros((2, 2)))
        np.testing.assert_allclose(additive.D1, 0.1 * np.eye(2), atol=1e-17)
        default = copy.deepcopy(lpv_model(GENERAL))
        del default["uncertainty"]
        m = lpvid.Model(default).matrices([2, 3])
        np.testing.assert_array_equal(m.C1, m.C)  # multiplicative with weight 1

    def test_refusals_name_what_is_wrong(self):
        model = lpvid.Model(lpv_model(GENERAL))
        with self.assertRaises(lpvid.LpvidValueError) as e:
            model.matrices()
        self.assertIn("rho", str(e.exception))
        self.assertIn("p, q", str(e.exception))
        with self.assertRaises(ValueError) as e:
            model.matrices([1.0])
        self.assertIn("1 value(s) for 2", str(e.exception))
        bad = lpv_model(GENERAL)
        bad["initial"]["B"][1]["basis"] = "q*r"
        with self.assertRaises(lpvid.LpvidValueError) as e:
            lpvid.Model(bad).matrices([1, 2])
        self.assertIn("'r'", str(e.exception))
        self.assertIn("initial.B[1]", str(e.exception))
        lti = lti_model([[0.5]], [[1]], [[1]], [[0]], [0])
        self.assertEqual(lti.matrices().A.tolist(), [[0.5]])
        with self.assertRaises(lpvid.LpvidValueError):
            lti.matrices(0.3)

    def test_static_blocks_are_named_not_matrices(self):
        doc = lti_model([[0.5]], [[1]], [[1]], [[0]], [0]).to_dict()
        doc["static"] = {"input_delay": 2, "input": {"kind": "saturation", "lower": -1, "upper": 1},
                         "output": {"kind": "identity"}}
        model = lpvid.Model(doc)
        self.assertTrue(model.has_static_blocks)
        self.assertEqual(model.static_blocks, {"input_delay": 2,
                                               "input": {"kind": "saturation", "lower": -1, "upper": 1}})
        with self.assertRaises(lpvid.LpvidValueError) as e:
            model.to_scipy()
        self.assertIn("static blocks", str(e.exception))
        doc["static"] = {"input_delay": 0, "output": {"kind": "identity"}}
        self.assertFalse(lpvid.Model(doc).has_static_blocks)


class AgainstTheProgram(unittest.TestCase):
    def test_numpy_simulation_with_matrices_is_lpvid_simulate(self):
        rng = np.random.default_rng(3)
        n = 80
        u, rho = rng.standard_normal((n, 2)), rng.uniform(-1, 1, (n, 2))
        for uncertainty in (GENERAL, {"structure": "multiplicative", "weight": "1/2"}):
            model = lpvid.Model(lpv_model(uncertainty))
            sim = lpvid.simulate(model, u=u, rho=rho)
            y, z = numpy_simulation(model, u, rho)
            self.assertEqual(sim.y.shape, (n, 2))
            self.assertGreater(np.abs(y).max(), 0.5)
            np.testing.assert_allclose(sim.y, y, rtol=0, atol=1e-12)
            np.testing.assert_allclose(sim.z, z, rtol=0, atol=1e-12)

    def assert_dlsim_is_simulate(self, model, u):
        import scipy.signal
        system = model.to_scipy()
        _, y, _ = scipy.signal.dlsim(system, u, x0=model.x0)
        sim = lpvid.simulate(model, u=u)
        self.assertGreater(np.abs(y).max(), 0.1)
        np.testing.assert_allclose(sim.y, y.reshape(sim.y.shape), rtol=0, atol=1e-10)
        return system

    def test_to_scipy_dlsim_is_lpvid_simulate(self):
        u = np.random.default_rng(5).standard_normal((120, 2))
        siso = lti_model([[0, 1], ["-3/25", "0.7"]], [[0], [1]], [["1/4", "0.5"]], [[0]], ["1", "-1/2"],
                         sample_time="1/10")
        system = self.assert_dlsim_is_simulate(siso, u[:, :1])
        self.assertEqual(system.dt, 0.1)
        np.testing.assert_array_equal(system.A, [[0, 1], [-0.12, 0.7]])
        mimo = lti_model([[0.5, 0.1, 0], [0, -0.3, 0.2], [0.1, 0, 0.6]], [[1, 0], [0, 1], ["1/2", "-1/2"]],
                         [[1, 0, 0], [0, 1, 1]], [["0.1", 0], [0, "-0.2"]], [0, "0.3", -1])
        system = self.assert_dlsim_is_simulate(mimo, u)
        self.assertIs(system.dt, True)
        x, y = 0.0, []
        for uk in u[:, 0]:
            y.append(x)
            x = 0.8 * x + 0.5 * uk
        fitted = lpvid.fit_linear(u=u[:, 0], y=np.array(y), order=2)
        self.assert_dlsim_is_simulate(fitted, u[:, :1])

    def test_to_scipy_refuses_what_is_not_lti(self):
        with self.assertRaises(lpvid.LpvidValueError) as e:
            lpvid.Model(lpv_model(GENERAL)).to_scipy()
        self.assertIn("initial.A[1] depends on the scheduling", str(e.exception))
        doc = lti_model([[0.5]], [[1]], [[1]], [[0]], [0]).to_dict()
        doc["offset"] = {"basis": ["1"], "values": [["0.5"]]}
        with self.assertRaises(lpvid.LpvidValueError) as e:
            lpvid.Model(doc).to_scipy()
        self.assertIn("output offset", str(e.exception))
        doc["offset"] = {"basis": ["1"]}  # unknown offset values: simulated as zero
        self.assertEqual(lpvid.Model(doc).to_scipy().A.tolist(), [[0.5]])


@unittest.skipUnless(HAVE_PANDAS, "pandas (Debian: python3-pandas) is not installed")
class ToPandas(unittest.TestCase):
    def test_simulation_frame_has_the_output_names_and_time(self):
        u = np.random.default_rng(9).standard_normal((30, 2))
        model = lti_model([[0.5, 0], [0, 0.2]], [[1, 0], [0, 1]], [[1, 0], [0, 1]], [[0, 0], [0, 0]], [0, 0],
                          sample_time="1/4", names=["pos", "vel"])
        sim = model.simulate(u)
        frame = sim.to_pandas()
        self.assertEqual(list(frame.columns), ["pos", "vel"])
        self.assertEqual(frame.index.name, "time [s]")
        np.testing.assert_array_equal(frame.index.to_numpy(), np.arange(30) * 0.25)
        np.testing.assert_array_equal(frame.to_numpy(), sim.y)
        with_z = sim.to_pandas(z=True)
        self.assertEqual(list(with_z.columns), ["pos", "vel", "z1", "z2"])
        np.testing.assert_array_equal(with_z[["z1", "z2"]].to_numpy(), sim.z)
        plain = Simulation(y=np.ones((4, 1)), z=np.zeros((4, 1)), columns=["flow_hat", "z1"])
        self.assertEqual(plain.to_pandas().index.name, "sample")
        self.assertEqual(list(plain.to_pandas().index), [0, 1, 2, 3])
        self.assertEqual(list(plain.to_pandas().columns), ["flow"])

    def test_comparison_frame_from_a_run(self):
        u = np.random.default_rng(2).standard_normal(40)
        true, slow = (lti_model([[a]], [[1]], [[1]], [[0]], [0]) for a in ("0.5", "0.9"))
        y = lpvid.simulate(true, u=u).y[:, 0]
        c = lpvid.compare(data={"volts": u, "y": y}, u="volts", y="y",
                          models={"true": true, "slow": slow})
        frame = c.to_pandas()
        self.assertEqual(list(frame.columns), ["y", "true:y", "slow:y"])
        self.assertEqual(frame.index.name, "sample")
        np.testing.assert_array_equal(frame.index.to_numpy(), np.arange(40))
        np.testing.assert_array_equal(frame["y"].to_numpy(), y)
        np.testing.assert_array_equal(frame["slow:y"].to_numpy(), c.score("slow").yhat[:, 0])
        np.testing.assert_allclose(frame["true:y"].to_numpy(), y, atol=1e-12)

    def test_tradeoff_generated_and_diagnosis_frames(self):
        t = Tradeoff(command="tradeoff", code=0, report={}, output="", messages="", out_dir=None,
                     points=[TradeoffPoint(0.1, 0.3, 0.2, True), TradeoffPoint(0.9, None, 0.5, False)])
        frame = t.to_pandas()
        self.assertEqual(list(frame.columns), ["lambda", "delta", "dmax", "verified"])
        self.assertEqual(frame["lambda"].tolist(), [0.1, 0.9])
        self.assertTrue(np.isnan(frame["delta"][1]))
        self.assertEqual(frame["verified"].tolist(), [True, False])
        data = {"u1": np.arange(5.0), "y1": np.arange(5.0) ** 2}
        g = Generated(command="generate", code=0, report={}, output="", messages="", out_dir=None, data=data)
        np.testing.assert_array_equal(g.to_pandas()["y1"].to_numpy(), data["y1"])
        with self.assertRaises(lpvid.LpvidValueError):
            g.to_pandas("validation")
        d = diagnosis()
        row = d.to_pandas()
        self.assertEqual(len(row), 1)
        self.assertEqual(row["rms_before"][0], d.rms_before)
        self.assertEqual(row["dmax"][0], d.dmax)
        self.assertEqual(row["effects"][0], "output_offset, input_saturation")

    def test_without_pandas_the_error_says_so(self):
        saved = sys.modules.get("pandas")
        sys.modules["pandas"] = None
        try:
            with self.assertRaises(ImportError) as e:
                diagnosis().to_pandas()
        finally:
            sys.modules["pandas"] = saved
        self.assertIn("pip install pandas", str(e.exception))


def big_report():
    return {"rounds": [{"candidates": list(range(2000))}], "note": "x" * 5000}


def common():
    return dict(code=0, report=big_report(), output="o" * 3000, messages="m" * 3000, out_dir=None)


def diagnosis():
    return Diagnosis(command="diagnose", **common(), effects=[{"kind": "output_offset"}, {"kind": "input_saturation"}],
                     rms_before=0.500799968945556, rms_after=0.020738058474082124, fit_before=85.25324654459287,
                     fit_after=99.38933894883218, after_worse=False, test_range=[{"signal": "u1"}] * 500,
                     delta=0.0001757197410933103, dmax=0.020016020308097987, verified=True)


class Display(unittest.TestCase):
    def check(self, result, numbers):
        text, html = repr(result), result._repr_html_()
        self.assertLess(len(text), 300, text)
        self.assertNotIn("\n", text)
        self.assertTrue(text.startswith(f"<lpvid.{type(result).__name__} "), text)
        self.assertTrue(html.startswith("<table>"), html)
        for number in numbers:
            self.assertIn(f"{number:.4g}", text)
            self.assertIn(f"{number:.4g}", html)

    def test_diagnosis(self):
        d = diagnosis()
        self.check(d, [d.rms_before, d.rms_after, d.fit_before, d.fit_after, d.delta, d.dmax])
        self.assertIn("output_offset", repr(d))

    def test_every_result(self):
        interval = Interval(of="dmax^2", lower=Fraction(1, 8), upper=Fraction(3, 16), lower_verified=True,
                            upper_verified=True, relative_gap=0.5)
        self.check(interval, [0.125, 0.1875, 0.5])
        bounds = dict(verdict="consistent", delta=0.0123, dmax=0.456, verified=True, interval=interval)
        self.check(Bounds(command="certify", **common(), **bounds), [0.0123, 0.456, 0.125])
        model = lpvid.Model(lpv_model(GENERAL))
        self.check(Identification(command="identify", **common(), **bounds, model=model, theta={"t": [1] * 999}),
                   [0.0123, 0.456])
        self.check(BasisSelection(command="select-basis", **common(), **bounds, basis=["1", "p"],
                                  steps=[{}] * 300), [0.0123])
        points = [TradeoffPoint(k / 10, 1 / (k + 1), k * 0.7, True) for k in range(1, 10)]
        self.check(Tradeoff(command="tradeoff", **common(), points=points), [0.1, 0.9, 0.1, 0.5, 0.7, 6.3])
        self.check(points[0], [0.1, 0.5, 0.7])
        scores = [ModelScore(name=f"m{k}", rms=0.25 * k, fit_percent=90.5 + k, outputs=[{"name": "y"}],
                             yhat=np.zeros((5000, 1))) for k in (1, 2)]
        self.check(Comparison(command="compare", **common(), scores=scores, y=np.zeros((5000, 1))),
                   [0.25, 0.5, 91.5, 92.5])
        self.check(scores[0], [0.25, 91.5])
        self.check(Simulation(y=np.zeros((5000, 2)), z=np.zeros((5000, 2)), columns=["a_hat", "b_hat", "z1", "z2"],
                              sample_time=0.25), [5000, 0.25])
        self.check(Generated(command="generate", **common(), data={"u1": np.zeros(4321)}, model=model), [4321])
        self.check(OracleRun(command="oracle", **common(), cases=[{}] * 37, passed=True), [37])
        self.check(model.matrices([0.5, 0.25]), [0.5, 0.25])
        self.assertLess(len(repr(model)), 300)
        self.assertIn("2", model._repr_html_())


class Records(unittest.TestCase):
    def record(self):
        k = np.arange(1000.0)
        return benchmarks.Record(u=k, y=10 * k, sampling_time=0.02, name="ced train", warmup=50, u_names=("u11",),
                                 y_names=("z11",), u_units=("V",), y_units=("",), source="DATAUNIF.csv")

    def test_unpacks_like_nonlinear_benchmarks(self):
        r = self.record()
        u, y = r
        self.assertIs(u, r.u)
        self.assertIs(y, r.y)
        self.assertIs(r[0], r.u)
        self.assertIs(r[1], r.y)
        self.assertEqual(len(r), 1000)
        with self.assertRaises(IndexError):
            r[2]
        with self.assertRaises(TypeError):
            r["u"]

    def test_slices_are_records(self):
        r = self.record()
        part = r[100:200]
        self.assertIsInstance(part, benchmarks.Record)
        self.assertEqual(len(part), 100)
        np.testing.assert_array_equal(part.u[:, 0], np.arange(100.0, 200.0))
        np.testing.assert_array_equal(part.y[:, 0], 10 * np.arange(100.0, 200.0))
        self.assertEqual((part.sampling_time, part.warmup), (0.02, 0))
        self.assertEqual((part.u_names, part.y_names, part.u_units, part.source),
                         (("u11",), ("z11",), ("V",), "DATAUNIF.csv"))
        self.assertEqual(part.name, "ced train[100:200]")
        self.assertEqual(r[10:100].warmup, 40)  # samples 10..49 were warm-up samples
        self.assertEqual(r[:20].warmup, 20)
        every4 = r[0:100:4]
        np.testing.assert_array_equal(every4.u[:, 0], np.arange(0.0, 100.0, 4))
        self.assertEqual((len(every4), every4.sampling_time, every4.warmup), (25, 0.08, 13))
        self.assertEqual(len(r[-10:]), 10)
        with self.assertRaises(ValueError):
            r[::-1]
        self.assertLess(len(repr(r)), 200)


if __name__ == "__main__":
    SCRATCH = sys.argv[1] if len(sys.argv) > 1 else tempfile.mkdtemp(prefix="shapes_test-")
    os.makedirs(os.path.join(SCRATCH, "tmp"), exist_ok=True)
    os.environ["TMPDIR"] = os.path.join(SCRATCH, "tmp")
    tempfile.tempdir = None
    unittest.main(argv=sys.argv[:1], verbosity=2)
