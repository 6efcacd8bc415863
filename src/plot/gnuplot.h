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

#include "plot/plot_spec.h"

namespace lpvid {

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

/// Whether plot_png runs gnuplot (the default) or writes only the figure
/// description: the Python module turns drawing off for a call whose files
/// are not kept, since it draws its figures from the descriptions, and only
/// when asked. Process-wide; the module runs one call at a time.
void set_png_drawing(bool on);
bool png_drawing();

/// Writes the plot as a PNG file and, from the same script, as an SVG file
/// beside it (png_path with extension .svg; vector graphics for papers).
/// First, whether or not gnuplot can be run, the figure's description
/// (every number and label drawn) as png_path with extension .plot.json
/// (plot/plot_sidecar.h), from which other front ends draw the same figure.
/// Never throws for a missing or failing gnuplot (ok = false and the
/// message; gnuplot's own error text included). With png_drawing() off,
/// only the description is written (ok = false, the message says so).
PlotOutcome plot_png(const PlotSpec& spec, const std::string& png_path);

/// The gnuplot script plot_png runs (exposed for tests): `data_path` holds
/// one block per series (x y label), separated by two blank lines.
std::string gnuplot_script(const PlotSpec& spec, const std::string& terminal, const std::string& png_path,
                           const std::string& data_path);

}  // namespace lpvid
