#include "plot/diagnose_plots.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/input_error.h"
#include "core/number_text.h"
#include "plot/palette.h"
#include "plot/plot_labels.h"

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

/// Adds "<name> <tag>" curves against the sample index for each column of m, in the role's colour.
void add_columns(PlotSpec& spec, const Mat<double>& m, const std::vector<std::string>& names, const std::string& tag,
                 const char* color) {
  for (Eigen::Index i = 0; i < m.cols(); ++i) {
    spec.series.push_back(series(output_name(names, i) + " " + tag, range(m.rows()), column(m, i), "lines"));
    spec.series.back().color = color;
  }
}

/// Adds column i of m against x as a line of a fixed colour ("" for gnuplot's cycle).
void add_line(PlotSpec& p, const std::string& title, const std::vector<double>& x, const Mat<double>& m, Eigen::Index i,
              const std::string& color) {
  p.series.push_back(series(title, x, column(m, i), "lines"));
  p.series.back().color = color;
}

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

/// The column name of a title: a closing remark " (…)" dropped (a remark
/// inside the name stays: "y1 (last fold) before" -> y1_last_fold_before,
/// so that the before and after columns differ), every run of other
/// characters than letters and digits one '_'.
std::string sanitise(const std::string& title) {
  std::string name = title;
  if (!name.empty() && name.back() == ')') {
    int depth = 0;
    for (size_t i = name.size(); i-- > 0;) {
      depth += name[i] == ')' ? 1 : name[i] == '(' ? -1 : 0;
      if (depth == 0) {
        if (i > 0 && name[i - 1] == ' ') name.erase(i - 1);
        break;
      }
    }
  }
  std::string out;
  for (char c : name) {
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

/// CSV (table) first, then the PNG; neither failure throws. Every column
/// but the x axis is named "<figure's file stem>_<curve>" (residual_y1_before,
/// test2_y1_measured): unique across the plots of one directory.
PlotOutcome write_plot(const PlotSpec& spec, std::vector<TextColumn> table, const std::string& png_path) {
  const std::string csv = plot_csv_path(png_path);
  const std::string stem = sanitise(std::filesystem::path(png_path).stem().string());
  for (size_t k = 1; k < table.size(); ++k) table[k].name = stem + "_" + table[k].name;
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
                            const std::vector<std::string>& output_names, const std::string& output_unit) {
  check_before_after(before, after, "residual plot");
  PlotSpec spec;
  const ResidualRms rb = residual_rms(before);
  spec.title = "Residual r = y - yhat - Phi, Phi = the output of the scheduled basis terms (RMS " +
               short_number(rb.overall);
  if (after.cols() > 0) spec.title += " before, " + short_number(residual_rms(after).overall) + " after";
  spec.title += ")";
  spec.xlabel = "sample t";
  spec.ylabel = "residual r(t)" + unit_suffix(output_unit);
  spec.width = 1100;
  spec.key = "outside right top";  // a legend inside would cover part of a long record
  add_columns(spec, before, output_names, "before", palette::kModelBefore);
  add_columns(spec, after, output_names, "after", palette::kModelAfter);
  spec.hlines.push_back({0.0, "", palette::kReference, 1});
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
    for (size_t i = 0; i < w->outputs.size(); ++i) {
      spec.series.push_back(series(output_name(output_names, static_cast<Eigen::Index>(i)) +
                                       (w == &wb ? " before" : " after") + " (Q " + short_number(w->outputs[i].q) + ")",
                                   lags, w->outputs[i].rho, "linespoints"));
      spec.series.back().color = w == &wb ? palette::kModelBefore : palette::kModelAfter;
    }
  }
  spec.xlabel = "lag k [samples]";
  spec.ylabel = "normalised autocorrelation rho(k) (no unit)";
  spec.hlines = {{wb.band_99, "99% band +-" + short_number(wb.band_99), palette::kBound, 2},
                 {-wb.band_99, "", palette::kBound, 2},
                 {wb.band_95, "95% band +-" + short_number(wb.band_95), palette::kSecondaryBound, 3},
                 {-wb.band_95, "", palette::kSecondaryBound, 3},
                 {0.0, "", palette::kReference, 1}};
  return spec;
}

PlotSpec output_fit_plot_spec(const Mat<double>& y, const Mat<double>& yhat_before, const Mat<double>& yhat_after,
                              const std::vector<std::string>& output_names, const std::string& output_unit) {
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
  spec.ylabel = "output" + unit_suffix(output_unit);
  spec.width = 1100;
  spec.key = "outside right top";
  add_columns(spec, y, output_names, "measured", palette::kMeasured);
  add_columns(spec, yhat_before, output_names, "model before", palette::kModelBefore);
  add_columns(spec, yhat_after, output_names, "model after", palette::kModelAfter);
  return spec;
}

namespace {

/// x of samples 0..n-1 whose first is file row first_row: seconds when the sample time is known, else the row.
std::vector<double> time_axis(const SignalInfo& info, double first_row, Eigen::Index n) {
  std::vector<double> x(static_cast<size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) x[static_cast<size_t>(k)] = info.time_of(first_row + static_cast<double>(k));
  return x;
}

/// "input [V]" when the count first columns share a unit, else "input (data units)".
std::string axis_label(const char* what, const SignalInfo& info, const std::vector<std::string>& cols, Eigen::Index count) {
  const std::vector<std::string> first(cols.begin(), cols.begin() + std::min<Eigen::Index>(count, static_cast<Eigen::Index>(cols.size())));
  return std::string(what) + unit_suffix(common_unit(info, first));
}

/// A panel of a stacked figure: its title and axis labels, the legend outside on the right.
PlotSpec panel(const std::string& title, const std::string& xlabel, const std::string& ylabel) {
  PlotSpec p;
  p.title = title;
  p.xlabel = xlabel;
  p.ylabel = ylabel;
  p.key = "outside right top";
  return p;
}

/// Rows [first, last) shaded over the panel's range [lo, hi] (a band series).
void shade_rows(PlotSpec& p, const std::vector<double>& x, long first, long last, double lo, double hi,
                const std::string& title, const char* color) {
  PlotSeries band;
  band.title = title;
  band.x.assign(x.begin() + first, x.begin() + last);
  band.y.assign(band.x.size(), lo);
  band.y_high.assign(band.x.size(), hi);
  band.color = color;
  p.series.push_back(std::move(band));
}

/// The name of column i: the model's column, else prefix + (i + 1) (prefix alone for one column).
std::string signal_name(const std::vector<std::string>& cols, Eigen::Index i, Eigen::Index count, const char* prefix) {
  if (static_cast<size_t>(i) < cols.size() && !cols[static_cast<size_t>(i)].empty()) return cols[static_cast<size_t>(i)];
  return std::string(prefix) + (count > 1 ? std::to_string(i + 1) : "");
}

/// Checks a test record's signals (shapes, d_max, warm-up).
void check_test_record(const TestRecordPlot& t) {
  require_signal(t.u, "test plot: input");
  require_signal(t.y, "test plot: measured output");
  check_before_after(t.yhat_before, t.yhat_after, "test plot: model output");
  const Eigen::Index n = t.y.rows();
  if (t.u.rows() != n || t.yhat_before.rows() != n || t.yhat_before.cols() != t.y.cols())
    throw InputError("test plot: the input, output and model output differ in length or width");
  if (!(t.dmax_after >= 0) || !std::isfinite(t.dmax_after)) throw InputError("test plot: d_max must be finite and >= 0");
  if (t.warmup < 0 || t.warmup >= n) throw InputError("test plot: the warm-up must leave samples to score");
}

/// The RMS of the scored rows (after the warm-up) of y - yhat.
double scored_rms(const TestRecordPlot& t, const Mat<double>& yhat) {
  const Eigen::Index m = t.y.rows() - t.warmup;
  return residual_rms(t.y.bottomRows(m) - yhat.bottomRows(m)).overall;
}

/// The test record's output panel: the d_max band, measured, model before and after per output.
PlotSpec test_output_panel(const TestRecordPlot& t, const std::vector<double>& x) {
  PlotSpec out = panel(t.dmax_after > 0 ? "output; band: model after +- the certified d_max " + short_number(t.dmax_after) +
                                              " (an RMS bound on the estimation windows, not a pointwise one)"
                                        : "output",
                       t.info.time_label(), axis_label("output", t.info, t.output_columns, t.y.cols()));
  for (Eigen::Index i = 0; i < t.y.cols(); ++i) {
    const std::string yi = signal_name(t.output_names.empty() ? t.output_columns : t.output_names, i, t.y.cols(), "y");
    if (t.yhat_after.cols() > 0 && t.dmax_after > 0) {
      PlotSeries band = series(yi + " band (after +- dmax)", x, column(t.yhat_after, i), "lines");
      band.y_high = band.y;
      for (size_t k = 0; k < band.y.size(); ++k) band.y[k] -= t.dmax_after, band.y_high[k] += t.dmax_after;
      band.color = palette::kBoundBand;
      out.series.push_back(std::move(band));
    }
    add_line(out, yi + " measured", x, t.y, i, palette::kMeasured);
    add_line(out, yi + " model before", x, t.yhat_before, i, palette::kModelBefore);
    if (t.yhat_after.cols() > 0) add_line(out, yi + " model after", x, t.yhat_after, i, palette::kModelAfter);
  }
  return out;
}

/// The range [lo, hi] of the signals drawn in a panel (its lines, not its bands).
std::pair<double, double> drawn_range(const PlotSpec& p) {
  double lo = INFINITY, hi = -INFINITY;
  for (const PlotSeries& ser : p.series)
    for (size_t k = 0; k < ser.y.size(); ++k) {
      lo = std::min({lo, ser.y[k], ser.y_high.empty() ? ser.y[k] : ser.y_high[k]});
      hi = std::max({hi, ser.y[k], ser.y_high.empty() ? ser.y[k] : ser.y_high[k]});
    }
  return {lo, hi};
}

/// Shades rows [first, last) first in each panel (drawn under the lines); titled in the top panel only.
void shade_in_panels(std::vector<PlotSpec*> panels, const std::vector<double>& x, long first, long last,
                     const std::string& title, const char* color) {
  for (size_t k = 0; k < panels.size(); ++k) {
    PlotSpec& p = *panels[k];
    const auto [lo, hi] = drawn_range(p);
    PlotSpec shaded;
    shade_rows(shaded, x, first, last, lo, hi, k == 0 ? title : std::string(), color);
    p.series.insert(p.series.begin(), shaded.series.begin(), shaded.series.end());
  }
}

/// The spec without its shaded row ranges (bands over fewer samples than the record): the CSV's series.
PlotSpec without_shading(PlotSpec spec, size_t n) {
  for (PlotSpec& p : spec.panels)
    p.series.erase(std::remove_if(p.series.begin(), p.series.end(),
                                  [n](const PlotSeries& ser) { return !ser.y_high.empty() && ser.x.size() != n; }),
                   p.series.end());
  return spec;
}

}  // namespace

PlotSpec test_record_plot_spec(const TestRecordPlot& t) {
  check_test_record(t);
  const std::vector<double> x = time_axis(t.info, 0, t.y.rows());
  PlotSpec fig;
  fig.width = 1200;
  fig.height = 800;
  fig.title = "Test record " + title_without_folders(t.source) + ": x0 from the first " + std::to_string(t.warmup) +
              " samples (shaded); RMS over the rest " + short_number(scored_rms(t, t.yhat_before)) + " before";
  if (t.yhat_after.cols() > 0) fig.title += ", " + short_number(scored_rms(t, t.yhat_after)) + " after";
  PlotSpec in = panel("input", t.info.time_label(), axis_label("input", t.info, t.input_columns, t.u.cols()));
  for (Eigen::Index i = 0; i < t.u.cols(); ++i)
    add_line(in, signal_name(t.input_names.empty() ? t.input_columns : t.input_names, i, t.u.cols(), "u"), x, t.u, i,
             t.u.cols() == 1 ? palette::kInput : "");
  PlotSpec out = test_output_panel(t, x);
  if (t.warmup > 0)
    shade_in_panels({&in, &out}, x, 0, static_cast<long>(t.warmup), "warm-up (x0 fit, not scored)", palette::kWarmup);
  fig.panels = {std::move(in), std::move(out)};
  return fig;
}

PlotSpec record_plot_spec(const RecordPlot& r) {
  require_signal(r.u, "record plot: input");
  require_signal(r.y, "record plot: output");
  const Eigen::Index n = r.y.rows();
  if (r.u.rows() != n || (r.yhat_after.cols() > 0 && (r.yhat_after.rows() != n || r.yhat_after.cols() != r.y.cols())))
    throw InputError("record plot: the input, output and model output differ in length or width");
  for (const auto& [a, b] : r.blocks)
    if (a < 0 || b > n || a >= b) throw InputError("record plot: a selection block lies outside the record");
  const std::vector<double> x = time_axis(r.info, static_cast<double>(r.first_row), n);
  const std::string xlabel = r.info.sample_time > 0 ? "time [s]" : "file row";
  PlotSpec in = panel("input", xlabel, axis_label("input", r.info, r.input_columns, r.u.cols()));
  PlotSpec out = panel("output", xlabel, axis_label("output", r.info, r.output_columns, r.y.cols()));
  for (Eigen::Index i = 0; i < r.u.cols(); ++i)
    add_line(in, signal_name(r.input_columns, i, r.u.cols(), "u"), x, r.u, i, r.u.cols() == 1 ? palette::kInput : "");
  for (Eigen::Index i = 0; i < r.y.cols(); ++i) {
    const std::string yi = signal_name(r.output_columns, i, r.y.cols(), "y");
    add_line(out, yi + " measured", x, r.y, i, palette::kMeasured);
    if (r.yhat_after.cols() > 0) add_line(out, yi + " model after", x, r.yhat_after, i, palette::kModelAfter);
  }
  for (size_t b = r.blocks.size(); b-- > 0;)  // each inserted first: block 1 ends up first
    shade_in_panels({&in, &out}, x, r.blocks[b].first, r.blocks[b].second, r.block_name + " " + std::to_string(b + 1),
                    b % 2 ? palette::kSelectionAlternate : palette::kSelection);
  PlotSpec fig;
  fig.width = 1200;
  fig.height = 800;
  fig.title = r.title;
  fig.panels = {std::move(in), std::move(out)};
  return fig;
}

PlotOutcome plot_record(const RecordPlot& r, const std::string& png_path) {
  const PlotSpec spec = record_plot_spec(r);
  // CSV: the signals only (a shaded block is a row range, listed in the report)
  const PlotSpec signals = without_shading(spec, static_cast<size_t>(r.y.rows()));
  return write_plot(spec, plot_table(signals, r.info.sample_time > 0 ? "time_s" : "file_row"), png_path);
}

PlotSpec static_map_plot_spec(const StaticMap<double>& g, double lo, double hi, const std::string& title,
                              const std::string& argument, const std::string& value) {
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) throw InputError("static map plot: need a finite range lo < hi");
  constexpr int kPoints = 400;
  std::vector<double> v(kPoints + 1), gv(kPoints + 1);
  for (int i = 0; i <= kPoints; ++i) {
    v[static_cast<size_t>(i)] = lo + (hi - lo) * i / kPoints;
    gv[static_cast<size_t>(i)] = g(v[static_cast<size_t>(i)]);
  }
  PlotSpec spec;
  spec.title = title;
  spec.xlabel = argument;
  spec.ylabel = value;
  PlotSeries fitted = series("fitted map", v, gv, "lines");
  fitted.color = palette::kModelAfter;
  PlotSeries identity = series("identity (no map)", v, v, "lines");
  identity.color = palette::kReference;
  spec.series = {std::move(fitted), std::move(identity)};
  return spec;
}

