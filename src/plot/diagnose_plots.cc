#include "plot/diagnose_plots.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/input_error.h"
#include "core/number_text.h"

namespace lpvid {
namespace {

std::string output_name(const std::vector<std::string>& names, Eigen::Index i) {
  const auto k = static_cast<size_t>(i);
  return k < names.size() && !names[k].empty() ? names[k] : "y" + std::to_string(i + 1);
}

/// `before` must be a signal; `after` is empty (no columns) or of the same shape.
void check_before_after(const Mat<double>& before, const Mat<double>& after, const std::string& what) {
  require_signal(before, what + " before");
  if (after.cols() == 0) return;
  require_signal(after, what + " after");
  if (after.rows() != before.rows() || after.cols() != before.cols())
    throw InputError(what + ": 'after' is " + std::to_string(after.rows()) + " x " + std::to_string(after.cols()) +
                     ", 'before' is " + std::to_string(before.rows()) + " x " + std::to_string(before.cols()));
}

std::vector<double> range(Eigen::Index count) {
  std::vector<double> v(static_cast<size_t>(count));
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<double>(i);
  return v;
}

PlotSeries series(const std::string& title, std::vector<double> x, std::vector<double> y, const std::string& style) {
  PlotSeries s;
  s.title = title;
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  return s;
}

std::vector<double> column(const Mat<double>& m, Eigen::Index j) {
  std::vector<double> v(static_cast<size_t>(m.rows()));
  for (Eigen::Index i = 0; i < m.rows(); ++i) v[static_cast<size_t>(i)] = m(i, j);
  return v;
}

/// Adds "<name> <tag>" curves against the sample index for each column of m.
void add_columns(PlotSpec& spec, const Mat<double>& m, const std::vector<std::string>& names, const std::string& tag) {
  for (Eigen::Index i = 0; i < m.cols(); ++i)
    spec.series.push_back(series(output_name(names, i) + " " + tag, range(m.rows()), column(m, i), "lines"));
}

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

std::string sanitise(const std::string& title) {
  std::string out;
  for (char c : title.substr(0, title.find(" ("))) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out.empty() ? "value" : out;
}

std::vector<std::string> text(const std::vector<double>& v) {
  std::vector<std::string> out;
  out.reserve(v.size());
  for (double x : v) out.push_back(double_to_text(x));
  return out;
}

/// CSV (table) first, then the PNG; neither failure throws.
PlotOutcome write_plot(const PlotSpec& spec, const std::vector<TextColumn>& table, const std::string& png_path) {
  const std::string csv = plot_csv_path(png_path);
  std::string csv_note;
  try {
    write_csv(csv, table);
    csv_note = "numbers in " + csv;
  } catch (const std::exception& e) {
    csv_note = "numbers not written: " + std::string(e.what());
  }
  PlotOutcome out = plot_png(spec, png_path);
  out.message += "; " + csv_note;
  return out;
}

}  // namespace

std::string plot_csv_path(const std::string& png_path) {
  return std::filesystem::path(png_path).replace_extension(".csv").string();
}

std::vector<TextColumn> plot_table(const PlotSpec& spec, const std::string& x_name) {
  std::vector<TextColumn> cols;
  std::vector<const PlotSpec*> parts;  // a figure of panels: every panel's series, top to bottom
  if (spec.panels.empty()) parts.push_back(&spec);
  for (const PlotSpec& p : spec.panels) parts.push_back(&p);
  const std::vector<double>* x = nullptr;
  for (const PlotSpec* p : parts) {
    for (const PlotSeries& s : p->series) {
      if (!x) {
        x = &s.x;
        cols.push_back({x_name, text(s.x)});
      }
      if (s.x != *x) throw std::invalid_argument("plot_table: series '" + s.title + "' has other x values");
      if (s.y_high.empty()) {
        cols.push_back({sanitise(s.title), text(s.y)});
      } else {  // a band: its two edges
        cols.push_back({sanitise(s.title) + "_lower", text(s.y)});
        cols.push_back({sanitise(s.title) + "_upper", text(s.y_high)});
      }
    }
    if (x)
      for (const PlotHLine& h : p->hlines) cols.push_back({sanitise(h.title), text(std::vector<double>(x->size(), h.y))});
  }
  return cols;
}

PlotSpec residual_plot_spec(const Mat<double>& before, const Mat<double>& after,
                            const std::vector<std::string>& output_names) {
  check_before_after(before, after, "residual plot");
  PlotSpec spec;
  const ResidualRms rb = residual_rms(before);
  spec.title = "Residual r = y - yhat - Phi (RMS " + short_number(rb.overall);
  if (after.cols() > 0) spec.title += " before, " + short_number(residual_rms(after).overall) + " after";
  spec.title += ")";
  spec.xlabel = "sample t";
  spec.ylabel = "residual r(t)";
  spec.width = 1100;
  spec.key = "outside right top";  // a legend inside would cover part of a long record
  add_columns(spec, before, output_names, "before");
  add_columns(spec, after, output_names, "after");
  spec.hlines.push_back({0.0, "", "#000000", 1});
  return spec;
}

PlotSpec autocorrelation_plot_spec(const Mat<double>& before, const Mat<double>& after,
                                   const std::vector<std::string>& output_names,
                                   const ResidualAnalysisOptions& options) {
  check_before_after(before, after, "autocorrelation plot");
  const WhitenessResult wb = residual_whiteness(before, options);
  const WhitenessResult wa = after.cols() > 0 ? residual_whiteness(after, options) : WhitenessResult{};
  PlotSpec spec;
  spec.title = "Residual autocorrelation, n = " + std::to_string(before.rows()) +
               "; Ljung-Box portmanteau Q is white if <= " + short_number(wb.outputs[0].q_threshold) + " (chi2 at " +
               short_number(100 * wb.level) + "%)";
  spec.width = 1000;
  const std::vector<double> lags = range(wb.max_lag + 1);
  for (const auto* w : {&wb, &wa}) {
    for (size_t i = 0; i < w->outputs.size(); ++i)
      spec.series.push_back(series(output_name(output_names, static_cast<Eigen::Index>(i)) +
                                       (w == &wb ? " before" : " after") + " (Q " + short_number(w->outputs[i].q) + ")",
                                   lags, w->outputs[i].rho, "linespoints"));
  }
  spec.xlabel = "lag k";
  spec.ylabel = "normalised autocorrelation rho(k)";
  spec.hlines = {{wb.band_99, "99% band +-" + short_number(wb.band_99), "#cc0000", 2},
                 {-wb.band_99, "", "#cc0000", 2},
                 {wb.band_95, "95% band +-" + short_number(wb.band_95), "#ff8800", 3},
                 {-wb.band_95, "", "#ff8800", 3},
                 {0.0, "", "#000000", 1}};
  return spec;
}

PlotSpec output_fit_plot_spec(const Mat<double>& y, const Mat<double>& yhat_before, const Mat<double>& yhat_after,
                              const std::vector<std::string>& output_names) {
  require_signal(y, "output plot: measured output");
  check_before_after(yhat_before, yhat_after, "output plot: model output");
  if (yhat_before.rows() != y.rows() || yhat_before.cols() != y.cols())
    throw InputError("output plot: the model output is " + std::to_string(yhat_before.rows()) + " x " +
                     std::to_string(yhat_before.cols()) + ", the measured output " + std::to_string(y.rows()) + " x " +
                     std::to_string(y.cols()));
  PlotSpec spec;
  spec.title = "Measured and simulated output (RMS error " + short_number(residual_rms(y - yhat_before).overall);
  if (yhat_after.cols() > 0) spec.title += " before, " + short_number(residual_rms(y - yhat_after).overall) + " after";
  spec.title += ")";
  spec.xlabel = "sample t";
  spec.ylabel = "output";
  spec.width = 1100;
  spec.key = "outside right top";
  add_columns(spec, y, output_names, "measured");
  add_columns(spec, yhat_before, output_names, "model before");
  add_columns(spec, yhat_after, output_names, "model after");
  return spec;
}

PlotSpec test_record_plot_spec(const TestRecordPlot& t) {
  require_signal(t.u, "test plot: input");
  require_signal(t.y, "test plot: measured output");
  check_before_after(t.yhat_before, t.yhat_after, "test plot: model output");
  const Eigen::Index n = t.y.rows();
  if (t.u.rows() != n || t.yhat_before.rows() != n || t.yhat_before.cols() != t.y.cols())
    throw InputError("test plot: the input, output and model output differ in length or width");
  if (!(t.dmax_after >= 0) || !std::isfinite(t.dmax_after)) throw InputError("test plot: d_max must be finite and >= 0");
  if (t.warmup < 0 || t.warmup >= n) throw InputError("test plot: the warm-up must leave samples to score");
  std::vector<double> x(static_cast<size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) x[static_cast<size_t>(k)] = t.info.time_of(static_cast<double>(k));
  const auto name = [](const char* role, Eigen::Index i, Eigen::Index count) {
    return std::string(role) + (count > 1 ? std::to_string(i + 1) : "");
  };
  const auto unit_of = [&](const std::vector<std::string>& cols, Eigen::Index i) {
    return static_cast<size_t>(i) < cols.size() ? t.info.unit_of(cols[static_cast<size_t>(i)]) : std::string();
  };
  const auto axis = [&](const char* what, const std::vector<std::string>& cols, Eigen::Index count) {
    std::string u = count > 0 ? unit_of(cols, 0) : "";
    for (Eigen::Index i = 1; i < count; ++i)
      if (unit_of(cols, i) != u) u.clear();
    return std::string(what) + (u.empty() ? "" : " [" + u + "]");
  };
  PlotSpec fig;
  fig.width = 1200;
  fig.height = 800;
  const double scored = residual_rms(t.y.bottomRows(n - t.warmup) - t.yhat_before.bottomRows(n - t.warmup)).overall;
  // the file's name without its folders: the title must fit above the figure
  std::string source = t.source;
  const size_t space = source.find(' '), slash = source.substr(0, space).rfind('/');
  if (slash != std::string::npos) source = source.substr(slash + 1);
  fig.title = "Test record " + source + ": x0 from the first " + std::to_string(t.warmup) + " samples; RMS over the rest " +
              short_number(scored) + " before";
  if (t.yhat_after.cols() > 0)
    fig.title += ", " + short_number(residual_rms(t.y.bottomRows(n - t.warmup) - t.yhat_after.bottomRows(n - t.warmup)).overall) +
                 " after";
  PlotSpec in;
  in.title = "input";
  in.xlabel = t.info.time_label();
  in.ylabel = axis("input", t.input_columns, t.u.cols());
  in.key = "outside right top";
  for (Eigen::Index i = 0; i < t.u.cols(); ++i) in.series.push_back(series(name("u", i, t.u.cols()), x, column(t.u, i), "lines"));
  PlotSpec out;
  out.title = t.dmax_after > 0 ? "output; band: model after +- the certified d_max " + short_number(t.dmax_after) +
                                     " (an RMS bound on the estimation windows, not a pointwise one)"
                               : "output";
  out.xlabel = t.info.time_label();
  out.ylabel = axis("output", t.output_columns, t.y.cols());
  out.key = "outside right top";
  for (Eigen::Index i = 0; i < t.y.cols(); ++i) {
    const std::string yi = name("y", i, t.y.cols());
    if (t.yhat_after.cols() > 0 && t.dmax_after > 0) {
      PlotSeries band = series(yi + " band (after +- dmax)", x, column(t.yhat_after, i), "lines");
      band.y_high = band.y;
      for (size_t k = 0; k < band.y.size(); ++k) band.y[k] -= t.dmax_after, band.y_high[k] += t.dmax_after;
      band.color = "#7799dd";
      out.series.push_back(std::move(band));
    }
    PlotSeries measured = series(yi + " measured", x, column(t.y, i), "lines");
    measured.color = "#000000";
    out.series.push_back(std::move(measured));
    PlotSeries before = series(yi + " model before", x, column(t.yhat_before, i), "lines");
    before.color = "#dd7711";
    out.series.push_back(std::move(before));
    if (t.yhat_after.cols() > 0) {
      PlotSeries after = series(yi + " model after", x, column(t.yhat_after, i), "lines");
      after.color = "#1155cc";
      out.series.push_back(std::move(after));
    }
  }
  fig.panels = {std::move(in), std::move(out)};
  return fig;
}

PlotOutcome plot_test_record(const TestRecordPlot& t, const std::string& png_path) {
  const PlotSpec spec = test_record_plot_spec(t);
  return write_plot(spec, plot_table(spec, t.info.sample_time > 0 ? "time_s" : "sample"), png_path);
}

void use_time_axis(PlotSpec& spec, const SignalInfo& info, double first_row) {
  const auto shift = [&](PlotSpec& p) {
    for (PlotSeries& ser : p.series)
      for (double& x : ser.x) x = info.time_of(first_row + x);
    p.xlabel = info.sample_time > 0 ? "time [s]" : "file row";
  };
  shift(spec);
  for (PlotSpec& p : spec.panels) shift(p);
}

PlotOutcome plot_residual(const Mat<double>& before, const Mat<double>& after, const std::string& png_path,
                          const std::vector<std::string>& output_names, const SignalInfo& info, double first_row) {
  PlotSpec spec = residual_plot_spec(before, after, output_names);
  use_time_axis(spec, info, first_row);
  std::vector<TextColumn> table = plot_table(spec, info.sample_time > 0 ? "time_s" : "sample");
  table.pop_back();  // the zero line
  return write_plot(spec, table, png_path);
}

PlotOutcome plot_residual_autocorrelation(const Mat<double>& before, const Mat<double>& after,
                                          const std::string& png_path,
                                          const std::vector<std::string>& output_names,
                                          const ResidualAnalysisOptions& options) {
  const PlotSpec spec = autocorrelation_plot_spec(before, after, output_names, options);
  std::vector<TextColumn> table = plot_table(spec, "lag");
  table.pop_back();  // the zero line
  const char* names[] = {"band_99_upper", "band_99_lower", "band_95_upper", "band_95_lower"};
  for (size_t k = 0; k < 4; ++k) table[table.size() - 4 + k].name = names[k];
  return write_plot(spec, table, png_path);
}

PlotOutcome plot_output_fit(const Mat<double>& y, const Mat<double>& yhat_before, const Mat<double>& yhat_after,
                            const std::string& png_path, const std::vector<std::string>& output_names,
                            const SignalInfo& info, double first_row) {
  PlotSpec spec = output_fit_plot_spec(y, yhat_before, yhat_after, output_names);
  use_time_axis(spec, info, first_row);
  return write_plot(spec, plot_table(spec, info.sample_time > 0 ? "time_s" : "sample"), png_path);
}

}  // namespace lpvid
