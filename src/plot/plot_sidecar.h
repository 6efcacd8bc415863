#pragma once
/// The figure description written beside every plot: `<stem>.plot.json`
/// next to `<stem>.png`, from the same PlotSpec gnuplot draws, so that another
/// front end (the Python module's lpvid.plots) can draw the same figure
/// without gnuplot. It holds every number drawn (not only the CSV's columns:
/// the shaded blocks, the point labels and the horizontal lines too) and the
/// layout: the figure's title and size, its panels top to bottom with their
/// titles, axis labels (with units), logarithmic axes, legend position and
/// explicit tick marks (xtics, ytics: at and label; only when the figure sets them);
/// per series its title, kind ("line", or "band": the area between y and
/// y_high filled), gnuplot style (lines, points, linespoints) and colour — the
/// colour gnuplot uses, its default cycle resolved when the spec names none.
/// The format is documented in docs/plots.md ("The figure description").

#include <string>

#include <nlohmann/json.hpp>

#include "plot/plot_spec.h"

namespace lpvid {

/// png_path with its extension replaced by ".plot.json".
std::string plot_sidecar_path(const std::string& png_path);

/// The description of the figure (format "lpvid-plot", version 1).
nlohmann::ordered_json plot_spec_json(const PlotSpec& spec);

/// Writes plot_spec_json(spec) to plot_sidecar_path(png_path); returns "" or
/// why it was not written (never throws: a figure description is an extra).
std::string write_plot_sidecar(const PlotSpec& spec, const std::string& png_path);

}  // namespace lpvid
