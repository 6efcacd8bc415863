"""The CLI's figures in memory, and drawn again with matplotlib.

Every plot the command line writes (``lpvid diagnose --plots DIR``,
``lpvid tradeoff --plots DIR``, ...) comes with a figure description beside
its PNG: ``<stem>.plot.json`` (docs/plots.md, "The figure description"),
written from the same specification gnuplot draws. It holds every number
drawn and the layout: title, panels, axis labels with units, which series is
a line, points or a band, their colours, shaded blocks and horizontal lines.

    plots = lpvid.plots.read_plots("diag_plots")   # {"record": Plot, "residual": Plot, ...}
    fig = plots["record"].figure()                 # a matplotlib Figure
    fig.savefig("record.png")

read_plots copies everything into memory (numpy arrays), so the folder may
be deleted afterwards. matplotlib is imported only by figure(): this module
and ``import lpvid`` work without it (Debian: python3-matplotlib).

Every figure keeps the palette of docs/plots.md (one colour per role:
measured black, the model before orange, the model after blue, ...). A
compared model named "before" or "after" takes its role's colour too, and
with the run's report beside it (compare.json, as the package writes it)
each compared model's legend entry gives its RMS and fit (%). In the
folders the package's functions work in, a title names what the caller
gave, never the package's own data files: "Estimation record rows 0:300",
"Test record 1", "lpvid compare on the given record".
"""

import json
import math
import os
import re
import warnings
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import numpy as np

from ._files import read_table

SIDECAR_SUFFIX = ".plot.json"
FORMAT = "lpvid-plot"
VERSION = 1


@dataclass
class Series:
    """One curve of a panel. kind "line": y against x, drawn with `style`
    (gnuplot's lines, points or linespoints); kind "band": the area between
    y and y_high filled (a confidence band, or a shaded block of rows).
    `labels` (or None): a text next to each point. An empty title is not in
    the legend."""

    title: str
    x: np.ndarray
    y: np.ndarray
    kind: str = "line"
    style: str = "lines"
    color: str = ""
    y_high: Optional[np.ndarray] = None
    labels: Optional[List[str]] = None


@dataclass
class HLine:
    """A horizontal line y = value across the panel; dashtype 1 solid, 2
    dashed, 3 dotted (gnuplot's)."""

    y: float
    title: str = ""
    color: str = "#000000"
    dashtype: int = 1


@dataclass
class Panel:
    """One axes of a figure (panels are stacked top to bottom and share x).
    key: where the legend goes, in gnuplot's words ("top right", "outside
    right top", "bottom left")."""

    title: str
    xlabel: str
    ylabel: str
    series: List[Series]
    hlines: List[HLine] = field(default_factory=list)
    logx: bool = False
    logy: bool = False
    key: str = "top right"
    xtics: List[Tuple[float, str]] = field(default_factory=list)
    ytics: List[Tuple[float, str]] = field(default_factory=list)


@dataclass
class Plot:
    """One figure of a run: its panels (one for a simple plot), its title,
    size in pixels, and the table of its CSV (column -> array; text columns
    as arrays of str), when the CSV was beside it."""

    name: str
    title: str
    panels: List[Panel]
    width: int = 900
    height: int = 650
    table: Dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def series(self):
        """Every series of every panel, top to bottom."""
        return [s for p in self.panels for s in p.series]

    def figure(self):
        """The figure as a matplotlib.figure.Figure (see figure())."""
        return figure(self)


# --- reading ------------------------------------------------------------------------------------


def _array(values, where):
    try:
        return np.array([np.nan if v is None else v for v in values], dtype=float)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{where}: not a list of numbers ({e})") from None


def _series(js, xs, where):
    i = js.get("x")
    if not isinstance(i, int) or not 0 <= i < len(xs):
        raise ValueError(f"{where}: 'x' must index x_values (0..{len(xs) - 1}), got {i!r}")
    y = _array(js["y"], where + ".y")
    if len(y) != len(xs[i]):
        raise ValueError(f"{where}: {len(y)} y values for {len(xs[i])} x values")
    y_high = _array(js["y_high"], where + ".y_high") if "y_high" in js else None
    return Series(title=js.get("title", ""), x=xs[i].copy(), y=y, kind=js.get("kind", "line"),
                  style=js.get("style", "lines"), color=js.get("color", ""), y_high=y_high,
                  labels=list(js["labels"]) if "labels" in js else None)


