// lpvid compare. Known answers by construction: on noise-free data of the
// true system the free run reproduces y (fit 100 %, RMS at the 10-decimal
// rounding of the data); a window that starts mid-record needs its state,
// which --x0 fit recovers; and the fit % in the report is recomputed here
// from the series compare writes (fit = 100·(1 − ‖y − ŷ‖/‖y − ȳ‖)).
#include <gtest/gtest.h>

#include <cmath>

#include "data/csv_reader.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct Compare : CliRunner {};

TEST_F(Compare, TrueSystemOnCleanDataFitsPerfectlyAndAWindowNeedsItsState) {
  ASSERT_EQ(run("generate", "example1 --n 200 --out " + file("d.csv") + " --truth-out " + file("t.json")), 0) << output();
  ASSERT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("t.json") + " --report " + file("r.json")), 0)
      << output();
  const nlohmann::json all = read_json(file("r.json"));
  EXPECT_GT(all["fit_percent"].get<double>(), 99.9999) << all.dump();
  EXPECT_LT(all["rms"].get<double>(), 1e-9) << all.dump();

  // rows 100:200 from x0 = 0 miss the state at row 100; fitted, it is recovered
  ASSERT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("t.json") + " --rows 100:200 --report " +
                               file("w0.json")),
            0)
      << output();
  ASSERT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("t.json") + " --rows 100:200 --x0 fit --report " +
                               file("w1.json") + " --model-out " + file("fitted.json")),
            0)
      << output();
  const double without = read_json(file("w0.json"))["fit_percent"], with = read_json(file("w1.json"))["fit_percent"];
  EXPECT_GT(with, 99.99) << output();
  EXPECT_LT(without, with);
  // the written model carries that x0: compared as written, it scores the same
  ASSERT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("fitted.json") + " --rows 100:200 --report " +
                               file("w2.json")),
            0)
      << output();
  EXPECT_NEAR(read_json(file("w2.json"))["fit_percent"].get<double>(), with, 1e-6);
}

TEST_F(Compare, ReportedFitIsTheFitOfTheWrittenSeries) {
  ASSERT_EQ(run("generate", "example1 --n 150 --noise-std 0.22360679774997896 --out " + file("d.csv") + " --model-out " +
                                file("i.json")),
            0)
      << output();
  ASSERT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("i.json") + " --warmup 10 --out " +
                               file("s.csv") + " --report " + file("r.json")),
            0)
      << output();
  const nlohmann::json r = read_json(file("r.json"));
  const TextTable t = read_csv(file("s.csv"));
  ASSERT_EQ(t.rows.size(), 150u);
  for (const auto& out : r["outputs"]) {
    const std::string name = out["name"];
    const size_t cy = *find_column(t, name), cm = *find_column(t, name + "_model");
    double mean = 0, e2 = 0, s2 = 0;
    const size_t first = 10;  // the warm-up rows are not scored
    for (size_t k = first; k < t.rows.size(); ++k) mean += std::stod(t.rows[k][cy]);
    mean /= static_cast<double>(t.rows.size() - first);
    for (size_t k = first; k < t.rows.size(); ++k) {
      const double y = std::stod(t.rows[k][cy]), m = std::stod(t.rows[k][cm]);
      e2 += (y - m) * (y - m);
      s2 += (y - mean) * (y - mean);
    }
    EXPECT_NEAR(out["fit_percent"].get<double>(), 100.0 * (1.0 - std::sqrt(e2 / s2)), 1e-6) << name;
    EXPECT_NEAR(out["rms"].get<double>(), std::sqrt(e2 / static_cast<double>(t.rows.size() - first)), 1e-9) << name;
  }
  // bad combinations are refused before any work
  EXPECT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("i.json") + " --x0 model --warmup 5"), 2);
  EXPECT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("i.json") + " --model-out " + file("m.json")), 2);
  EXPECT_EQ(run("compare", "--data " + file("d.csv") + " --model " + file("i.json") + " --warmup 150"), 2);
}

}  // namespace
}  // namespace lpvid
