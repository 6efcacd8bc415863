"""lpvid.plots: the CLI's figures read into memory and drawn with matplotlib.

    PYTHONPATH=build/python python3 tests/python/plots_test.py <lpvid program> <scratch dir>

Runs the real `lpvid diagnose --plots DIR` (fold mode: the record's shaded
blocks; a test record: the band) and `lpvid tradeoff` on a small generated
case, reads every figure with read_plots, and checks it against the CSV
written beside each PNG, parsed here independently: every series' numbers
equal the CSV column named by its title, every PNG has a Plot, the folder
can be deleted afterwards, and figure() draws one matplotlib line per line
series, one filled area per band, one per horizontal line, and the title.
Then, through the package's functions (lpvid.compare, diagnose, tradeoff on
arrays): the palette's roles (docs/plots.md: the model before orange, the
model after blue) in every figure, also a compared model named "before" or
"after" and in the drawn matplotlib lines; each compared model's legend entry
with its RMS and fit (%) equal to Comparison.scores; and titles that name
what the caller gave (the estimation record, test record 1, the caller's
file), never the data files the package wrote for the arrays.
Without matplotlib the drawing checks are skipped (exit 0, with a message).
Exits non-zero on the first failed check.
"""

import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

import lpvid.plots as lp

LPVID, SCRATCH = sys.argv[1], sys.argv[2]
ENV = dict(os.environ, OPENBLAS_NUM_THREADS="1")
checks = 0


def check(condition, what):
    global checks
    checks += 1
    if not condition:
        sys.exit(f"FAILED: {what}")