def _panel(js, xs, where):
    series = [_series(s, xs, f"{where}.series[{k}]") for k, s in enumerate(js.get("series", []))]
    hlines = [HLine(y=float(h["y"]), title=h.get("title", ""), color=h.get("color", "#000000"),
                    dashtype=int(h.get("dashtype", 1))) for h in js.get("hlines", [])]
    return Panel(title=js.get("title", ""), xlabel=js.get("xlabel", ""), ylabel=js.get("ylabel", ""),
                 series=series, hlines=hlines, logx=bool(js.get("logx", False)), logy=bool(js.get("logy", False)),
                 key=js.get("key", "top right"),
                 xtics=[(float(t["at"]), str(t["label"])) for t in js.get("xtics", [])],
                 ytics=[(float(t["at"]), str(t["label"])) for t in js.get("ytics", [])])


def _csv_table(path):
    """The CSV's columns (lpvid._files.read_table)."""
    return read_table(path)


def read_plot(path):
    """One figure from its description `<stem>.plot.json` (or the PNG or
    CSV of the same stem). The CSV's table is read too when it is there."""
    stem = str(path)
    for suffix in (SIDECAR_SUFFIX, ".png", ".svg", ".csv"):
        if stem.endswith(suffix):
            stem = stem[: -len(suffix)]
            break
    sidecar = stem + SIDECAR_SUFFIX
    try:
        with open(sidecar, encoding="utf-8") as f:
            js = json.load(f)
    except FileNotFoundError:
        raise FileNotFoundError(f"{sidecar}: no figure description (written by lpvid since the figure "
                                f"descriptions were added; run the command again)") from None
    except json.JSONDecodeError as e:
        raise ValueError(f"{sidecar}: not JSON ({e})") from None
    if not isinstance(js, dict) or js.get("format") != FORMAT or js.get("version") != VERSION:
        raise ValueError(f"{sidecar}: not an {FORMAT} version {VERSION} figure description")
    try:
        xs = [_array(x, f"{sidecar}: x_values[{k}]") for k, x in enumerate(js["x_values"])]
        panels = [_panel(p, xs, f"{sidecar}: panels[{k}]") for k, p in enumerate(js["panels"])]
    except KeyError as e:
        raise ValueError(f"{sidecar}: missing field {e}") from None
    csv_path = stem + ".csv"
    table = _csv_table(csv_path) if os.path.isfile(csv_path) else {}
    plot = Plot(name=os.path.basename(stem), title=js.get("title", ""), panels=panels,
                width=int(js.get("width", 900)), height=int(js.get("height", 650)), table=table)
    _role_colours(plot)
    folder = os.path.dirname(os.path.abspath(stem))
    if plot.name == "compare":
        _compare_scores(plot, os.path.join(folder, "compare.json"))
    _caller_titles(plot, folder)
    return plot


def read_plots(folder):
    """Every figure a run wrote into `folder`, by file stem ("record",
    "residual", "test", ...), read into memory. A PNG without a figure
    description (written by an older lpvid) is skipped with a warning."""
    names = sorted(os.listdir(folder))
    plots = {}
    for name in names:
        if name.endswith(SIDECAR_SUFFIX):
            p = read_plot(os.path.join(folder, name))
            plots[p.name] = p
    for name in names:
        if name.endswith(".png") and name[: -len(".png")] not in plots:
            warnings.warn(f"{os.path.join(folder, name)} has no figure description ({name[:-4]}{SIDECAR_SUFFIX}); "
                          "not read", stacklevel=2)
    return plots


# --- the palette, the scores, the titles ---------------------------------------------------------

# One colour per role (docs/plots.md, "one colour per role"): the model before orange, the model
# after blue, as every figure of the command line draws them.
MODEL_BEFORE = "#ee7733"
MODEL_AFTER = "#0077bb"
ROLE_COLOURS = {"before": MODEL_BEFORE, "after": MODEL_AFTER}
# The colours of further compared models, in the command line's order.
OTHER_MODELS = ("#0077bb", "#ee7733", "#009988", "#cc3311", "#33bbee", "#aa3377")


