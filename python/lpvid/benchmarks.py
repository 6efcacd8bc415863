"""Nonlinear system identification benchmarks, loaded from files you have.

Nothing is downloaded. Each loader takes the benchmark's file, or a folder
holding it (the unpacked zip from nonlinearbenchmark.org, or the cache of the
Python package nonlinear_benchmarks, ~/.nonlinear_benchmarks), finds the file
by its official name, and returns the train and test records with the splits
and warm-up windows of nonlinear_benchmarks 1.0.1 (MaartenSchoukens/
nonlinear_benchmarks on GitHub):

    from lpvid import benchmarks
    train, test = benchmarks.cascaded_tanks("~/data/CascadedTanksFiles")
    train.u, train.y, train.sampling_time      # numpy arrays (samples x channels), seconds
    test.warmup                                # 50: the first 50 test samples are not scored
    u, y = train                               # unpacks like nonlinear_benchmarks' records
    part = train[100:200]                      # a Record of samples 100..199, same sampling time

    trains, tests = benchmarks.load("coupled electric drives", "~/data")

`warmup` is the package's state_initialization_window_length: a model may use
those first samples of a test record to set its state, and the error is
scored on the samples after them.

This module uses only numpy (and scipy.io for MATLAB .mat files); it imports
nothing from the rest of lpvid.

Layouts checked against real files: Cascaded Tanks dataBenchmark.csv. The
others (Cascaded Tanks .mat, Coupled Electric Drives, Silverbox,
Wiener-Hammerstein, EMPS) follow the layout nonlinear_benchmarks reads
(variable and column names) and are tested on synthetic files in that layout.
"""

from __future__ import annotations

import csv
import dataclasses
import difflib
import math
import os
from typing import Dict, Iterator, List, Sequence, Tuple, Union

import numpy as np

__all__ = ["Record", "BENCHMARKS", "load", "cascaded_tanks", "coupled_electric_drives",
           "coupled_electric_drives_prbs", "silverbox", "wiener_hammerstein", "emps"]

_SITE = "https://www.nonlinearbenchmark.org/benchmarks/"
_SEARCH_DEPTH = 3  # folder levels searched below `path` for the official file names