def run(*args):
    r = subprocess.run([LPVID, *args], cwd=SCRATCH, env=ENV, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAILED: lpvid {' '.join(args)} -> exit {r.returncode}\n{r.stdout}\n{r.stderr}")


def csv_columns(path):
    """The CSV as {column: list of text}, read with the csv module only."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {name: [r[j] for r in rows[1:]] for j, name in enumerate(rows[0])}


def column_name(title):
    """The CSV column of a series: its title without a closing " (...)"
    remark, every run of other characters than letters and digits one '_'
    (the CLI's naming, restated)."""
    return re.sub(r"[^0-9A-Za-z]+", "_", re.sub(r" \([^()]*\)$", "", title)).strip("_") or "value"


def floats(texts):
    return np.array([float(t) for t in texts])


BEFORE, AFTER = "#ee7733", "#0077bb"  # docs/plots.md: the model before orange, the model after blue


def roles(p, where):
    """Every line series of a model before (after) in its role's colour, and each role present."""
    seen = set()
    for s in p.series:
        for role, colour in (("before", BEFORE), ("after", AFTER)):
            if s.kind == "line" and re.search(rf"\b{role}\b", s.title):
                seen.add(role)
                check(s.color == colour, f"{where}: {s.title!r} in {s.color}, want {colour}")
    check(seen == {"before", "after"} or where.endswith("record"), f"{where}: the lines of both models {seen}")


# --- the runs --------------------------------------------------------------------------------------
shutil.rmtree(SCRATCH, ignore_errors=True)
os.makedirs(os.path.join(SCRATCH, "curve"))
run("generate", "effect-case", "--effect", "output_offset", "--n", "200", "--out", "est.csv",
    "--validation-out", "val.csv", "--model-out", "m.json")
run("diagnose", "--data", "est.csv", "--model", "m.json", "--folds", "2", "--test", "val.csv", "--window", "0:80",
    "--max-taps", "16", "--max-windows", "1", "--max-effects", "1", "--plots", "plots", "--report", "r.json",
    "--model-out", "after.json")
run("tradeoff", "--data", "est.csv", "--model", "m.json", "--lambdas", "0.1,0.5,0.9", "--max-taps", "16",
    "--plots", "curve", "--certificate", "curve/t.cert.json", "--quiet")

plots_dir, curve_dir = os.path.join(SCRATCH, "plots"), os.path.join(SCRATCH, "curve")
plots = lp.read_plots(plots_dir)
curve = lp.read_plots(curve_dir)
pngs = sorted(f[:-4] for f in os.listdir(plots_dir) if f.endswith(".png"))
check(sorted(plots) == pngs, f"a Plot per PNG: {sorted(plots)} vs {pngs}")
check({"record", "residual", "autocorrelation", "output", "test"} <= set(plots), f"the diagnose plots: {sorted(plots)}")
check(list(curve) == ["tradeoff"], f"the trade-off plot: {list(curve)}")
tables = {name: csv_columns(os.path.join(plots_dir, name + ".csv")) for name in plots}
curve_csv = csv_columns(os.path.join(curve_dir, "tradeoff.csv"))

# --- the numbers equal the CSV's ---------------------------------------------------------------------
for name, p in plots.items():
    table = tables[name]
    x = floats(next(iter(table.values())))  # the first column: time, sample, lag, ...
    for s in p.series:
        where = f"{name}: series {s.title!r}"
        if s.kind == "band" and len(s.x) != len(x):  # shaded rows (selection blocks, warm-up: not in the CSV)
            check(len(s.x) > 0 and all(np.isin(s.x, x)), f"{where}: its x are rows of the CSV")
            continue
        check(np.array_equal(s.x, x), f"{where}: x equals the CSV's first column")
        if s.kind == "band":
            for edge, values in (("lower", s.y), ("upper", s.y_high)):
                col = name + "_" + column_name(s.title) + "_" + edge  # "<file stem>_<curve>"
                check(col in table and np.array_equal(values, floats(table[col])), f"{where}: {edge} edge = CSV {col}")
        else:
            col = name + "_" + column_name(s.title)
            check(col in table and np.array_equal(s.y, floats(table[col])), f"{where}: y = CSV column {col}")
    # the Plot's own copy of the table is the CSV's
    check(sorted(p.table) == sorted(table), f"{name}: table columns")
    for col, texts in table.items():
        check(np.array_equal(p.table[col], floats(texts)), f"{name}: table column {col}")

acf = plots["autocorrelation"].panels[0]
check([h.dashtype for h in acf.hlines] == [2, 2, 3, 3, 1], "autocorrelation: the two bands and the zero line")
for h, col in zip(acf.hlines, ["autocorrelation_band_" + b for b in ("99_upper", "99_lower", "95_upper", "95_lower")]):
    check(np.all(floats(tables["autocorrelation"][col]) == h.y), f"autocorrelation: line {h.y} = CSV {col}")

record = plots["record"]
check([pn.title for pn in record.panels] == ["input", "output"], "record: the input and output panels")
blocks = [s for s in record.panels[0].series if s.kind == "band"]
check([b.title for b in blocks] == ["fold 1", "fold 2"], f"record: the 2 folds shaded: {[b.title for b in blocks]}")
check(all(np.all(b.y <= b.y_high) for b in blocks), "record: a block spans from below to above")

test = plots["test"]
band = [s for s in test.panels[1].series if s.kind == "band" and len(s.x) == len(test.panels[1].series[-1].x)]
warmup = [s for s in test.panels[1].series if s.kind == "band" and len(s.x) < len(test.panels[1].series[-1].x)]
check(len(warmup) == 1 and warmup[0].x[0] == test.panels[1].series[-1].x[0], "test: the warm-up rows shaded")
check(len(band) == 1 and np.allclose(band[0].y_high - band[0].y, band[0].y_high[0] - band[0].y[0]),
      "test: one band of constant width (model after +- d_max)")
check(test.panels[1].series[2].color == "#000000", "test: the measured output in black")

t = curve["tradeoff"]
ser = t.series[0]
verified = [i for i, v in enumerate(curve_csv["verified"]) if v == "true"]
check(np.array_equal(ser.x, floats([curve_csv["dmax"][i] for i in verified])), "tradeoff: x = the CSV's dmax")
check(np.array_equal(ser.y, floats([curve_csv["delta"][i] for i in verified])), "tradeoff: y = the CSV's delta")
check(ser.labels == ["λ=" + curve_csv["lambda"][i] for i in verified], f"tradeoff: labels {ser.labels}")

# --- nothing refers to the files -------------------------------------------------------------------
shutil.rmtree(plots_dir)
shutil.rmtree(curve_dir)
plots.update(curve)

# --- without matplotlib: importing works, figure() names the package --------------------------------
probe = ("import sys; sys.modules['matplotlib'] = None; sys.modules['matplotlib.figure'] = None\n"
         "import lpvid, lpvid.plots as lp\n"
         "p = lp.Plot(name='p', title='t', panels=[])\n"
         "try:\n    p.figure()\nexcept ImportError as e:\n    print(e)\n")
r = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=ENV)
check(r.returncode == 0 and "python3-matplotlib" in r.stdout, f"no matplotlib: {r.stdout}{r.stderr}")

# --- the figures ------------------------------------------------------------------------------------
try:
    from matplotlib.colors import to_hex
    from matplotlib.figure import Figure
    have_matplotlib = True
except ImportError:
    print("plots_test: matplotlib is not installed (Debian: python3-matplotlib): the figures are not drawn")
    have_matplotlib = False


def drawn_roles(fig, where):
    """Every drawn line whose legend names a model before (after) in its role's colour."""
    for ax in fig.axes:
        for ln in ax.lines:
            label = ln.get_label()
            for role, colour in (("before", BEFORE), ("after", AFTER)):
                if re.search(rf"\b{role}\b", label):
                    check(to_hex(ln.get_color()) == colour,
                          f"{where}: line {label!r} drawn in {to_hex(ln.get_color())}, want {colour}")


# the diagnose figures: every line of a model before orange, after blue
for name in ("residual", "autocorrelation", "output", "test"):
    roles(plots[name], name)

out = os.path.join(SCRATCH, "figures")
os.makedirs(out)
for name, p in (plots.items() if have_matplotlib else []):
    fig = p.figure()
    check(isinstance(fig, Figure), f"{name}: a matplotlib Figure")
    check(len(fig.axes) == len(p.panels), f"{name}: {len(fig.axes)} axes for {len(p.panels)} panels")
    for ax, panel in zip(fig.axes, p.panels):
        lines = sum(s.kind == "line" for s in panel.series) + len(panel.hlines)
        bands = sum(s.kind == "band" for s in panel.series)
        check(len(ax.lines) == lines, f"{name}: {len(ax.lines)} lines drawn for {lines} line series and lines")
        check(len(ax.collections) == bands, f"{name}: {len(ax.collections)} areas for {bands} bands")
        check(ax.get_xlabel() == panel.xlabel and ax.get_ylabel() == panel.ylabel, f"{name}: axis labels")
    shown = fig._suptitle.get_text() if len(p.panels) > 1 else fig.axes[0].get_title()
    check(shown == p.title, f"{name}: title {shown!r}")
    fig.savefig(os.path.join(out, name + ".png"))
    if name in ("residual", "autocorrelation", "output", "test"):
        drawn_roles(fig, name)

# --- the package's figures: the palette's roles, the scores, the caller's names ----------------------
import lpvid  # noqa: E402

est = {k: floats(v) for k, v in csv_columns(os.path.join(SCRATCH, "est.csv")).items()}
val = {k: floats(v) for k, v in csv_columns(os.path.join(SCRATCH, "val.csv")).items()}
m_path, after_path = os.path.join(SCRATCH, "m.json"), os.path.join(SCRATCH, "after.json")
before_model, after_model = lpvid.Model.from_file(m_path), lpvid.Model.from_file(after_path)
temp_names = ("data.csv", "data1.csv", "test1.csv", "test2.csv", "lpvid-", tempfile.gettempdir())


def no_temp_names(p, where):
    texts = [p.title] + [pn.title for pn in p.panels] + [s.title for s in p.series]
    for text in texts:
        check(not any(t in text for t in temp_names), f"{where}: a temporary name in the title {text!r}")


# compare: models named before and after (given in that order: the command line colours them by
# position, blue then orange), each legend entry with the model's scores
c = lpvid.compare(models={"before": before_model, "after": after_model}, data=val, quiet=True)
p = c.plots["compare"]
lines = {s.title.split(":")[0]: s for s in p.series if s.kind == "line"}
check(lines["before"].color == BEFORE and lines["after"].color == AFTER,
      f"compare: before {lines['before'].color}, after {lines['after'].color} (want {BEFORE}, {AFTER})")
for s in c.scores:
    want = f"{s.name}: RMS {s.rms:#.3g}, fit {s.fit_percent:.1f} %"
    check(lines[s.name].title == want, f"compare: legend {lines[s.name].title!r}, want {want!r}")
check(c.score("after").rms < c.score("before").rms, "compare: the after model scores better")
check(p.title.startswith("lpvid compare on the given record"), f"compare: title {p.title!r}")
no_temp_names(p, "compare")
if have_matplotlib:
    fig = c.plot("compare")
    drawn = {ln.get_label().split(":")[0]: to_hex(ln.get_color()) for ln in fig.axes[0].lines}
    check(drawn.get("before") == BEFORE and drawn.get("after") == AFTER, f"compare: drawn colours {drawn}")
    labels = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    check(all(f"{s.name}: RMS {s.rms:#.3g}, fit {s.fit_percent:.1f} %" in labels for s in c.scores),
          f"compare: the legend {labels}")
    fig.savefig(os.path.join(out, "compare.png"))

# a third model that had the after model's colour takes another one; a file the caller named keeps its name
c3 = lpvid.compare(models={"first": before_model, "before": before_model, "after": after_model},
                   data=os.path.join(SCRATCH, "val.csv"), quiet=True)
colours = {s.title.split(":")[0]: s.color for s in c3.plots["compare"].series if s.kind == "line"}
check(colours["before"] == BEFORE and colours["after"] == AFTER and len(set(colours.values())) == len(colours),
      f"compare, three models: one colour each, before and after by role: {colours}")
check("val.csv" in c3.plots["compare"].title, f"compare on the caller's file: {c3.plots['compare'].title!r}")

# diagnose on arrays with two test records: the roles' colours, titles without the package's files
d = lpvid.diagnose(model=m_path, u=est["u1"], y=est["y1"], rho=est["rho1"],
                   test=[(val["u1"], val["y1"], val["rho1"]), (val["u1"][:150], val["y1"][:150], val["rho1"][:150])],
                   folds=2, window="0:80", max_taps=16, max_windows=1, max_effects=1, quiet=True)
check({"record", "residual", "autocorrelation", "output", "test1", "test2"} <= set(d.plots),
      f"diagnose: {sorted(d.plots)}")
for name, p in d.plots.items():
    roles(p, "diagnose " + name)
    no_temp_names(p, "diagnose " + name)
record_title = d.plots["record"].title
check(record_title.startswith("Estimation record rows 0:"), f"diagnose record: title {record_title!r}")
check('figures "test1" to "test2"' in record_title, f"diagnose record: the test figures by name: {record_title!r}")
for k in (1, 2):
    check(d.plots[f"test{k}"].title.startswith(f"Test record {k}: "), f"test{k}: title {d.plots[f'test{k}'].title!r}")
if have_matplotlib:
    for name, fig in d.plot().items():
        if name in ("residual", "autocorrelation", "output", "test1", "test2"):
            drawn_roles(fig, "diagnose " + name)

t = lpvid.tradeoff(model=m_path, u=est["u1"], y=est["y1"], rho=est["rho1"], lambdas=[0.5], max_taps=16, quiet=True)
check(t.plots["tradeoff"].title == "delta-dmax trade-off: the given record", f"tradeoff: {t.plots['tradeoff'].title!r}")
print(f"plots_test: {checks} checks passed; figures in {out}")