PlotOutcome plot_static_map(const StaticMap<double>& g, double lo, double hi, const std::string& title,
                            const std::string& argument, const std::string& value, const std::string& png_path) {
  const PlotSpec spec = static_map_plot_spec(g, lo, hi, title, argument, value);
  return write_plot(spec, plot_table(spec, "argument"), png_path);
}

PlotOutcome plot_test_record(const TestRecordPlot& t, const std::string& png_path) {
  const PlotSpec spec = test_record_plot_spec(t);
  // CSV: the signals and the d_max band (the warm-up is the first t.warmup rows)
  const PlotSpec signals = without_shading(spec, static_cast<size_t>(t.y.rows()));
  return write_plot(spec, plot_table(signals, t.info.sample_time > 0 ? "time_s" : "sample"), png_path);
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
                          const std::vector<std::string>& output_names, const SignalInfo& info, double first_row,
                          const std::string& output_unit) {
  PlotSpec spec = residual_plot_spec(before, after, output_names, output_unit);
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
                            const SignalInfo& info, double first_row, const std::string& output_unit) {
  PlotSpec spec = output_fit_plot_spec(y, yhat_before, yhat_after, output_names, output_unit);
  use_time_axis(spec, info, first_row);
  return write_plot(spec, plot_table(spec, info.sample_time > 0 ? "time_s" : "sample"), png_path);
}

}  // namespace lpvid
