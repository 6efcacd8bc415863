#pragma once
/// What a figure shows, independent of who draws it: series, bands,
/// horizontal lines, ticks and stacked panels. gnuplot draws it
/// (plot/gnuplot.h) and its description is written beside the picture
/// (plot/plot_sidecar.h) for other front ends.

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

}  // namespace lpvid
