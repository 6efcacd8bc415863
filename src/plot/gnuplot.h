#pragma once
/// A small wrapper around the external `gnuplot` program (Debian package
/// gnuplot-nox) for the PNG plots of the reports (trade-off curve, …).
///
/// gnuplot is run as a separate process on a temporary script and data
/// file; nothing is linked. The program is `gnuplot` on PATH, or the value
/// of the environment variable LPVID_GNUPLOT. The PNG terminal is
/// `pngcairo` when gnuplot has it (anti-aliased), else `png` (libgd).
/// A missing gnuplot is not an error of the caller's computation: plot_png
/// returns ok = false with a message saying so, and the caller goes on
/// (the numbers are always written as CSV as well).
///

#include <string>
#include <vector>

namespace lpvid {

struct PlotSeries {
  std::string title;
  std::vector<double> x, y;
  std::vector<std::string> labels;        ///< optional text next to each point (same length as x)
  std::string style = "linespoints";      ///< gnuplot `with` style: lines, points, linespoints
  /// A band: when not empty (length of x), the area between y and y_high is
  /// filled (gnuplot `filledcurves`, translucent) instead of a line.
  std::vector<double> y_high;
  std::string color;                      ///< gnuplot rgb colour ("#4477aa"); "" for gnuplot's own cycle
};

/// A horizontal line y = value across the whole plot (e.g. a confidence band).
struct PlotHLine {
  double y = 0;
  std::string title;              ///< legend text; "" for none
  std::string color = "#cc0000";  ///< gnuplot rgb colour
  int dashtype = 2;               ///< gnuplot `dt`: 1 solid, 2 dashed, 3 dotted
};

/// A tick mark placed by the figure (not by gnuplot) with its label.
struct PlotTick {
  double at = 0;
  std::string label;
};

struct PlotSpec {
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
  int width = 900, height = 650;          ///< pixels
  bool logx = false, logy = false;
  std::string key = "top right";          ///< gnuplot `set key` position
  std::vector<PlotHLine> hlines;          ///< drawn after the series (need at least one series)
  /// Tick marks of the x and y axes (distinct labels); empty: gnuplot's own.
  std::vector<PlotTick> xtics, ytics;
  /// A figure of stacked panels (top to bottom, sharing the width): when not
  /// empty, each panel is drawn with its own title, labels, series and lines,
  /// `title` heads the figure and this spec's own series are not drawn.
  std::vector<PlotSpec> panels;
};

struct PlotOutcome {
  bool ok = false;    ///< the PNG was written
  std::string svg;    ///< the SVG written beside it (same stem), "" if none
  std::string sidecar;  ///< the figure description beside it (plot_sidecar.h), "" if none
  std::string message;   ///< why not, or what was written
  std::string terminal;  ///< "pngcairo" or "png"
};

/// The gnuplot program that will be run (LPVID_GNUPLOT or "gnuplot").
std::string gnuplot_program();

/// The PNG terminal the installed gnuplot offers ("pngcairo", "png"), or ""
/// when gnuplot cannot be run or has neither.
std::string gnuplot_png_terminal();

/// Writes the plot as a PNG file and, from the same script, as an SVG file
/// beside it (png_path with extension .svg; vector graphics for papers).
/// First, whether or not gnuplot can be run, the figure's description
/// (every number and label drawn) as png_path with extension .plot.json
/// (plot/plot_sidecar.h), from which other front ends draw the same figure.
/// Never throws for a missing or failing gnuplot (ok = false and the
/// message; gnuplot's own error text included).
PlotOutcome plot_png(const PlotSpec& spec, const std::string& png_path);

/// The gnuplot script plot_png runs (exposed for tests): `data_path` holds
/// one block per series (x y label), separated by two blank lines.
std::string gnuplot_script(const PlotSpec& spec, const std::string& terminal, const std::string& png_path,
                           const std::string& data_path);

}  // namespace lpvid
