// Issue 4 item 7 on the real measurements (read in place from ../shared/data;
// skipped when absent, e.g. on a machine without the benchmark files):
//  - cascaded tanks: from a linear model fitted on Est, diagnose must lower
//    the benchmark's figure (free-run RMS on Val, x0 from the first 5 Val
//    samples) below the published linear reference 0.7574 V;
//  - dryer (nearly linear): no effect may be added.
// The thresholds are the benchmark's published numbers, not our output.
#include <filesystem>

#include <gtest/gtest.h>

#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "diagnose/effect_ranking.h"
#include "diagnose/linear_fit.h"

namespace lpvid {
namespace {

const std::string kData = LPVID_SOURCE_DIR "/../shared/data/";

struct Split {
  Experiment<double> est, val;
  ColumnMap cols;
};

RankingResult diagnose(const Split& s, int degree) {
  LinearFitOptions lo;
  lo.offset = true;
  // the order as `fit-linear --order auto` chooses it (held-out last third of Est)
  const Eigen::Index cut = s.est.n() * 2 / 3;
  lo.order = choose_order(select_rows(s.est, 0, cut), select_rows(s.est, cut, s.est.n()), s.cols, 5, true, 5).order;
  const LpvModel<double> linear = fit_linear(s.est, s.cols, lo).model;
  const LpvModel<double> declared = with_input_scheduling(linear);
  RankingOptions o;
  o.candidates.max_degree = degree;
  return rank_effects(declared, with_input_scheduling(s.est, linear, declared),
                      with_input_scheduling(s.val, linear, declared), o);
}

TEST(MeasuredData, CascadedTanksBeatsTheLinearReference) {
  const std::string f = kData + "cascaded-tanks/dataBenchmark.csv";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " not present";
  const TextTable t = read_table(f);
  Split s;
  s.cols = {{"uEst"}, {"yEst"}, {}};
  s.est = make_experiment<double>(t, s.cols);
  s.val = make_experiment<double>(t, ColumnMap{{"uVal"}, {"yVal"}, {}});
  const RankingResult r = diagnose(s, 3);
  ASSERT_FALSE(r.chosen.empty());
  EXPECT_LT(r.after_validation, 0.7574);
  EXPECT_LT(r.after_validation, r.before_validation);
  RecordProperty("tanks_before_validation_rms", std::to_string(r.before_validation));
  RecordProperty("tanks_after_validation_rms", std::to_string(r.after_validation));
}

TEST(MeasuredData, DryerGetsNoInventedEffect) {
  const std::string f = kData + "dryer/dryer.dat";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " not present";
  const TextTable t = read_table(f, std::vector<std::string>{"u", "y"});
  Split s;
  s.cols = {{"u"}, {"y"}, {}};
  const Experiment<double> all = make_experiment<double>(t, s.cols);
  s.est = select_rows(all, 0, 500);
  s.val = select_rows(all, 500, 1000);
  const RankingResult r = diagnose(s, 2);
  EXPECT_TRUE(r.chosen.empty()) << "chose " << (r.chosen.empty() ? "" : r.chosen.front().label);
}

}  // namespace
}  // namespace lpvid