@dataclasses.dataclass(repr=False)
class Record:
    """One input/output record of a benchmark.

    u: samples x inputs, y: samples x outputs (float numpy arrays);
    sampling_time in seconds; warmup: number of samples at the start whose
    error is not scored (0 for training records); u_names/y_names: the
    columns or variables the data came from; u_units/y_units: units where the
    benchmark states them ("" otherwise); source: the file read.

    Like the records of nonlinear_benchmarks (its Input_output_data):
    `u, y = record` unpacks (iteration yields u, then y; record[0] is u,
    record[1] is y), `record[100:200]` is a Record of those samples, and
    len(record) is the number of samples.
    """

    u: np.ndarray
    y: np.ndarray
    sampling_time: float
    name: str
    warmup: int = 0
    u_names: Tuple[str, ...] = ()
    y_names: Tuple[str, ...] = ()
    u_units: Tuple[str, ...] = ()
    y_units: Tuple[str, ...] = ()
    source: str = ""

    def __post_init__(self):
        self.u = _as_columns(self.u, "u")
        self.y = _as_columns(self.y, "y")
        if self.u.shape[0] != self.y.shape[0]:
            raise ValueError(f"Record {self.name!r}: u has {self.u.shape[0]} samples, y has {self.y.shape[0]}")
        if not 0 <= self.warmup <= self.u.shape[0]:
            raise ValueError(f"Record {self.name!r}: warmup {self.warmup} outside 0..{self.u.shape[0]}")
        self.u_names = _labels(self.u_names, self.u.shape[1], "u")
        self.y_names = _labels(self.y_names, self.y.shape[1], "y")
        self.u_units = _labels(self.u_units, self.u.shape[1], None)
        self.y_units = _labels(self.y_units, self.y.shape[1], None)

    def __len__(self) -> int:
        """Number of samples."""
        return self.u.shape[0]

    def __iter__(self) -> Iterator[np.ndarray]:
        """u, then y: `u, y = record`."""
        yield self.u
        yield self.y

    def __getitem__(self, key: Union[int, slice]) -> Union[np.ndarray, "Record"]:
        """record[0] is u and record[1] is y (as in `u, y = record`);
        record[a:b] or record[a:b:step] is a Record of those samples.

        A slice keeps the names, units and source, notes the slice in the
        name ("... train[100:200]"), multiplies the sampling time by the
        step, and keeps as warm-up the selected samples that were warm-up
        samples of this record. A negative step is refused (a record runs
        forward in time).
        """
        if isinstance(key, slice):
            return self._slice(key)
        if isinstance(key, (int, np.integer)) and not isinstance(key, (bool, np.bool_)):
            if -2 <= key < 2:
                return (self.u, self.y)[key]
            raise IndexError(f"Record index {key}: 0 is u and 1 is y (samples are selected with a slice, "
                             f"record[a:b])")
        raise TypeError(f"Record indices are 0 (u), 1 (y) or a slice of samples, not {type(key).__name__}")

    def _slice(self, key: slice) -> "Record":
        start, stop, step = key.indices(len(self))
        if step < 0:
            raise ValueError(f"Record {self.name!r}[{key.start}:{key.stop}:{key.step}]: a negative step would "
                             f"run the record backwards in time")
        note = f"{start}:{max(stop, start)}" + (f":{step}" if step != 1 else "")
        warmup = len(range(start, min(stop, self.warmup), step))  # the selected samples below self.warmup
        return Record(u=self.u[key], y=self.y[key], sampling_time=self.sampling_time * step,
                      name=f"{self.name}[{note}]", warmup=warmup, u_names=self.u_names, y_names=self.y_names,
                      u_units=self.u_units, y_units=self.y_units, source=self.source)

    def __repr__(self) -> str:
        warmup = f", warmup={self.warmup}" if self.warmup else ""
        return (f"<lpvid.benchmarks.Record {self.name!r}: {len(self)} samples, u={list(self.u_names)}, "
                f"y={list(self.y_names)}, sampling_time={self.sampling_time:.6g} s{warmup}>")

    def to_csv(self, path: str, u_names: Sequence[str] = None, y_names: Sequence[str] = None) -> str:
        """Write the record as CSV (header u_names + y_names, one row per sample,
        numbers in shortest round-trip form) for the lpvid command line. Column
        names default to the record's own; returns the path written."""
        u_names = _labels(u_names or self.u_names, self.u.shape[1], "u")
        y_names = _labels(y_names or self.y_names, self.y.shape[1], "y")
        with open(path, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(list(u_names) + list(y_names))
            for row in np.hstack([self.u, self.y]):
                w.writerow([repr(float(v)) for v in row])
        return path


def _as_columns(a, what: str) -> np.ndarray:
    a = np.asarray(a, dtype=float)
    if a.ndim == 1:
        a = a[:, None]
    if a.ndim != 2:
        raise ValueError(f"{what} must be 1-D or samples x channels, got shape {a.shape}")
    return a


def _labels(given, count: int, prefix) -> Tuple[str, ...]:
    given = tuple(given or ())
    if given and len(given) != count:
        raise ValueError(f"{len(given)} names for {count} columns: {given}")
    if given:
        return given
    if prefix is None:
        return ("",) * count
    return (prefix,) if count == 1 else tuple(f"{prefix}{i + 1}" for i in range(count))


# ---------------------------------------------------------------- files

def _locate(path, names: Sequence[str], benchmark: str, page: str) -> str:
    """The file `path` itself, or the first of `names` (official file names,
    in order of preference, matched without regard to case) found in the
    folder `path` or up to _SEARCH_DEPTH levels below it."""
    path = os.path.expanduser(os.fspath(path))
    if os.path.isfile(path):
        return path
    if os.path.isdir(path):
        found = _search(path, [n.lower() for n in names])
        if found:
            return found
    raise FileNotFoundError(
        f"{benchmark}: no {' or '.join(names)} at {path!r} (a file, or a folder searched {_SEARCH_DEPTH} levels "
        f"deep). Get the files from {_SITE}{page} (unpack the zip), or point at the cache of the Python "
        f"package nonlinear_benchmarks; lpvid downloads nothing.")


def _search(root: str, lower_names: List[str]):
    best = None  # (preference, depth, path)
    base_depth = root.rstrip(os.sep).count(os.sep)
    for folder, dirs, files in os.walk(root):
        depth = folder.rstrip(os.sep).count(os.sep) - base_depth
        if depth >= _SEARCH_DEPTH:
            dirs[:] = []
        dirs.sort()
        for f in sorted(files):
            if f.lower() in lower_names:
                key = (lower_names.index(f.lower()), depth, os.path.join(folder, f))
                best = key if best is None or key < best else best
    return best[2] if best else None


def _read_vectors(file: str, names: Sequence[str]) -> Dict[str, np.ndarray]:
    """Columns `names` of a CSV file (by header) or variables of a .mat file."""
    if file.lower().endswith(".mat"):
        return _mat_vectors(file, names)
    return _csv_vectors(file, names)


def _csv_vectors(file: str, names: Sequence[str]) -> Dict[str, np.ndarray]:
    """Leading non-empty cells of each named column. A column may end early
    (Ts is given in the first row only); a number after an empty cell, or a
    cell that is not a finite number, is an error naming file, line and column."""
    with open(file, newline="") as f:
        rows = [(i + 1, r) for i, r in enumerate(csv.reader(f)) if any(c.strip() for c in r)]
    if not rows:
        raise ValueError(f"{file}: empty file")
    header = [c.strip() for c in rows[0][1]]
    missing = [n for n in names if n not in header]
    if missing:
        raise ValueError(f"{file}:{rows[0][0]}: header {header} lacks column(s) {missing}")
    return {n: _csv_column(file, rows[1:], n, header.index(n)) for n in names}


def _csv_column(file: str, rows, name: str, j: int) -> np.ndarray:
    values, ended_at = [], None
    for line, r in rows:
        cell = r[j].strip() if j < len(r) else ""
        if not cell:
            ended_at = ended_at or line
            continue
        if ended_at:
            raise ValueError(f"{file}:{line}: column {name!r} has a value after the empty cell on line {ended_at}")
        try:
            v = float(cell)
        except ValueError:
            raise ValueError(f"{file}:{line}: column {name!r}: {cell!r} is not a number") from None
        if not math.isfinite(v):
            raise ValueError(f"{file}:{line}: column {name!r}: {cell!r} is not finite")
        values.append(v)
    return np.array(values, dtype=float)


def _mat_vectors(file: str, names: Sequence[str]) -> Dict[str, np.ndarray]:
    try:
        import scipy.io
    except ImportError:
        raise ImportError(f"{file} is a MATLAB .mat file: reading it needs scipy (Debian: apt install "
                          f"python3-scipy), or use the benchmark's .csv file where it has one") from None
    try:
        mat = scipy.io.loadmat(file)
    except (ValueError, NotImplementedError, OSError) as e:
        raise ValueError(f"{file}: not a readable MATLAB .mat file ({e})") from None
    out = {}
    for n in names:
        if n not in mat:
            have = sorted(k for k in mat if not k.startswith("__"))
            raise ValueError(f"{file}: no variable {n!r} (it has {have})")
        v = np.asarray(mat[n], dtype=float)
        if sum(d > 1 for d in v.shape) > 1:
            raise ValueError(f"{file}: variable {n!r} has shape {v.shape}, expected a vector")
        v = v.reshape(-1)
        if not np.all(np.isfinite(v)):
            raise ValueError(f"{file}: variable {n!r} has a value that is not finite")
        out[n] = v
    return out


def _scalar(vectors: Dict[str, np.ndarray], name: str, file: str) -> float:
    v = vectors[name]
    if v.size == 0 or not v[0] > 0:
        raise ValueError(f"{file}: {name!r} must start with a positive number")
    return float(v[0])


def _same_length(file: str, vectors: Dict[str, np.ndarray], *names: str) -> int:
    lengths = {n: vectors[n].size for n in names}
    if len(set(lengths.values())) != 1:
        raise ValueError(f"{file}: columns of one record differ in length: {lengths}")
    return lengths[names[0]]


def _need(file: str, length: int, needed: int, what: str):
    if length < needed:
        raise ValueError(f"{file}: {length} samples, the benchmark's split needs at least {needed} ({what})")


def _record(vectors, file, u: str, y: str, ts: float, name: str, units=("", ""),
            start: int = 0, stop: int = None, warmup: int = 0) -> Record:
    """Record of samples start..stop-1 of the vectors named u and y."""
    return Record(u=vectors[u][start:stop], y=vectors[y][start:stop], sampling_time=ts, name=name,
                  warmup=warmup, u_names=(u,), y_names=(y,), u_units=(units[0],), y_units=(units[1],),
                  source=file)


# ---------------------------------------------------------------- benchmarks

def cascaded_tanks(path) -> Tuple[Record, Record]:
    """Cascaded Tanks (Schoukens, Mattsson, Wigren, Noel, 2016).

    path: dataBenchmark.csv or dataBenchmark.mat, or a folder holding one
    (CascadedTanksFiles.zip unpacked). Variables uEst, yEst (train), uVal,
    yVal (test), Ts (4 s; in the CSV, first row only). u: pump voltage (V);
    y: lower tank level sensor (V).
    Returns (train, test): train = uEst/yEst, warmup 0; test = uVal/yVal,
    warmup 50. The CSV layout was checked against the real file; the .mat
    layout against the names nonlinear_benchmarks reads.
    """
    file = _locate(path, ["dataBenchmark.csv", "dataBenchmark.mat"], "Cascaded Tanks", "cascaded-tanks")
    v = _read_vectors(file, ["uEst", "uVal", "yEst", "yVal", "Ts"])
    ts = _scalar(v, "Ts", file)
    n_train = _same_length(file, v, "uEst", "yEst")
    n_test = _same_length(file, v, "uVal", "yVal")
    _need(file, n_test, 51, "test warm-up 50")
    volts = ("V", "V")
    return (_record(v, file, "uEst", "yEst", ts, "cascaded tanks train", volts, 0, n_train),
            _record(v, file, "uVal", "yVal", ts, "cascaded tanks test", volts, 0, n_test, warmup=50))


_CED_TS = 0.02   # s (50 Hz), as in the technical report and nonlinear_benchmarks
_CED_SPLIT = 400  # train = samples 0..399 of each record, test = the rest


def coupled_electric_drives(path) -> Tuple[List[Record], List[Record]]:
    """Coupled Electric Drives (Wigren, Schoukens, 2017), the records with
    uniformly distributed input amplitude, which nonlinear_benchmarks splits.

    path: DATAUNIF.csv or DATAUNIF.MAT, or a folder holding one (the
    CoupledElectricDrivesDataSetAndReferenceModels zip unpacked). Variables
    u11/z11 (low input amplitude) and u12/z12 (high input amplitude), 500
    samples each, Ts = 0.02 s. u: drive voltage (V); y: pulley speed from a
    pulse counter (unit not stated in the files).
    Returns ([train_low, train_high], [test_low, test_high]): train =
    samples 0..399, test = samples 400.. with warmup 10. Report the two test
    errors separately. Layout checked against the documented names only.
    """
    file = _locate(path, ["DATAUNIF.csv", "DATAUNIF.MAT"], "Coupled Electric Drives", "coupled-electric-drives")
    v = _read_vectors(file, ["u11", "u12", "z11", "z12"])
    trains, tests = [], []
    for u, y, level in (("u11", "z11", "low"), ("u12", "z12", "high")):
        n = _same_length(file, v, u, y)
        _need(file, n, _CED_SPLIT + 11, "400 train samples, test warm-up 10")
        name = f"coupled electric drives {level} amplitude"
        trains.append(_record(v, file, u, y, _CED_TS, name + " train", ("V", ""), 0, _CED_SPLIT))
        tests.append(_record(v, file, u, y, _CED_TS, name + " test", ("V", ""), _CED_SPLIT, n, warmup=10))
    return trains, tests


def coupled_electric_drives_prbs(path) -> List[Record]:
    """Coupled Electric Drives, the three PRBS records u1/z1, u2/z2, u3/z3 of
    DATAPRBS.csv or DATAPRBS.MAT (or a folder holding one), Ts = 0.02 s.

    nonlinear_benchmarks defines no split for these: each comes back whole,
    warmup 0, for the user to split. Layout checked against the documented
    names only.
    """
    file = _locate(path, ["DATAPRBS.csv", "DATAPRBS.MAT"], "Coupled Electric Drives (PRBS)",
                   "coupled-electric-drives")
    v = _read_vectors(file, ["u1", "u2", "u3", "z1", "z2", "z3"])
    out = []
    for k in (1, 2, 3):
        n = _same_length(file, v, f"u{k}", f"z{k}")
        out.append(_record(v, file, f"u{k}", f"z{k}", _CED_TS, f"coupled electric drives prbs {k}", ("V", ""), 0, n))
    return out


_SILVERBOX_TS = 1 / 610.35  # s, the value nonlinear_benchmarks uses (10 MHz / 2^14 = 610.35 Hz)


def silverbox(path) -> Tuple[Record, List[Record]]:
    """Silverbox (Wigren, Schoukens, ECC 2013), an electronic Duffing oscillator.

    path: SNLS80mV.csv or SNLS80mV.mat, or a folder holding one
    (SilverboxFiles.zip unpacked). Variables V1 (input, V) and V2 (output, V),
    Ts = 1/610.35 s.
    Returns (train, [test_multisine, test_arrow_full,
    test_arrow_no_extrapolation]), all tests with warmup 50:
    multisine = samples 40650..127399, train = its first 65062 samples
    (75 %), test_multisine = the remaining 21688; test_arrow_full = samples
    100..40574 (40475); test_arrow_no_extrapolation = its first 32000.
    Layout checked against the documented names only.
    """
    file = _locate(path, ["SNLS80mV.csv", "SNLS80mV.mat"], "Silverbox", "silverbox")
    v = _read_vectors(file, ["V1", "V2"])
    n = _same_length(file, v, "V1", "V2")
    _need(file, n, 127400, "multisine part ends at sample 127400")
    start, stop = 40650, 127400
    cut = start + int((stop - start) * 0.75)
    volts = ("V", "V")

    def rec(name, a, b, w=50):
        return _record(v, file, "V1", "V2", _SILVERBOX_TS, "silverbox " + name, volts, a, b, w)

    return (rec("multisine train", start, cut, 0),
            [rec("multisine test", cut, stop), rec("arrow full test", 100, 40575),
             rec("arrow no extrapolation test", 100, 100 + 32000)])


def wiener_hammerstein(path) -> Tuple[Record, Record]:
    """Wiener-Hammerstein benchmark (SYSID 2009).

    path: WienerHammerBenchmark.csv or WienerHammerBenchMark.mat, or a folder
    holding one. Variables uBenchMark (input, V), yBenchMark (output, V), fs
    (51200 Hz; in the CSV, first row); Ts = 1/fs.
    Returns (train, test): of samples 5200..183999, train = the first 100000,
    test = the remaining 78800 with warmup 50. Layout checked against the
    documented names only.
    """
    file = _locate(path, ["WienerHammerBenchmark.csv", "WienerHammerBenchMark.mat"], "Wiener-Hammerstein",
                   "wiener-hammerstein")
    v = _read_vectors(file, ["uBenchMark", "yBenchMark", "fs"])
    ts = 1.0 / _scalar(v, "fs", file)
    n = _same_length(file, v, "uBenchMark", "yBenchMark")
    _need(file, n, 184000, "the split ends at sample 184000")
    volts = ("V", "V")
    return (_record(v, file, "uBenchMark", "yBenchMark", ts, "wiener-hammerstein train", volts, 5200, 105200),
            _record(v, file, "uBenchMark", "yBenchMark", ts, "wiener-hammerstein test", volts, 105200, 184000,
                    warmup=50))


def emps(path) -> Tuple[Record, Record]:
    """Electro-Mechanical Positioning System (Janot, Gautier, Brunot, 2019).

    path: a folder holding DATA_EMPS.mat (train) and DATA_EMPS_PULSES.mat
    (test), or one of these files (the other is looked for next to it).
    Variables vir (motor force on the load side, N) as u, qm (measured
    position, m) as y, t (time, s; Ts = t[1] - t[0]). MATLAB files only:
    needs scipy (python3-scipy).
    Returns (train, test): the whole of each file; test warmup 20. Layout
    checked against the documented names only.
    """
    path = os.path.expanduser(os.fspath(path))
    folder = os.path.dirname(path) if os.path.isfile(path) else path
    out = []
    for part, file_name, warmup in (("train", "DATA_EMPS.mat", 0), ("test", "DATA_EMPS_PULSES.mat", 20)):
        file = _locate(folder, [file_name], "EMPS", "emps")
        v = _read_vectors(file, ["vir", "qm", "t"])
        n = _same_length(file, v, "vir", "qm", "t")
        _need(file, n, warmup + 2, "two time stamps and the warm-up")
        ts = float(v["t"][1] - v["t"][0])
        if not ts > 0:
            raise ValueError(f"{file}: t does not increase (t[1] - t[0] = {ts})")
        out.append(_record(v, file, "vir", "qm", ts, f"emps {part}", ("N", "m"), 0, n, warmup))
    return out[0], out[1]


# ---------------------------------------------------------------- by name

BENCHMARKS = {
    "cascaded_tanks": cascaded_tanks,
    "coupled_electric_drives": coupled_electric_drives,
    "coupled_electric_drives_prbs": coupled_electric_drives_prbs,
    "silverbox": silverbox,
    "wiener_hammerstein": wiener_hammerstein,
    "emps": emps,
}
_ALIASES = {"tanks": "cascaded_tanks", "ced": "coupled_electric_drives", "ced_prbs": "coupled_electric_drives_prbs",
            "wh": "wiener_hammerstein", "wienerhammerbenchmark": "wiener_hammerstein"}


def load(name: str, path):
    """Load benchmark `name` from `path` (a file or folder, as for its function).

    Names: the keys of BENCHMARKS (cascaded_tanks, coupled_electric_drives,
    coupled_electric_drives_prbs, silverbox, wiener_hammerstein, emps), in
    any case, with spaces or hyphens for underscores, or the short names
    tanks, ced, ced_prbs, wh and nonlinear_benchmarks' names (Cascaded_Tanks,
    CED, WienerHammerBenchMark, Silverbox, EMPS). Returns what that function
    returns. An unknown name raises ValueError with the closest names.
    """
    key = str(name).strip().lower().replace("-", "_").replace(" ", "_")
    key = _ALIASES.get(key, key)
    if key in BENCHMARKS:
        return BENCHMARKS[key](path)
    close = difflib.get_close_matches(key, list(BENCHMARKS) + list(_ALIASES), n=3, cutoff=0.5)
    hint = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
    raise ValueError(f"unknown benchmark {name!r}{hint} (known: {', '.join(BENCHMARKS)})")
