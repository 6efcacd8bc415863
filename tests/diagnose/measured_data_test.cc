// `diagnose` on the real measurements, read in place from $LPVID_DATA or
// ../shared/data beside the repository; each test skips itself, saying so,
// when its file is absent (e.g. in CI, which has no measured data):
//  - cascaded tanks: the README's figure, by the README's commands (below);
//  - dryer (linear with a transport delay): no nonlinear effect may be added.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "diagnose/effect_ranking.h"
#include "fit/linear_fit.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

/// The folder holding cascaded-tanks/ and dryer/ (with a trailing slash).
std::string data_dir() {
  const char* env = std::getenv("LPVID_DATA");
  const std::string d = env && *env ? env : LPVID_SOURCE_DIR "/../shared/data";
  return d + "/";
}

struct Split {
  Experiment<double> est, val;
  ColumnMap cols;
};

RankingResult diagnose(const Split& s, int degree) {
  // the order and fit as `fit-linear --order auto --validation-…` chooses them (scored on the selection rows)
  const LpvModel<double> linear = choose_order(s.est, s.val, s.cols, 5, true, 5).fit.model;
  const LpvModel<double> declared = with_input_scheduling(linear);
  RankingOptions o;
  o.candidates.max_degree = degree;
  return rank_effects(declared, with_input_scheduling(s.est, linear, declared),
                      with_input_scheduling(s.val, linear, declared), o);
}

// The README's tanks figure, as `scripts/demo.sh` computes it: the built
// `lpvid` runs the demo's two commands (fit-linear on uEst/yEst rows 0:716,
// order chosen on 716:1024, offset; diagnose with 4 blocked folds of rows
// 0:1024, warm-up 50, degree 3, uVal/yVal scored once). One difference:
// --max-windows 1 certifies one bound window instead of five; the windows
// come after the ranking and the test score, which do not depend on them.
// Long (about 5 minutes on 2 idle cores, the ranking's 3 rounds of 165 fits):
// hence "Long" in its name (ctest -E Long leaves it out).
//
// Pinned: the outcome of this commit's method, to its printed digits (test
// RMS to 1e-4 V, fit to 0.01 %, every effect's label). It is one answer on
// every x86-64 machine and for the data moved by one ulp (docs/determinism.md;
// ctest LastBit runs the perturbations, CpuVariants the CPU variants); a
// change of lpvid's arithmetic can still move it (the fits are not convex),
// and then the README, docs/benchmarks.md and this figure move together.
struct TanksOutcome {
  double rms, fit;
  std::vector<std::string> effects;
};
const TanksOutcome kTanksOutcome{
    0.2922, 86.22,
    {"store cascade: two stores x1 -> x2 (A = I), outflow e*sqrt(max(x_i - c_i, 0)) and overflow "
     "e*max(x_i - o_i, 0) from each, levels fitted; replaces the linear part (27 starts)",
     "output_polynomial degree 3"}};

struct MeasuredDataCli : gen::CliRunner {};

TEST_F(MeasuredDataCli, LongTanksDemoFigureAsTheReadme) {
  const std::string f = data_dir() + "cascaded-tanks/dataBenchmark.csv";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " not present (set LPVID_DATA to the folder holding cascaded-tanks/)";
  gen::CliRunner& run = *this;
  const std::string linear = run.file("tanks_linear.json"), report = run.file("tanks.report.json");
  ASSERT_EQ(run.run("fit-linear", "--data " + f + " --u uEst --y yEst --rows 0:716 --order auto --offset "
                                   "--validation-rows 716:1024 --sample-time 4 --unit uEst=V --unit yEst=V --model-out " + linear),
            0)
      << run.output();
  const int code = run.run("diagnose", "--data " + f + " --model " + linear +
                                           " --benchmark cascaded-tanks --test-columns uVal,yVal --degree 3"
                                           " --max-windows 1 --report " + report);
  ASSERT_TRUE(code == 0 || code == 4) << run.output();  // 4: a bound not verified; the figures stand
  const nlohmann::json r = gen::CliRunner::read_json(report);
  const nlohmann::json& t = r.at("test");
  EXPECT_NEAR(t.at("rms_before").get<double>(), 0.6936, 1e-4);
  EXPECT_NEAR(t.at("fit_percent_before").get<double>(), 67.3, 0.1);
  std::vector<std::string> effects;
  for (const auto& e : r.at("effects")) effects.push_back(e.at("label").get<std::string>());
  EXPECT_EQ(effects, kTanksOutcome.effects);
  EXPECT_NEAR(t.at("rms_after").get<double>(), kTanksOutcome.rms, 1e-4);
  EXPECT_NEAR(t.at("fit_percent_after").get<double>(), kTanksOutcome.fit, 0.01);
  // the published best linear approximation, an outside reference
  EXPECT_LT(t.at("rms_after").get<double>(), 0.7574);
}

TEST(MeasuredData, DryerGetsNoInventedEffect) {
  const std::string f = data_dir() + "dryer/dryer.dat";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " not present (set LPVID_DATA)";
  const TextTable t = read_table(f, std::vector<std::string>{"u", "y"});
  Split s;
  s.cols = {{"u"}, {"y"}, {}};
  const Experiment<double> all = make_experiment<double>(t, s.cols);
  s.est = select_rows(all, 0, 500);
  s.val = select_rows(all, 500, 1000);
  const RankingResult r = diagnose(s, 2);
  // The dryer is linear with a transport delay: Ljung's models of these data
  // use an input delay of 3 samples (System Identification Toolbox, "dryer2",
  // arx with nk = 3). With the dynamics re-fitted jointly an
  // input delay of at most 3 samples is a linear effect that may be found;
  // any nonlinear effect is invented.
  for (const ScoredCandidate& c : r.chosen) {
    EXPECT_EQ(c.kind, "input_delay") << "chose " << c.label;
    if (c.kind == "input_delay") {
      EXPECT_LE(c.model.statics.input_delay, 3) << c.label;
    }
  }
  RecordProperty("dryer_effects", static_cast<int>(r.chosen.size()));
}

}  // namespace
}  // namespace lpvid
