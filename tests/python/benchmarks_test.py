"""lpvid.benchmarks against answers known from the files themselves.

Real data: the Cascaded Tanks dataBenchmark.csv, read from $LPVID_DATA or
<repository>/../shared/data (skipped with a message when absent); lengths,
sampling time and warm-up are the benchmark's, and the first and last values
are parsed here from the file's text, independently of the loader.
Synthetic data: for every other benchmark a file in the layout that
nonlinear_benchmarks reads (names of files, columns and variables) is written
here with sample k holding a value made from k, so that every split's length
and first/last values are known by construction (the splits of
nonlinear_benchmarks 1.0.1).

Usage: PYTHONPATH=python /usr/bin/python3 tests/python/benchmarks_test.py
(or with <build>/python on PYTHONPATH). Needs numpy; scipy for the .mat cases.
"""

import csv
import importlib.util
import os
import sys
import tempfile
import unittest

import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def import_benchmarks():
    """lpvid.benchmarks; when the package's __init__ cannot load (no compiled
    extension on this path), the same file loaded on its own: the module
    imports nothing from the package."""
    try:
        from lpvid import benchmarks
        return benchmarks
    except ImportError as e:
        for base in sys.path + [os.path.join(ROOT, "python")]:
            file = os.path.join(base or ".", "lpvid", "benchmarks.py")
            if os.path.isfile(file):
                print(f"[benchmarks_test] import lpvid failed ({e}); loading {file} alone", file=sys.stderr)
                spec = importlib.util.spec_from_file_location("lpvid_benchmarks", file)
                module = importlib.util.module_from_spec(spec)
                sys.modules[spec.name] = module  # dataclasses look the module up by name
                spec.loader.exec_module(module)
                return module
        raise


B = import_benchmarks()

try:
    import scipy.io
    HAVE_SCIPY = True
except ImportError:
    HAVE_SCIPY = False


def data_dir():
    return os.environ.get("LPVID_DATA", os.path.join(ROOT, "..", "shared", "data"))


def write_csv(path, columns):
    """CSV with a header; a shorter column (fs) leaves its later cells empty."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    names = list(columns)
    n = max(len(v) for v in columns.values())
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(names)
        for k in range(n):
            w.writerow([repr(float(columns[c][k])) if k < len(columns[c]) else "" for c in names])
    return path


def write_mat(path, variables, rows=False):
    """MATLAB file; vectors as columns (N x 1), or as rows (1 x N) if `rows`."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    shaped = {k: (np.atleast_2d(v) if rows else np.asarray(v, float).reshape(-1, 1)) if np.size(v) > 1
              else np.array([[v]], float) for k, v in variables.items()}
    with open(path, "wb") as f:
        scipy.io.savemat(f, shaped)
    return path


class CascadedTanksReal(unittest.TestCase):
    def setUp(self):
        self.file = os.path.join(data_dir(), "cascaded-tanks", "dataBenchmark.csv")
        if not os.path.isfile(self.file):
            self.skipTest(f"{self.file} not present (set LPVID_DATA to the folder holding cascaded-tanks/)")

    def text_values(self):
        """Columns uEst, uVal, yEst, yVal and Ts of the file, parsed from its text."""
        with open(self.file, "rb") as f:
            lines = [l for l in f.read().decode().split("\r\n") if l]
        header = [h.strip('"') for h in lines[0].split(",")]
        body = [l.split(",") for l in lines[1:]]
        cols = {h: [float(r[i]) for r in body if r[i]] for i, h in enumerate(header) if h}
        return cols

    def check(self, train, test):
        t = self.text_values()
        self.assertEqual((len(train), len(test)), (1024, 1024))
        self.assertEqual((train.sampling_time, test.sampling_time), (4.0, 4.0))
        self.assertEqual(t["Ts"], [4.0])
        self.assertEqual((train.warmup, test.warmup), (0, 50))
        self.assertEqual(train.u.shape, (1024, 1))
        self.assertEqual(test.y.shape, (1024, 1))
        for rec, u, y in ((train, "uEst", "yEst"), (test, "uVal", "yVal")):
            for k in (0, -1):
                self.assertEqual(rec.u[k, 0], t[u][k])
                self.assertEqual(rec.y[k, 0], t[y][k])
            self.assertEqual((rec.u[:, 0].tolist(), rec.y[:, 0].tolist()), (t[u], t[y]))
            self.assertEqual((rec.u_names, rec.y_names), ((u,), (y,)))

    def test_file_folder_and_name(self):
        self.check(*B.cascaded_tanks(self.file))
        self.check(*B.cascaded_tanks(os.path.dirname(self.file)))
        self.check(*B.cascaded_tanks(data_dir()))       # found one level down
        self.check(*B.load("Cascaded_Tanks", self.file))
        self.check(*B.load("tanks", self.file))

    def test_to_csv_round_trip(self):
        train, _ = B.cascaded_tanks(self.file)
        with tempfile.TemporaryDirectory() as d:
            out = train.to_csv(os.path.join(d, "t.csv"), y_names=["level"])
            with open(out) as f:
                rows = list(csv.reader(f))
        self.assertEqual(rows[0], ["uEst", "level"])
        self.assertEqual(len(rows), 1025)
        self.assertEqual([float(x) for x in rows[1]], [train.u[0, 0], train.y[0, 0]])
        self.assertEqual([float(x) for x in rows[-1]], [train.u[-1, 0], train.y[-1, 0]])


