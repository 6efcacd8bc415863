// Diagnose plots (plot/diagnose_plots.h): the specifications, the
// gnuplot script (checked as text, so these tests need no gnuplot), the CSV
// written next to the PNG, and the PNG itself when gnuplot is installed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "plot/diagnose_plots.h"
#include "support/plot_records.h"
#include "support/test_signals.h"
#include "support/gen_identify.h"

namespace lpvid {
namespace {

using gen::ScratchDir;

std::string first_line(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  return line;
}

bool is_png(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  char sig[8] = {};
  f.read(sig, 8);
  return std::string(sig + 1, 3) == "PNG";
}

TEST(DiagnosePlots, AutocorrelationScriptHasTheBandLines) {
  const Mat<double> before = gaussian(400, 1, 1, 1.0), after = gaussian(400, 1, 2, 0.5);
  const PlotSpec spec = autocorrelation_plot_spec(before, after, {"level"});
  ASSERT_EQ(spec.series.size(), 2u);
  EXPECT_EQ(spec.series[0].title.rfind("level before (Q ", 0), 0u) << spec.series[0].title;
  EXPECT_EQ(spec.series[1].title.rfind("level after (Q ", 0), 0u) << spec.series[1].title;
  EXPECT_EQ(spec.series[0].x.size(), 26u);  // lags 0..25
  ASSERT_GE(spec.hlines.size(), 4u);
  const double b99 = whiteness_band(400, 0.99), b95 = whiteness_band(400, 0.95);
  EXPECT_DOUBLE_EQ(spec.hlines[0].y, b99);
  EXPECT_DOUBLE_EQ(spec.hlines[1].y, -b99);
  EXPECT_DOUBLE_EQ(spec.hlines[2].y, b95);
  EXPECT_DOUBLE_EQ(spec.hlines[3].y, -b95);

  const std::string script = gnuplot_script(spec, "pngcairo", "/tmp/a.png", "/tmp/d.txt");
  std::ostringstream upper, lower;
  upper.precision(17);
  lower.precision(17);
  upper << b99 << " with lines dt 2";
  lower << -b99 << " with lines dt 2";
  EXPECT_NE(script.find(upper.str()), std::string::npos) << script;
  EXPECT_NE(script.find(lower.str()), std::string::npos) << script;
  EXPECT_NE(script.find("title '99% band +-0.129'"), std::string::npos) << script;  // 2.5758/20
  EXPECT_NE(script.find("title '95% band +-0.098'"), std::string::npos) << script;
  EXPECT_NE(script.find("set xlabel 'lag k [samples]'"), std::string::npos);
}

TEST(DiagnosePlots, HLinesLeaveOldScriptsAlone) {
  PlotSpec spec;
  PlotSeries s;
  s.x = {1, 2};
  s.y = {3, 4};
  spec.series.push_back(s);
  const std::string script = gnuplot_script(spec, "png", "/tmp/o.png", "/tmp/d.txt");
  EXPECT_EQ(script.find("with lines dt"), std::string::npos);
  EXPECT_NE(script.find("'/tmp/d.txt' index 0 using 1:2 with linespoints"), std::string::npos);
}

TEST(DiagnosePlots, SpecsOfResidualAndOutputPlots) {
  const Mat<double> y = gaussian(100, 2, 3, 1.0), yb = gaussian(100, 2, 4, 1.0), ya = y + gaussian(100, 2, 5, 0.1);
  const PlotSpec r = residual_plot_spec(y - yb, y - ya, {"h1"});
  ASSERT_EQ(r.series.size(), 4u);
  EXPECT_EQ(r.series[0].title, "h1 before");
  EXPECT_EQ(r.series[1].title, "y2 before");
  EXPECT_EQ(r.series[3].title, "y2 after");
  EXPECT_NE(r.title.find("after"), std::string::npos);
  const PlotSpec f = output_fit_plot_spec(y, yb, Mat<double>(), {"h1", "h2"});
  ASSERT_EQ(f.series.size(), 4u);  // measured and model before, no after
  EXPECT_EQ(f.series[2].title, "h1 model before");
  EXPECT_EQ(f.title.find("after"), std::string::npos);
  const std::vector<TextColumn> table = plot_table(f, "sample");
  ASSERT_EQ(table.size(), 5u);
  EXPECT_EQ(table[0].name, "sample");
  EXPECT_EQ(table[3].name, "h1_model_before");
  EXPECT_EQ(table[3].cells.size(), 100u);
}

TEST(DiagnosePlots, WritesCsvAndPngOrSaysWhyNot) {
  ScratchDir dir("diagnose-plots");
  const Mat<double> before = gaussian(300, 1, 6, 1.0), after = gaussian(300, 1, 7, 0.3);
  const PlotOutcome a = plot_residual_autocorrelation(before, after, dir.file("acf.png"));
  EXPECT_EQ(first_line(dir.file("acf.csv")),
            "lag,acf_y1_before,acf_y1_after,acf_band_99_upper,acf_band_99_lower,acf_band_95_upper,acf_band_95_lower");
  const PlotOutcome r = plot_residual(before, after, dir.file("res.png"));
  EXPECT_EQ(first_line(dir.file("res.csv")), "sample,res_y1_before,res_y1_after");
  const PlotOutcome o = plot_output_fit(before, after, Mat<double>(), dir.file("fit.png"), {"v"});
  EXPECT_EQ(first_line(dir.file("fit.csv")), "sample,fit_v_measured,fit_v_model_before");
  for (const PlotOutcome* p : {&a, &r, &o}) EXPECT_NE(p->message.find(".csv"), std::string::npos) << p->message;
  if (gnuplot_png_terminal().empty()) GTEST_SKIP() << "gnuplot with a PNG terminal is not installed";
  for (const PlotOutcome* p : {&a, &r, &o}) EXPECT_TRUE(p->ok) << p->message;
  for (const char* f : {"acf.png", "res.png", "fit.png"}) EXPECT_TRUE(is_png(dir.file(f))) << f;
}

TEST(DiagnosePlots, CsvColumnsOfNamesWithARemarkDiffer) {
  // diagnose names the held-out rows "y1 (last fold)": before and after must stay two columns
  ScratchDir dir("diagnose-plots-remark");
  const Mat<double> before = gaussian(40, 1, 16, 1.0), after = gaussian(40, 1, 17, 0.3);
  plot_residual(before, after, dir.file("res.png"), {"y1 (last fold)"});
  EXPECT_EQ(first_line(dir.file("res.csv")), "sample,res_y1_last_fold_before,res_y1_last_fold_after");
  plot_residual_autocorrelation(before, after, dir.file("acf.png"), {"y1 (held out)"});
  EXPECT_EQ(first_line(dir.file("acf.csv")),
            "lag,acf_y1_held_out_before,acf_y1_held_out_after,acf_band_99_upper,acf_band_99_lower,acf_band_95_upper,"
            "acf_band_95_lower");
}

TEST(DiagnosePlots, TestRecordFigureHasTimeUnitsAndTheBand) {
  TestRecordPlot t = random_test_record("tanks.csv columns uVal,yVal");
  t.info.units = {{"uEst", "V"}, {"yEst", "V"}};
  const PlotSpec f = test_record_plot_spec(t);
  ASSERT_EQ(f.panels.size(), 2u);
  EXPECT_EQ(f.panels[0].xlabel, "time [s]");
  EXPECT_EQ(f.panels[0].ylabel, "input [V]");
  EXPECT_EQ(f.panels[1].ylabel, "output [V]");
  ASSERT_EQ(f.panels[1].series.size(), 5u);  // warm-up shading, band, measured, before, after
  const PlotSeries& band = f.panels[1].series[1];
  ASSERT_EQ(band.y_high.size(), 60u);
  EXPECT_DOUBLE_EQ(band.x[7], 28.0);  // sample 7 at 4 s
  EXPECT_DOUBLE_EQ(band.y[7], t.yhat_after(7, 0) - 0.25);
  EXPECT_DOUBLE_EQ(band.y_high[7], t.yhat_after(7, 0) + 0.25);
  // the figure's data blocks in order, both panels in one script, PNG then SVG
  const std::string script = gnuplot_script(f, "pngcairo", "/tmp/t.png", "/tmp/d.txt");
  EXPECT_NE(script.find("set multiplot layout 2,1"), std::string::npos) << script;
  EXPECT_NE(script.find("index 3 using 1:2:3 with filledcurves"), std::string::npos) << script;
  EXPECT_NE(script.find("set output '/tmp/t.svg'"), std::string::npos) << script;
  // CSV: distinct names, the band's two edges
  ScratchDir dir("test-record-plot");
  const PlotOutcome o = plot_test_record(t, dir.file("test.png"));
  EXPECT_EQ(first_line(dir.file("test.csv")),
            "time_s,test_uEst,test_yEst_band_lower,test_yEst_band_upper,test_yEst_measured,test_yEst_model_before,"
            "test_yEst_model_after");
  // the warm-up must leave samples to score; no sample time: the x axis counts samples
  t.warmup = 60;
  EXPECT_THROW(test_record_plot_spec(t), InputError);
  t.warmup = 10;
  t.info = {};
  EXPECT_EQ(test_record_plot_spec(t).panels[1].xlabel, "sample");
  EXPECT_EQ(test_record_plot_spec(t).panels[0].ylabel, "input (data units)");
  if (gnuplot_png_terminal().empty()) GTEST_SKIP() << "gnuplot with a PNG terminal is not installed";
  EXPECT_TRUE(o.ok) << o.message;
  EXPECT_TRUE(is_png(dir.file("test.png")));
  EXPECT_EQ(o.svg, dir.file("test.svg"));
  EXPECT_NE(first_line(o.svg).find("<?xml"), std::string::npos);
}

TEST(DiagnosePlots, RecordFigureShadesTheSelectionBlocks) {
  RecordPlot r;
  r.u = gaussian(80, 1, 21, 1.0);
  r.y = gaussian(80, 1, 22, 2.0);
  r.yhat_after = r.y + gaussian(80, 1, 23, 0.1);
  r.blocks = {{0, 40}, {40, 80}};
  r.input_columns = {"pump"};
  r.output_columns = {"level"};
  r.info.sample_time = 0.5;
  r.info.units = {{"pump", "V"}, {"level", "cm"}};
  r.first_row = 100;
  const PlotSpec f = record_plot_spec(r);
  ASSERT_EQ(f.panels.size(), 2u);
  EXPECT_EQ(f.panels[0].ylabel, "input [V]");
  EXPECT_EQ(f.panels[1].ylabel, "output [cm]");
  // input panel: two shaded blocks (legend), then the input; times from file row 100 at 0.5 s
  ASSERT_EQ(f.panels[0].series.size(), 3u);
  EXPECT_EQ(f.panels[0].series[1].title, "fold 2");
  EXPECT_DOUBLE_EQ(f.panels[0].series[1].x.front(), 70.0);  // (100 + 40) · 0.5
  EXPECT_DOUBLE_EQ(f.panels[0].series[1].y.front(), r.u.minCoeff());
  EXPECT_DOUBLE_EQ(f.panels[0].series[1].y_high.front(), r.u.maxCoeff());
  ScratchDir dir("record-plot");
  plot_record(r, dir.file("record.png"));
  EXPECT_EQ(first_line(dir.file("record.csv")), "time_s,record_pump,record_level_measured,record_level_model_after");
  r.blocks = {{70, 90}};
  EXPECT_THROW(record_plot_spec(r), InputError);
}

TEST(DiagnosePlots, StaticMapPlotEvaluatesTheMap) {
  StaticMap<double> g;
  g.kind = StaticKind::kPolynomial;
  g.coefficients = {0.0, 1.0, 0.4};  // y = v + 0.4 v^2
  const PlotSpec p = static_map_plot_spec(g, -2.0, 2.0, "g", "v", "y");
  ASSERT_EQ(p.series.size(), 2u);
  EXPECT_DOUBLE_EQ(p.series[0].x.front(), -2.0);
  EXPECT_DOUBLE_EQ(p.series[0].y.front(), -2.0 + 0.4 * 4.0);
  EXPECT_DOUBLE_EQ(p.series[0].x.back(), 2.0);
  EXPECT_DOUBLE_EQ(p.series[0].y.back(), 2.0 + 0.4 * 4.0);
  EXPECT_EQ(p.series[1].y, p.series[1].x);  // the identity for reference
  EXPECT_THROW(static_map_plot_spec(g, 1.0, 1.0, "g", "v", "y"), InputError);
}

TEST(DiagnosePlots, MissingGnuplotIsNotFatal) {
  const char* old = std::getenv("LPVID_GNUPLOT");
  const std::string saved = old ? old : "";
  setenv("LPVID_GNUPLOT", "/nonexistent/gnuplot-for-lpvid-test", 1);
  ScratchDir dir("diagnose-plots-nognuplot");
  const PlotOutcome out = plot_residual(gaussian(50, 1, 8, 1.0), Mat<double>(), dir.file("r.png"));
  if (old) setenv("LPVID_GNUPLOT", saved.c_str(), 1);
  else unsetenv("LPVID_GNUPLOT");
  EXPECT_FALSE(out.ok);
  EXPECT_NE(out.message.find("gnuplot"), std::string::npos) << out.message;
  EXPECT_TRUE(std::filesystem::exists(dir.file("r.csv")));
}

TEST(DiagnosePlots, BadInputThrows) {
  const Mat<double> a = gaussian(50, 1, 9, 1.0);
  Mat<double> nan = a;
  nan(0, 0) = std::nan("");
  EXPECT_THROW(residual_plot_spec(a, gaussian(49, 1, 1, 1.0)), InputError);
  EXPECT_THROW(residual_plot_spec(Mat<double>(), a), InputError);
  EXPECT_THROW(autocorrelation_plot_spec(a, gaussian(50, 2, 1, 1.0)), InputError);
  EXPECT_THROW(autocorrelation_plot_spec(nan, a), InputError);
  EXPECT_THROW(output_fit_plot_spec(a, gaussian(50, 2, 1, 1.0), Mat<double>()), InputError);
  EXPECT_THROW(output_fit_plot_spec(a, a, nan), InputError);
  ScratchDir dir("diagnose-plots-bad");
  EXPECT_THROW(plot_residual(a, nan, dir.file("r.png")), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("r.csv")));
}

}  // namespace
}  // namespace lpvid
