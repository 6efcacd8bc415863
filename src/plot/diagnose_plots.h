#pragma once
/// The plots of `lpvid diagnose` (docs/design.md §9.4), drawn by
/// gnuplot through plot/gnuplot.h:
///  (a) the residual r = y − ŷ − Φ before and after adding the effect, per
///      sample;
///  (b) its normalised autocorrelation (lags 0..L) before and after, with
///      the 99 % and 95 % whiteness bands ±z/√n (residual_analysis.h);
///  (c) the measured output with the model output before and after.
///
/// Every plot_* function writes the numbers of its plot as CSV next to the
/// PNG (same path, extension .csv; first column the x axis, then one column
/// per curve named "<file stem>_<plot_table's name>", unique across the plots
/// of one folder) and then the PNG. A missing or failing gnuplot or an
/// unwritable CSV is not an error: the PlotOutcome says what happened
/// (ok = the PNG was written). Bad signals (empty, non-finite, mismatched
/// shapes) throw lpvid::InputError before anything is written.
///
/// `after` (and `yhat_after`) may have no columns: the plot then shows the
/// "before" curves only (e.g. when no effect was found). Output names
/// default to y1, y2, ….

#include <string>
#include <utility>
#include <vector>

#include "core/scalar.h"
#include "data/csv_writer.h"
#include "data/signal_info.h"
#include "model/static_blocks.h"
#include "diagnose/residual_analysis.h"
#include "plot/gnuplot.h"
#include "plot/plot_labels.h"

namespace lpvid {

/// The figure of one test record (scored once at the end): the input(s) on
/// top; below, the measured output, the model's free-run output before and
/// after, and the after model's output ± the certified d_max as a band. The x
/// axis is time in seconds when the sample time is known, else the sample.
/// d_max bounds the noise's RMS on the estimation windows, so the band shows
/// its size, not a pointwise guarantee (the title says so). The warm-up rows
/// (x0 fit, not scored) are shaded in both panels (palette::kWarmup).
struct TestRecordPlot {
  Mat<double> u, y, yhat_before, yhat_after;  ///< yhat_after may have no columns
  double dmax_after = 0;                      ///< certified d_max of the after model; 0: no band
  Eigen::Index warmup = 0;                    ///< first samples used for x0, not scored
  std::vector<std::string> input_columns, output_columns;  ///< the model's columns (their units apply)
  std::vector<std::string> input_names, output_names;      ///< legends: the test record's columns (empty: the model's)
  SignalInfo info;
  std::string source;                         ///< the record's file and columns (title)
};

/// The whole estimation record and the roles of its rows: the input(s) on
/// top, below the measured output and the after model's free run (x0 from the
/// first samples), each selection block (a fold held out, or the validation
/// rows) shaded in both panels. x: time_of(first_row + k).
struct RecordPlot {
  Mat<double> u, y, yhat_after;                 ///< yhat_after may have no columns
  std::vector<std::pair<long, long>> blocks;    ///< selection rows [first, last) of the record
  std::string block_name = "fold";              ///< "fold k" in the legend
  std::vector<std::string> input_columns, output_columns;
  SignalInfo info;
  long first_row = 0;                           ///< file row of the record's first sample
  std::string title;
};

/// A fitted static map g (model/static_blocks.h) over [lo, hi], with the
/// identity for reference.
PlotSpec static_map_plot_spec(const StaticMap<double>& g, double lo, double hi, const std::string& title,
                              const std::string& argument, const std::string& value);

/// The plot specifications (exposed for tests and for other front ends).
PlotSpec record_plot_spec(const RecordPlot& r);
PlotSpec test_record_plot_spec(const TestRecordPlot& t);
/// output_unit: the outputs' unit (axis label "[unit]"; "" labels it "(data units)").
PlotSpec residual_plot_spec(const Mat<double>& before, const Mat<double>& after,
                            const std::vector<std::string>& output_names = {}, const std::string& output_unit = "");
PlotSpec autocorrelation_plot_spec(const Mat<double>& before, const Mat<double>& after,
                                   const std::vector<std::string>& output_names = {},
                                   const ResidualAnalysisOptions& options = {});
PlotSpec output_fit_plot_spec(const Mat<double>& y, const Mat<double>& yhat_before, const Mat<double>& yhat_after,
                              const std::vector<std::string>& output_names = {}, const std::string& output_unit = "");

/// The CSV table of a plot whose series share their x values: column
/// `x_name`, then one column per series and one per horizontal line, named
/// by the titles without a closing " (…)" remark, with spaces and symbols
/// replaced by '_' ("y1 before (Q 12.3)" -> y1_before, "y1 (last fold)
/// before" -> y1_last_fold_before).
std::vector<TextColumn> plot_table(const PlotSpec& spec, const std::string& x_name);

/// png_path with its extension replaced by ".csv".
std::string plot_csv_path(const std::string& png_path);

/// Puts a plot over samples on the record's time axis: x ↦ time_of(first_row
/// + x), i.e. seconds when the sample time is known, else the file row; the
/// x label says which.
void use_time_axis(PlotSpec& spec, const SignalInfo& info, double first_row);

/// `info` and `first_row` (the file row of the first sample): use_time_axis;
/// the CSV's first column is then time_s (or sample, the file row).
/// output_unit: as residual_plot_spec.
PlotOutcome plot_residual(const Mat<double>& before, const Mat<double>& after, const std::string& png_path,
                          const std::vector<std::string>& output_names = {}, const SignalInfo& info = {},
                          double first_row = 0, const std::string& output_unit = "");
PlotOutcome plot_residual_autocorrelation(const Mat<double>& before, const Mat<double>& after,
                                          const std::string& png_path,
                                          const std::vector<std::string>& output_names = {},
                                          const ResidualAnalysisOptions& options = {});
/// The CSV columns: time (or sample), u…, then per output measured, model
/// before/after and the band's lower and upper edge.
PlotOutcome plot_test_record(const TestRecordPlot& t, const std::string& png_path);
PlotOutcome plot_record(const RecordPlot& r, const std::string& png_path);
PlotOutcome plot_static_map(const StaticMap<double>& g, double lo, double hi, const std::string& title,
                            const std::string& argument, const std::string& value, const std::string& png_path);
PlotOutcome plot_output_fit(const Mat<double>& y, const Mat<double>& yhat_before, const Mat<double>& yhat_after,
                            const std::string& png_path, const std::vector<std::string>& output_names = {},
                            const SignalInfo& info = {}, double first_row = 0, const std::string& output_unit = "");

}  // namespace lpvid