class Synthetic(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def need_scipy(self):
        if not HAVE_SCIPY:
            self.skipTest("scipy not importable: .mat layouts not tested")

    def span(self, rec, first, last):
        """rec.u runs first..last (u = k), y = 1000000 + k."""
        self.assertEqual(len(rec), last - first + 1)
        self.assertEqual((rec.u[0, 0], rec.u[-1, 0]), (first, last))
        self.assertEqual((rec.y[0, 0], rec.y[-1, 0]), (1e6 + first, 1e6 + last))

    # Cascaded Tanks, the .mat of the package's cache: <cache>/Cascaded_Tanks/CascadedTanksFiles/
    def test_tanks_mat_in_package_cache(self):
        self.need_scipy()
        k = np.arange(1024.0)
        write_mat(os.path.join(self.dir, "Cascaded_Tanks", "CascadedTanksFiles", "dataBenchmark.mat"),
                  {"uEst": k, "yEst": 1e6 + k, "uVal": 2000 + k, "yVal": 1e6 + 2000 + k, "Ts": 4.0})
        train, test = B.cascaded_tanks(self.dir)
        self.span(train, 0, 1023)
        self.span(test, 2000, 3023)
        self.assertEqual((test.warmup, test.sampling_time), (50, 4.0))

    def ced_columns(self, names, n=500):
        k = np.arange(float(n))
        return {u: 10000 * i + k for i, u in enumerate(names["u"])} | \
               {y: 1e6 + 10000 * i + k for i, y in enumerate(names["y"])}

    def check_ced(self, trains, tests):
        self.assertEqual([len(r) for r in trains + tests], [400, 400, 100, 100])
        self.span(trains[0], 0, 399)
        self.span(tests[0], 400, 499)
        self.span(trains[1], 10000, 10399)
        self.span(tests[1], 10400, 10499)
        self.assertEqual([r.warmup for r in trains + tests], [0, 0, 10, 10])
        self.assertEqual({r.sampling_time for r in trains + tests}, {0.02})
        self.assertEqual((tests[1].u_names, tests[1].y_names), (("u12",), ("z12",)))

    def test_ced_csv_and_mat(self):
        cols = self.ced_columns({"u": ["u11", "u12"], "y": ["z11", "z12"]})
        self.check_ced(*B.coupled_electric_drives(write_csv(os.path.join(self.dir, "DATAUNIF.csv"), cols)))
        self.check_ced(*B.load("CED", self.dir))
        if HAVE_SCIPY:
            os.remove(os.path.join(self.dir, "DATAUNIF.csv"))
            write_mat(os.path.join(self.dir, "ced", "DATAUNIF.MAT"), cols)
            self.check_ced(*B.load("coupled electric drives", self.dir))

    def test_ced_prbs_whole_records(self):
        cols = self.ced_columns({"u": ["u1", "u2", "u3"], "y": ["z1", "z2", "z3"]})
        recs = B.coupled_electric_drives_prbs(write_csv(os.path.join(self.dir, "DATAPRBS.csv"), cols))
        for i, r in enumerate(recs):
            self.span(r, 10000 * i, 10000 * i + 499)
            self.assertEqual((r.warmup, r.sampling_time), (0, 0.02))

    def check_silverbox(self, train, tests):
        self.span(train, 40650, 40650 + 65062 - 1)
        multisine, arrow, arrow_short = tests
        self.span(multisine, 40650 + 65062, 127399)
        self.span(arrow, 100, 40574)
        self.span(arrow_short, 100, 32099)
        self.assertEqual([len(r) for r in tests], [21688, 40475, 32000])
        self.assertEqual([train.warmup] + [r.warmup for r in tests], [0, 50, 50, 50])
        self.assertEqual(train.sampling_time, 1 / 610.35)

    def test_silverbox_csv_and_row_vector_mat(self):
        k = np.arange(131072.0)
        cols = {"V1": k, "V2": 1e6 + k}
        write_csv(os.path.join(self.dir, "SilverboxFiles", "SNLS80mV.csv"), cols)
        self.check_silverbox(*B.silverbox(self.dir))
        if HAVE_SCIPY:
            other = os.path.join(self.dir, "m")
            write_mat(os.path.join(other, "Silverbox", "SilverboxFiles", "SNLS80mV.mat"), cols, rows=True)
            self.check_silverbox(*B.load("Silverbox", other))

    def check_wh(self, train, test):
        self.span(train, 5200, 105199)
        self.span(test, 105200, 183999)
        self.assertEqual((train.warmup, test.warmup), (0, 50))
        self.assertEqual(test.sampling_time, 1 / 51200.0)

    def test_wiener_hammerstein_csv_and_mat(self):
        k = np.arange(188000.0)
        cols = {"uBenchMark": k, "yBenchMark": 1e6 + k, "fs": [51200.0]}
        self.check_wh(*B.load("wh", write_csv(os.path.join(self.dir, "WienerHammerBenchmark.csv"), cols)))
        if HAVE_SCIPY:
            other = os.path.join(self.dir, "m")
            write_mat(os.path.join(other, "WienerHammerBenchMark.mat"), cols | {"fs": 51200.0})
            self.check_wh(*B.wiener_hammerstein(other))

    def test_emps_two_mat_files(self):
        self.need_scipy()
        for name, n, first in (("DATA_EMPS.mat", 300, 0), ("DATA_EMPS_PULSES.mat", 200, 5000)):
            k = np.arange(float(n))
            write_mat(os.path.join(self.dir, "EMPS", name),
                      {"vir": first + k, "qm": 1e6 + first + k, "qg": -k, "t": k / 1000})
        for path in (self.dir, os.path.join(self.dir, "EMPS", "DATA_EMPS_PULSES.mat")):
            train, test = B.emps(path)
            self.span(train, 0, 299)
            self.span(test, 5000, 5199)
            self.assertEqual((train.warmup, test.warmup), (0, 20))
            self.assertEqual(test.sampling_time, 0.001)
            self.assertEqual((test.u_units, test.y_units), (("N",), ("m",)))


class Refusals(unittest.TestCase):
    def test_missing_file_names_the_files_and_where_to_get_them(self):
        with tempfile.TemporaryDirectory() as d:
            with self.assertRaises(FileNotFoundError) as c:
                B.silverbox(d)
        msg = str(c.exception)
        for part in ("SNLS80mV.csv", "SNLS80mV.mat", "nonlinearbenchmark.org/benchmarks/silverbox", "downloads nothing"):
            self.assertIn(part, msg)
        with self.assertRaises(FileNotFoundError) as c:
            B.emps("/nonexistent/emps")
        self.assertIn("DATA_EMPS.mat", str(c.exception))

    def test_misspelt_name_suggests(self):
        with self.assertRaises(ValueError) as c:
            B.load("silverbx", ".")
        self.assertIn("did you mean 'silverbox'", str(c.exception))
        with self.assertRaises(ValueError) as c:
            B.load("cascaded_tank", ".")
        self.assertIn("'cascaded_tanks'", str(c.exception))

    def test_bad_cell_names_file_line_column(self):
        with tempfile.TemporaryDirectory() as d:
            cols = {"u11": list(range(500)), "u12": list(range(500)), "z11": list(range(500)), "z12": list(range(500))}
            f = write_csv(os.path.join(d, "DATAUNIF.csv"), cols)
            with open(f) as g:
                text = g.read().splitlines()
            text[7] = "6.0,abc,6.0,6.0"  # line 8 = data row 7
            with open(f, "w") as g:
                g.write("\n".join(text) + "\n")
            with self.assertRaises(ValueError) as c:
                B.coupled_electric_drives(d)
        self.assertIn("DATAUNIF.csv:8: column 'u12': 'abc' is not a number", str(c.exception))

    def test_value_after_empty_cell_refused(self):
        with tempfile.TemporaryDirectory() as d:
            f = write_csv(os.path.join(d, "WienerHammerBenchmark.csv"),
                          {"uBenchMark": [1.0, 2.0, 3.0], "yBenchMark": [1.0, 2.0, 3.0], "fs": [51200.0]})
            with open(f) as g:
                text = g.read().splitlines()
            text[3] = "3.0,3.0,51200.0"  # fs again on line 4 after the empty cell on line 3
            with open(f, "w") as g:
                g.write("\n".join(text) + "\n")
            with self.assertRaises(ValueError) as c:
                B.wiener_hammerstein(f)
        self.assertIn("WienerHammerBenchmark.csv:4: column 'fs' has a value after the empty cell on line 3",
                      str(c.exception))

    def test_short_file_refused(self):
        with tempfile.TemporaryDirectory() as d:
            f = write_csv(os.path.join(d, "SNLS80mV.csv"), {"V1": np.arange(1000.0), "V2": np.arange(1000.0)})
            with self.assertRaises(ValueError) as c:
                B.silverbox(f)
        self.assertIn("1000 samples", str(c.exception))

    def test_mat_without_scipy_names_python3_scipy(self):
        saved = {k: sys.modules[k] for k in list(sys.modules) if k == "scipy" or k.startswith("scipy.")}
        sys.modules.update({"scipy": None, "scipy.io": None})
        try:
            with tempfile.TemporaryDirectory() as d:
                open(os.path.join(d, "DATA_EMPS.mat"), "wb").close()
                with self.assertRaises(ImportError) as c:
                    B.emps(d)
        finally:
            for k in ("scipy", "scipy.io"):
                sys.modules.pop(k, None)
            sys.modules.update(saved)
        self.assertIn("python3-scipy", str(c.exception))


if __name__ == "__main__":
    unittest.main(verbosity=2)