def _role_colours(plot):
    """A line series titled "before" or "after" (a compared model of that
    name) in its role's colour; another model that had that colour takes the
    first colour of OTHER_MODELS no series of its panel has."""
    for panel in plot.panels:
        roles = [s for s in panel.series if s.kind == "line" and s.title.strip().lower() in ROLE_COLOURS]
        if not roles:
            continue
        for s in roles:
            s.color = ROLE_COLOURS[s.title.strip().lower()]
        taken = {s.color.lower() for s in roles}
        for s in panel.series:
            if s in roles or s.kind != "line" or s.color.lower() not in taken:
                continue
            used = {t.color.lower() for t in panel.series}
            s.color = next((c for c in OTHER_MODELS if c not in used), s.color)


def _score_text(name, rms, fit):
    def number(x, spec):
        return "n/a" if x is None else format(float(x), spec) if math.isfinite(float(x)) else str(float(x))
    return f"{name}: RMS {number(rms, '#.3g')}, fit {number(fit, '.1f')} %"


def _compare_scores(plot, report_path):
    """Each compared model's legend entry with its RMS and fit (%) on that
    panel's output, from the run's report beside the figure (the numbers of
    Comparison.scores). Without the report the entries stay the names."""
    try:
        with open(report_path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError):
        return
    entries = report.get("models") if isinstance(report.get("models"), list) else [report]
    for i, panel in enumerate(plot.panels):
        models = [s for s in panel.series if s.kind == "line" and not s.title.startswith("measured")]
        if len(entries) == 1 and len(models) == 1 and "name" not in entries[0]:
            pairs = [(models[0], entries[0])]  # one model: its report has no name
        else:
            by_name = {e.get("name"): e for e in entries if isinstance(e, dict)}
            pairs = [(s, by_name[s.title]) for s in models if s.title in by_name]
        for s, entry in pairs:
            outputs = entry.get("outputs") or []
            score = outputs[i] if i < len(outputs) and len(plot.panels) > 1 else entry
            s.title = _score_text(s.title, score.get("rms"), score.get("fit_percent"))


# The data files the package's functions write for arrays and DataFrames (lpvid._inputs,
# lpvid._commands), and the report each function writes beside its figures.
_PACKAGE_DATA = re.compile(r"(?<![\w.-])(data|test)(\d*)\.csv(?![\w.-])")
_PACKAGE_REPORTS = {"compare": "compare.json", "tradeoff": "tradeoff.json"}


def _package_folder(plot, folder):
    """The folder a package function ran in when `folder` holds its figures
    (compare, tradeoff: the folder itself; diagnose: its "plots" folder),
    known by the function's report there; None for any other folder."""
    report = _PACKAGE_REPORTS.get(plot.name)
    if report and os.path.isfile(os.path.join(folder, report)):
        return folder
    parent = os.path.dirname(folder)
    if os.path.basename(folder) == "plots" and os.path.isfile(os.path.join(parent, "diagnose.json")):
        return parent
    return None


def _numbered(folder, stem, suffix=".csv"):
    """The k of the files <stem>k<suffix> in `folder`, sorted."""
    found = (re.fullmatch(re.escape(stem) + r"(\d+)" + re.escape(suffix), n) for n in os.listdir(folder))
    return sorted(int(m.group(1)) for m in found if m)


def _caller_titles(plot, folder):
    """In a package function's folder: the titles name what the caller gave
    instead of the data files the package wrote for it ("Estimation record
    data.csv rows 0:300" -> "Estimation record rows 0:300", "Test record
    test1.csv" -> "Test record 1", "on data.csv" -> "on the given record").
    A file the caller named by its path keeps its name: the package did not
    write it there."""
    ws = _package_folder(plot, folder)
    if ws is None:
        return
    records, tests = _numbered(ws, "data"), _numbered(folder, "test", SIDECAR_SUFFIX)  # test1, test2, ... figures

    def record(k):
        # the command line names the first of several records for all of them
        return f"records 1 to {records[-1]}" if k == "1" and len(records) > 1 else f"record {k}"

    def caption(m):
        if not os.path.isfile(os.path.join(ws, m.group(0))):
            return m.group(0)  # not the package's: the caller's own file
        which, k = m.group(1), m.group(2)
        if which == "test":
            return f"test record {k}" if k else m.group(0)
        return record(k) if k else "the given record"

    def retitle(text):
        m = re.match(r"(Estimation|Test) record ((data|test)(\d*)\.csv)(?![\w.-])", text)
        if m and os.path.isfile(os.path.join(ws, m.group(2))):
            kind, k = m.group(1), m.group(4)
            if kind == "Test":
                head = "Test record" + (f" {k}" if k and len(tests) > 1 else "")
            else:
                head = "Estimation " + record(k) if k else "Estimation record"
            text = head + text[m.end():]
        if "test records: test*.png" in text:  # the test figures, by their names in result.plot()
            text = text.replace("test records: test*.png", "the test record: figure \"test\"" if len(tests) <= 1
                                else f"the test records: figures \"test1\" to \"test{tests[-1]}\"")
        return _PACKAGE_DATA.sub(caption, text)

    plot.title = retitle(plot.title)
    for panel in plot.panels:
        panel.title = retitle(panel.title)
        for s in panel.series:
            s.title = retitle(s.title)


