// Rules every figure keeps (plot/palette.h, plot/plot_labels.h): CSV column
// names unique across the plots of one directory, the test record's warm-up
// shaded, one colour per role in every figure, no folder in a title, units on
// the axes, distinct tick labels. Known answers by construction: the figures
// are made from random signals with the roles and names diagnose gives them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>

#include "plot/diagnose_plots.h"
#include "plot/palette.h"
#include "plot/plot_labels.h"
#include "plot/plot_sidecar.h"
#include "plot/tradeoff_plot.h"
#include "support/gen_identify.h"
#include "support/plot_records.h"
#include "support/test_signals.h"

namespace lpvid {
namespace {

using gen::ScratchDir;

/// The CSV header's names.
std::vector<std::string> csv_names(const std::string& path) {
  std::ifstream f(path);
  std::string line, name;
  std::getline(f, line);
  std::vector<std::string> out;
  for (char c : line + ",") {
    if (c == ',') out.push_back(name), name.clear();
    else name += c;
  }
  return out;
}

/// No gnuplot run while alive (the CSV and the figure description are written all the same).
struct NoGnuplot {
  std::string old;
  bool had = false;
  NoGnuplot() {
    if (const char* o = std::getenv("LPVID_GNUPLOT")) old = o, had = true;
    setenv("LPVID_GNUPLOT", "/nonexistent/gnuplot", 1);
  }
  ~NoGnuplot() { had ? setenv("LPVID_GNUPLOT", old.c_str(), 1) : unsetenv("LPVID_GNUPLOT"); }
};

TestRecordPlot test_record(const std::string& source) { return random_test_record(source); }

RecordPlot record() {
  RecordPlot r;
  r.u = gaussian(80, 1, 21, 1.0);
  r.y = gaussian(80, 1, 22, 2.0);
  r.yhat_after = r.y + gaussian(80, 1, 23, 0.1);
  r.blocks = {{0, 40}, {40, 80}};
  r.input_columns = {"uEst"};
  r.output_columns = {"yEst"};
  r.info.sample_time = 4.0;
  r.title = "Estimation record data.csv rows 0:80";
  return r;
}

StaticMap<double> square_map() {
  StaticMap<double> g;
  g.kind = StaticKind::kPolynomial;
  g.coefficients = {0.0, 1.0, 0.4};
  return g;
}

TEST(PlotRules, CsvColumnNamesAreUniqueAcrossTheDiagnosePlots) {
  NoGnuplot no_gnuplot;
  ScratchDir dir("plot-rules-csv");
  const Mat<double> y = gaussian(120, 1, 1, 1.0), before = gaussian(120, 1, 2, 1.0), after = gaussian(120, 1, 3, 0.5);
  const std::vector<std::string> names = {"yEst (last fold)"};  // as diagnose names the shown rows
  plot_residual(y - before, y - after, dir.file("residual.png"), names);
  plot_residual_autocorrelation(y - before, y - after, dir.file("autocorrelation.png"), names);
  plot_output_fit(y, before, after, dir.file("output.png"), names);
  plot_record(record(), dir.file("record.png"));
  plot_test_record(test_record("a.csv"), dir.file("test1.png"));
  plot_test_record(test_record("b.csv"), dir.file("test2.png"));
  plot_static_map(square_map(), -1, 1, "g_in", "u", "u'", dir.file("input_map.png"));
  plot_static_map(square_map(), -1, 1, "g_out", "v", "y", dir.file("output_map.png"));
  std::map<std::string, std::string> owner;  // column name -> the CSV it was first seen in
  for (const char* stem : {"residual", "autocorrelation", "output", "record", "test1", "test2", "input_map", "output_map"}) {
    const std::vector<std::string> cols = csv_names(dir.file(std::string(stem) + ".csv"));
    ASSERT_GE(cols.size(), 2u) << stem;
    EXPECT_EQ(std::set<std::string>(cols.begin(), cols.end()).size(), cols.size()) << stem;
    for (size_t k = 1; k < cols.size(); ++k) {  // the first column is the x axis (time_s, lag, …)
      const auto [it, fresh] = owner.emplace(cols[k], stem);
      EXPECT_TRUE(fresh) << cols[k] << " in " << stem << ".csv and in " << it->second << ".csv";
    }
  }
}

TEST(PlotRules, TestPlotShadesTheWarmupInItsFigureDescription) {
  NoGnuplot no_gnuplot;
  ScratchDir dir("plot-rules-warmup");
  const TestRecordPlot t = test_record("tanks.csv columns uVal,yVal");
  plot_test_record(t, dir.file("test.png"));
  std::ifstream f(plot_sidecar_path(dir.file("test.png")));
  const nlohmann::json j = nlohmann::json::parse(f);
  ASSERT_EQ(j["panels"].size(), 2u);
  for (const auto& panel : j["panels"]) {  // in both panels: a band over exactly the warm-up samples
    bool shaded = false;
    for (const auto& s : panel["series"]) {
      if (s["kind"] != "band" || s["color"] != palette::kWarmup) continue;
      const auto& x = j["x_values"][s["x"].get<size_t>()];
      ASSERT_EQ(x.size(), static_cast<size_t>(t.warmup));
      EXPECT_DOUBLE_EQ(x[0].get<double>(), 0.0);
      EXPECT_DOUBLE_EQ(x[9].get<double>(), 36.0);  // sample 9 at 4 s
      shaded = true;
    }
    EXPECT_TRUE(shaded) << panel["title"];
  }
  EXPECT_NE(j["panels"][0]["series"][0]["title"].get<std::string>().find("warm-up"), std::string::npos);
}

/// The role of a curve by its legend text ("" for none of the three).
std::string role_of(const std::string& title) {
  if (title.find("measured") != std::string::npos) return "measured";
  if (title.find("band") != std::string::npos || title.find("fold") == 0 || title.find("warm-up") == 0) return "";
  if (title.find("after") != std::string::npos) return "after";
  if (title.find("before") != std::string::npos) return "before";
  return "";
}

TEST(PlotRules, OneColourPerRoleInEveryFigure) {
  const Mat<double> y = gaussian(120, 1, 1, 1.0), before = gaussian(120, 1, 2, 1.0), after = gaussian(120, 1, 3, 0.5);
  const std::vector<PlotSpec> figures = {residual_plot_spec(y - before, y - after),
                                         autocorrelation_plot_spec(y - before, y - after),
                                         output_fit_plot_spec(y, before, after),
                                         test_record_plot_spec(test_record("a.csv")),
                                         record_plot_spec(record())};
  std::map<std::string, std::set<std::string>> colours;
  for (const PlotSpec& fig : figures) {
    std::vector<const PlotSpec*> parts = {&fig};
    for (const PlotSpec& p : fig.panels) parts.push_back(&p);
    for (const PlotSpec* p : parts)
      for (const PlotSeries& s : p->series)
        if (!role_of(s.title).empty()) colours[role_of(s.title)].insert(s.color);
  }
  EXPECT_EQ(colours["measured"], std::set<std::string>{palette::kMeasured});
  EXPECT_EQ(colours["before"], std::set<std::string>{palette::kModelBefore});
  EXPECT_EQ(colours["after"], std::set<std::string>{palette::kModelAfter});
  // the record's input and the test record's input: one colour too
  EXPECT_EQ(figures[3].panels[0].series.back().color, palette::kInput);
  EXPECT_EQ(figures[4].panels[0].series.back().color, palette::kInput);
}

TEST(PlotRules, NoFolderInAnyTitle) {
  EXPECT_EQ(title_without_folders("delta-dmax trade-off: /home/me/data/run.csv"), "delta-dmax trade-off: run.csv");
  EXPECT_EQ(title_without_folders("Test record ../x/t.csv columns u,y rows 0:9"), "Test record t.csv columns u,y rows 0:9");
  EXPECT_EQ(title_without_folders("y / scale"), "y / scale");  // a lone '/' is not a path
  const std::vector<PlotSpec> figures = {tradeoff_plot({}, "delta-dmax trade-off: /home/me/data/run.csv"),
                                         test_record_plot_spec(test_record("/home/me/data/tanks.csv columns uVal,yVal"))};
  for (const PlotSpec& fig : figures) {
    EXPECT_EQ(fig.title.find('/'), std::string::npos) << fig.title;
    for (const PlotSpec& p : fig.panels) EXPECT_EQ(p.title.find('/'), std::string::npos) << p.title;
  }
}

TEST(PlotRules, UnitsOnEveryAxisAndPhiExplained) {
  const Mat<double> r = gaussian(50, 1, 4, 1.0);
  const PlotSpec known = residual_plot_spec(r, r, {}, "V"), unknown = residual_plot_spec(r, r);
  EXPECT_EQ(known.ylabel, "residual r(t) [V]");
  EXPECT_EQ(unknown.ylabel, "residual r(t) (data units)");
  EXPECT_NE(known.title.find("Phi ="), std::string::npos) << known.title;
  EXPECT_EQ(output_fit_plot_spec(r, r, r).ylabel, "output (data units)");
  EXPECT_EQ(autocorrelation_plot_spec(r, r).xlabel, "lag k [samples]");
  TestRecordPlot t = test_record("a.csv");
  EXPECT_EQ(test_record_plot_spec(t).panels[0].ylabel, "input (data units)");
  t.info.units = {{"uEst", "V"}, {"yEst", "cm"}};
  EXPECT_EQ(test_record_plot_spec(t).panels[1].ylabel, "output [cm]");
}

TEST(PlotRules, TradeoffTicksAreDistinct) {
  // d_max within 4 % of 0.1, delta over three decades: gnuplot's own ticks would repeat "0.1"
  const std::vector<double> dmax = {0.1, 0.101, 0.102, 0.104}, delta = {0.001, 0.01, 0.1, 1.0};
  for (const auto& [values, log] : {std::pair{dmax, false}, std::pair{delta, true}}) {
    const std::vector<PlotTick> ticks = distinct_ticks(values, log);
    ASSERT_GE(ticks.size(), 2u);
    std::set<std::string> labels;
    for (const PlotTick& t : ticks) {
      labels.insert(t.label);
      EXPECT_NEAR(std::stod(t.label), t.at, 1e-12 * t.at) << t.label;  // the label is where the tick is
      EXPECT_GE(t.at, values.front() * (1 - 1e-12));
      EXPECT_LE(t.at, values.back() * (1 + 1e-12));
    }
    EXPECT_EQ(labels.size(), ticks.size());
  }
  // known answers: steps of 0.001 on the narrow range, the powers of ten on three decades
  EXPECT_EQ(distinct_ticks(dmax, false).size(), 5u);
  EXPECT_EQ(distinct_ticks(dmax, false)[1].label, "0.101");
  EXPECT_EQ(distinct_ticks(delta, true).size(), 4u);
  EXPECT_EQ(distinct_ticks(delta, true)[0].label, "0.001");
  EXPECT_EQ(distinct_ticks({0.5, 0.5}, false).size(), 1u);
  EXPECT_TRUE(distinct_ticks({}, false).empty());
}

}  // namespace
}  // namespace lpvid
