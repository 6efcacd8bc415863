// The figure description beside every plot (plot/plot_sidecar.h): written
// by plot_png whether or not gnuplot can run, and holding the panels, the
// series' numbers, kinds and colours, and the horizontal lines of the spec.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "plot/diagnose_plots.h"
#include "plot/palette.h"
#include "plot/plot_sidecar.h"
#include "support/gen_identify.h"
#include "support/test_signals.h"

namespace lpvid {
namespace {

TEST(PlotSidecar, RecordFigureHasItsPanelsBlocksAndOneTimeAxis) {
  RecordPlot r;
  r.u = gaussian(40, 1, 31, 1.0);
  r.y = gaussian(40, 1, 32, 2.0);
  r.blocks = {{0, 20}, {20, 40}};
  r.input_columns = {"pump"};
  r.output_columns = {"level"};
  r.info.sample_time = 0.5;
  r.title = "record";
  const nlohmann::ordered_json j = plot_spec_json(record_plot_spec(r));
  EXPECT_EQ(j["format"], "lpvid-plot");
  EXPECT_EQ(j["title"], "record");
  ASSERT_EQ(j["panels"].size(), 2u);
  const auto& in = j["panels"][0];
  EXPECT_EQ(in["title"], "input");
  EXPECT_EQ(in["xlabel"], "time [s]");
  ASSERT_EQ(in["series"].size(), 3u);  // two shaded blocks, then the input
  EXPECT_EQ(in["series"][1]["kind"], "band");
  EXPECT_EQ(in["series"][1]["title"], "fold 2");
  EXPECT_DOUBLE_EQ(in["series"][1]["y"][0].get<double>(), r.u.minCoeff());
  EXPECT_DOUBLE_EQ(in["series"][1]["y_high"][0].get<double>(), r.u.maxCoeff());
  EXPECT_EQ(in["series"][2]["kind"], "line");
  EXPECT_EQ(in["series"][2]["color"], palette::kInput);  // the spec's own colour
  EXPECT_DOUBLE_EQ(in["series"][2]["y"][7].get<double>(), r.u(7, 0));
  // x: the whole record once, each block's rows once; both panels name the same vectors
  ASSERT_EQ(j["x_values"].size(), 3u);
  const auto& x = j["x_values"][in["series"][2]["x"].get<size_t>()];
  ASSERT_EQ(x.size(), 40u);
  EXPECT_DOUBLE_EQ(x[3].get<double>(), 1.5);  // row 3 at 0.5 s
  EXPECT_EQ(j["panels"][1]["series"][2]["x"], in["series"][2]["x"]);
}

TEST(PlotSidecar, DefaultColoursAreGnuplotsCycleAndLinesAreKept) {
  const Mat<double> before = gaussian(60, 1, 33, 1.0), after = gaussian(60, 1, 34, 0.3);
  PlotSpec spec = autocorrelation_plot_spec(before, after);
  EXPECT_EQ(plot_spec_json(spec)["panels"][0]["series"][0]["color"], palette::kModelBefore);  // the spec's own
  for (PlotSeries& ser : spec.series) ser.color.clear();  // none named: gnuplot's cycle
  const nlohmann::ordered_json j = plot_spec_json(spec);
  ASSERT_EQ(j["panels"].size(), 1u);
  const auto& p = j["panels"][0];
  EXPECT_EQ(p["title"], "");  // a single plot: the figure's title is the plot's
  EXPECT_EQ(p["series"][0]["color"], "#9400d3");
  EXPECT_EQ(p["series"][1]["color"], "#009e73");
  EXPECT_EQ(p["series"][1]["style"], "linespoints");
  ASSERT_EQ(p["hlines"].size(), 5u);
  EXPECT_EQ(p["hlines"][2]["dashtype"], 3);
  EXPECT_GT(p["hlines"][0]["y"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(p["hlines"][1]["y"].get<double>(), -p["hlines"][0]["y"].get<double>());
}

TEST(PlotSidecar, WrittenBesideThePngEvenWithoutGnuplot) {
  const char* old = std::getenv("LPVID_GNUPLOT");
  const std::string saved = old ? old : "";
  setenv("LPVID_GNUPLOT", "/nonexistent/gnuplot-for-lpvid-test", 1);
  gen::ScratchDir dir("plot-sidecar");
  const PlotOutcome out = plot_residual(gaussian(50, 1, 35, 1.0), Mat<double>(), dir.file("r.png"));
  if (old) setenv("LPVID_GNUPLOT", saved.c_str(), 1);
  else unsetenv("LPVID_GNUPLOT");
  EXPECT_FALSE(out.ok);
  EXPECT_EQ(out.sidecar, dir.file("r.plot.json"));
  std::ifstream f(dir.file("r.plot.json"));
  const nlohmann::json j = nlohmann::json::parse(f);
  EXPECT_EQ(j["panels"][0]["series"][0]["y"].size(), 50u);
  EXPECT_EQ(plot_sidecar_path("a/b.png"), "a/b.plot.json");
}

}  // namespace
}  // namespace lpvid
