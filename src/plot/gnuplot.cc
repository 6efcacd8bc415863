#include "plot/gnuplot.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "plot/plot_sidecar.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

/// 'text' for /bin/sh.
std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// 'text' for gnuplot (a quote inside is doubled).
std::string gp_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

/// Output (stdout and stderr) of a shell command, and its exit status.
std::string run_capture(const std::string& command, int* status) {
  std::string out;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) {
    *status = -1;
    return out;
  }
  std::array<char, 4096> buf;
  size_t got;
  while ((got = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), got);
  *status = pclose(p);
  return out;
}

/// A fresh private directory under the system's temporary directory.
fs::path make_temp_dir() {
  std::string tmpl = (fs::temp_directory_path() / "lpvid-plot-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) return {};
  return fs::path(tmpl);
}

std::string number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

}  // namespace

namespace {

std::atomic<bool>& drawing() {
  static std::atomic<bool> on{true};
  return on;
}

}  // namespace

void set_png_drawing(bool on) { drawing() = on; }

bool png_drawing() { return drawing(); }

std::string gnuplot_program() {
  const char* env = std::getenv("LPVID_GNUPLOT");
  return env && *env ? std::string(env) : std::string("gnuplot");
}

std::string gnuplot_png_terminal() {
  int status = 0;
  const std::string out = run_capture(sh_quote(gnuplot_program()) + " -e 'set terminal'", &status);
  if (status != 0) return "";
  bool png = false;
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "pngcairo") return "pngcairo";
    if (first == "png") png = true;
  }
  return png ? "png" : "";
}

namespace {

/// The series of a figure in drawing order (panels top to bottom): one data
/// block each, numbered in this order.
std::vector<const PlotSeries*> drawn_series(const PlotSpec& spec) {
  std::vector<const PlotSeries*> out;
  const auto add = [&](const PlotSpec& p) {
    for (const PlotSeries& ser : p.series)
      if (!ser.x.empty()) out.push_back(&ser);
  };
  if (spec.panels.empty()) add(spec);
  for (const PlotSpec& p : spec.panels) add(p);
  return out;
}

/// `set xtics ("label" at, …)` for explicit tick marks (none: gnuplot's own).
void tics_script(std::ostringstream& s, const char* axis, const std::vector<PlotTick>& tics) {
  if (tics.empty()) return;
  s << "set " << axis << "tics (";
  for (size_t i = 0; i < tics.size(); ++i) s << (i ? ", " : "") << gp_quote(tics[i].label) << " " << number(tics[i].at);
  s << ")\n";
}

/// One panel: its labels, key and plot command; `block` counts data blocks.
void panel_script(std::ostringstream& s, const PlotSpec& spec, const std::string& data_path, int& block) {
  s << "set title " << gp_quote(spec.title) << "\n"
    << "set xlabel " << gp_quote(spec.xlabel) << "\n"
    << "set ylabel " << gp_quote(spec.ylabel) << "\n"
    << "set grid\n"
    << "set key " << spec.key << " opaque\n";
  s << (spec.logx ? "set logscale x\nset format x '%g'\n" : "unset logscale x\nset format x '% h'\n");
  s << (spec.logy ? "set logscale y\nset format y '%g'\n" : "unset logscale y\nset format y '% h'\n");
  tics_script(s, "x", spec.xtics);
  tics_script(s, "y", spec.ytics);
  std::vector<std::string> parts;
  for (const PlotSeries& ser : spec.series) {
    if (ser.x.empty()) continue;
    const std::string src = gp_quote(data_path) + " index " + std::to_string(block);
    const std::string color = ser.color.empty() ? "" : " lc rgb " + gp_quote(ser.color);
    if (!ser.y_high.empty())
      parts.push_back(src + " using 1:2:3 with filledcurves fs transparent solid 0.4 noborder" + color + " title " +
                      gp_quote(ser.title));
    else
      parts.push_back(src + " using 1:2 with " + ser.style + " lw 2 pt 7 ps 1.2" + color + " title " + gp_quote(ser.title));
    if (!ser.labels.empty()) parts.push_back(src + " using 1:2:3 with labels offset char 1,0.7 font ',9' notitle");
    ++block;
  }
  for (const PlotHLine& h : spec.hlines)
    parts.push_back(number(h.y) + " with lines dt " + std::to_string(h.dashtype) + " lw 1.5 lc rgb " + gp_quote(h.color) +
                    (h.title.empty() ? " notitle" : " title " + gp_quote(h.title)));
  s << "plot ";
  for (size_t i = 0; i < parts.size(); ++i) s << (i ? ", \\\n     " : "") << parts[i];
  s << "\n";
}

/// Everything after `set terminal` and `set output`: the figure itself.
std::string figure_script(const PlotSpec& spec, const std::string& data_path) {
  std::ostringstream s;
  int block = 0;
  if (spec.panels.empty()) {
    panel_script(s, spec, data_path, block);
    return s.str();
  }
  // panels share the time axis: the same left and right edges (a key outside
  // on the right would otherwise move each panel's edge) and no padding in x
  s << "set multiplot layout " << spec.panels.size() << ",1 title " << gp_quote(spec.title) << "\n"
    << "set lmargin at screen 0.08\nset rmargin at screen 0.78\nset autoscale xfix\n";
  for (const PlotSpec& p : spec.panels) panel_script(s, p, data_path, block);
  s << "unset multiplot\nset lmargin\nset rmargin\nset autoscale x\n";
  return s.str();
}

/// The data file of the script: one block per drawn series (x y [y_high] ["label"]), two blank lines apart.
void write_plot_data(const PlotSpec& spec, const fs::path& data) {
  std::ofstream d(data);
  bool first = true;
  for (const PlotSeries* sp : drawn_series(spec)) {
    const PlotSeries& ser = *sp;
    if (!first) d << "\n\n";
    first = false;
    for (size_t i = 0; i < ser.x.size() && i < ser.y.size(); ++i) {
      d << number(ser.x[i]) << " " << number(ser.y[i]);
      if (!ser.y_high.empty()) d << " " << number(i < ser.y_high.size() ? ser.y_high[i] : ser.y[i]);
      if (!ser.labels.empty()) {
        std::string label = i < ser.labels.size() ? ser.labels[i] : "";
        for (char& c : label)
          if (c == '"') c = '\'';
        d << " \"" << label << "\"";
      }
      d << "\n";
    }
  }
}

/// svg_path with the PNG's extension replaced.
std::string svg_path_of(const std::string& png_path) { return fs::path(png_path).replace_extension(".svg").string(); }

}  // namespace

