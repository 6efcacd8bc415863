#include "plot/plot_sidecar.h"

#include <array>
#include <filesystem>
#include <vector>

#include "core/file_io.h"

namespace lpvid {
namespace {

/// gnuplot 5's default colour sequence: plot element k (0-based, counted
/// within one `plot` command) without `lc` is drawn in kGnuplotCycle[k % 8].
constexpr std::array<const char*, 8> kGnuplotCycle = {"#9400d3", "#009e73", "#56b4e9", "#e69f00",
                                                       "#f0e442", "#0072b2", "#e51e10", "#000000"};

nlohmann::ordered_json numbers(const std::vector<double>& v) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (double x : v) a.push_back(x);  // NaN and infinities become null
  return a;
}

/// One panel; `xs` collects the distinct x vectors of the figure (a series
/// names its x by index: the panels of a record share one time axis).
nlohmann::ordered_json panel_json(const PlotSpec& p, const std::string& title,
                                  std::vector<const std::vector<double>*>& xs) {
  nlohmann::ordered_json j;
  j["title"] = title;
  j["xlabel"] = p.xlabel;
  j["ylabel"] = p.ylabel;
  j["logx"] = p.logx;
  j["logy"] = p.logy;
  j["key"] = p.key;
  for (const auto& [name, tics] : {std::pair{"xtics", &p.xtics}, std::pair{"ytics", &p.ytics}}) {
    if (tics->empty()) continue;  // gnuplot's own ticks
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const PlotTick& t : *tics) list.push_back({{"at", t.at}, {"label", t.label}});
    j[name] = list;
  }
  nlohmann::ordered_json series = nlohmann::ordered_json::array();
  size_t element = 0;  // gnuplot's plot elements of this panel, as in gnuplot.cc's panel_script
  for (const PlotSeries& s : p.series) {
    if (s.x.empty()) continue;
    size_t x = 0;
    while (x < xs.size() && *xs[x] != s.x) ++x;
    if (x == xs.size()) xs.push_back(&s.x);
    const size_t n = std::min(s.x.size(), s.y.size());
    nlohmann::ordered_json js;
    js["title"] = s.title;
    js["kind"] = s.y_high.empty() ? "line" : "band";
    js["style"] = s.style;
    js["color"] = s.color.empty() ? kGnuplotCycle[element % kGnuplotCycle.size()] : s.color;
    js["x"] = x;
    js["y"] = numbers(std::vector<double>(s.y.begin(), s.y.begin() + static_cast<long>(n)));
    if (!s.y_high.empty()) {
      std::vector<double> hi(n);
      for (size_t i = 0; i < n; ++i) hi[i] = i < s.y_high.size() ? s.y_high[i] : s.y[i];
      js["y_high"] = numbers(hi);
    }
    if (!s.labels.empty()) {
      std::vector<std::string> labels(n);
      for (size_t i = 0; i < n && i < s.labels.size(); ++i) labels[i] = s.labels[i];
      js["labels"] = labels;
      ++element;  // the labels are a plot element of their own
    }
    ++element;
    series.push_back(js);
  }
  j["series"] = series;
  nlohmann::ordered_json hlines = nlohmann::ordered_json::array();
  for (const PlotHLine& h : p.hlines)
    hlines.push_back({{"y", h.y}, {"title", h.title}, {"color", h.color}, {"dashtype", h.dashtype}});
  j["hlines"] = hlines;
  return j;
}

}  // namespace

std::string plot_sidecar_path(const std::string& png_path) {
  return std::filesystem::path(png_path).replace_extension(".plot.json").string();
}

nlohmann::ordered_json plot_spec_json(const PlotSpec& spec) {
  nlohmann::ordered_json j;
  j["format"] = "lpvid-plot";
  j["version"] = 1;
  j["title"] = spec.title;
  j["width"] = spec.width;
  j["height"] = spec.height;
  std::vector<const std::vector<double>*> xs;
  nlohmann::ordered_json panels = nlohmann::ordered_json::array();
  // a single plot is one panel whose title is the figure's (gnuplot draws it once)
  if (spec.panels.empty()) panels.push_back(panel_json(spec, "", xs));
  for (const PlotSpec& p : spec.panels) panels.push_back(panel_json(p, p.title, xs));
  nlohmann::ordered_json x_values = nlohmann::ordered_json::array();
  for (const std::vector<double>* x : xs) x_values.push_back(numbers(*x));
  j["x_values"] = x_values;
  j["panels"] = panels;
  return j;
}

std::string write_plot_sidecar(const PlotSpec& spec, const std::string& png_path) {
  try {
    write_text_file(plot_sidecar_path(png_path), plot_spec_json(spec).dump() + "\n", "figure description");
    return "";
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace lpvid