# --- drawing ------------------------------------------------------------------------------------

_DASHES = {1: "-", 2: "--", 3: ":", 4: "-.", 5: (0, (5, 2, 1, 2, 1, 2))}


def _figure_class():
    try:
        from matplotlib.figure import Figure
    except ImportError as e:
        raise ImportError("lpvid's figures need matplotlib, which is not installed "
                          "(Debian: apt install python3-matplotlib; or pip install matplotlib)") from e
    return Figure


def _legend(ax, key):
    """gnuplot's `set key` position as a matplotlib legend."""
    handles, _ = ax.get_legend_handles_labels()
    if not handles:
        return
    words = key.split()
    if "outside" in words:
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, fontsize="small")
        return
    vertical = "lower" if "bottom" in words else "center" if "center" in words and "top" not in words else "upper"
    horizontal = "left" if "left" in words else "right"
    ax.legend(loc=f"{vertical} {horizontal}", fontsize="small", framealpha=1.0)


def _draw_series(ax, s):
    label = s.title if s.title else "_nolegend_"
    if s.kind == "band":
        ax.fill_between(s.x, s.y, s.y_high, color=s.color or None, alpha=0.4, linewidth=0, label=label)
        return
    marker = "o" if s.style in ("points", "linespoints") else None
    linestyle = "none" if s.style == "points" else "-"
    ax.plot(s.x, s.y, linestyle=linestyle, marker=marker, markersize=5, linewidth=1.5, color=s.color or None,
            label=label)
    for x, y, text in zip(s.x, s.y, s.labels or []):
        if text:
            ax.annotate(text, (x, y), xytext=(8, 6), textcoords="offset points", fontsize=8)


def _draw_panel(ax, panel, title, fix_x):
    for s in panel.series:
        _draw_series(ax, s)
    for h in panel.hlines:
        ax.axhline(h.y, color=h.color, linestyle=_DASHES.get(h.dashtype, "--"), linewidth=1.2,
                   label=h.title if h.title else "_nolegend_")
    if panel.logx:
        ax.set_xscale("log")
    if panel.logy:
        ax.set_yscale("log")
    if panel.xtics or panel.ytics:  # the figure's own tick marks (distinct labels)
        ax.minorticks_off()
    if panel.xtics:
        ax.set_xticks([t[0] for t in panel.xtics])
        ax.set_xticklabels([t[1] for t in panel.xtics])
    if panel.ytics:
        ax.set_yticks([t[0] for t in panel.ytics])
        ax.set_yticklabels([t[1] for t in panel.ytics])
    if fix_x:  # panels over one time axis: no padding in x (gnuplot's autoscale xfix)
        ax.margins(x=0)
    ax.set_title(title, fontsize="medium")
    ax.set_xlabel(panel.xlabel)
    ax.set_ylabel(panel.ylabel)
    ax.grid(True, alpha=0.4)
    _legend(ax, panel.key)


def figure(plot):
    """A matplotlib.figure.Figure with the content of the CLI's PNG of
    `plot`: the same panels, series, bands, horizontal lines, labels, title
    and colours. Made without pyplot (no global state: headless and in
    notebooks; display it there as the cell's value, or fig.savefig(path)).
    Raises ImportError naming python3-matplotlib when matplotlib is missing."""
    Figure = _figure_class()
    fig = Figure(figsize=(plot.width / 100.0, plot.height / 100.0), dpi=100, layout="constrained")
    many = len(plot.panels) > 1
    axes = fig.subplots(len(plot.panels), 1, sharex=many, squeeze=False)[:, 0]
    for ax, panel in zip(axes, plot.panels):
        _draw_panel(ax, panel, panel.title if many else plot.title, fix_x=many)
    if many:
        fig.suptitle(plot.title, fontsize="medium")
    return fig