std::string gnuplot_script(const PlotSpec& spec, const std::string& terminal, const std::string& png_path,
                           const std::string& data_path) {
  std::ostringstream s;
  if (terminal == "pngcairo")
    s << "set terminal pngcairo size " << spec.width << "," << spec.height << " noenhanced font 'Sans,11'\n";
  else
    s << "set terminal png size " << spec.width << "," << spec.height << " noenhanced\n";
  const std::string figure = figure_script(spec, data_path);
  s << "set output " << gp_quote(png_path) << "\n" << figure;
  // the same figure as SVG (gnuplot's built-in svg terminal needs no cairo)
  s << "set output\n"
    << "set terminal svg size " << spec.width << "," << spec.height << " noenhanced font 'Sans,11' background '#ffffff'\n"
    << "set output " << gp_quote(svg_path_of(png_path)) << "\n"
    << figure << "set output\n";
  return s.str();
}

PlotOutcome plot_png(const PlotSpec& spec, const std::string& png_path) {
  PlotOutcome out;
  if (drawn_series(spec).empty()) {
    out.message = "nothing to plot (no points)";
    return out;
  }
  const std::string sidecar_error = write_plot_sidecar(spec, png_path);
  if (sidecar_error.empty()) out.sidecar = plot_sidecar_path(png_path);
  const std::string sidecar_note = sidecar_error.empty() ? "" : "; figure description not written: " + sidecar_error;
  if (!png_drawing()) {
    out.message = sidecar_error.empty() ? "figure description " + out.sidecar + " only (PNG drawing is off)"
                                        : "PNG drawing is off" + sidecar_note;
    return out;
  }
  out.terminal = gnuplot_png_terminal();
  if (out.terminal.empty()) {
    out.message = "gnuplot ('" + gnuplot_program() +
                  "') could not be run or has no PNG terminal; install gnuplot-nox (or set LPVID_GNUPLOT) "
                  "for the plot" + sidecar_note;
    return out;
  }
  const fs::path dir = make_temp_dir();
  if (dir.empty()) {
    out.message = "cannot create a temporary directory for the gnuplot script";
    return out;
  }
  const fs::path data = dir / "data.txt", script = dir / "plot.gp";
  write_plot_data(spec, data);
  std::ofstream(script) << gnuplot_script(spec, out.terminal, fs::absolute(png_path).string(), data.string());
  std::error_code ec;
  fs::remove(png_path, ec);
  fs::remove(svg_path_of(png_path), ec);
  int status = 0;
  const std::string log = run_capture(sh_quote(gnuplot_program()) + " " + sh_quote(script.string()), &status);
  const bool written = fs::exists(png_path, ec) && fs::file_size(png_path, ec) > 0;
  if (status != 0 || !written) {
    out.message = "gnuplot failed (exit status " + std::to_string(status) + ")" + (log.empty() ? "" : ": " + log);
  } else {
    out.ok = true;
    const std::string svg = svg_path_of(png_path);
    if (fs::exists(svg, ec) && fs::file_size(svg, ec) > 0) out.svg = svg;
    out.message = "wrote " + png_path + (out.svg.empty() ? "" : " and " + out.svg) + " (gnuplot, terminal " + out.terminal + ")" +
                  sidecar_note;
  }
  fs::remove_all(dir, ec);
  return out;
}

}  // namespace lpvid
