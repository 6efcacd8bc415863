// `diagnose` on the real measurements (read in place from ../shared/data;
// skipped when absent, e.g. on a machine without the benchmark files):
//  - cascaded tanks, with the benchmark's protocol: the linear model
//    and every candidate are fitted on Est rows 0:716, the order and the
//    effects are chosen on Est rows 716:1024, and Val is scored once at the
//    end; the benchmark's figure (free-run RMS on Val, x0 from the first 5 Val
//    samples) must be below the published linear reference 0.7574 V, below
//    the starting model's and below 0.45 V (the goal: the top of the
//    published nonlinear models' range);
//  - dryer (linear with a transport delay): no nonlinear effect may be added.
// The thresholds are the benchmark's published numbers, not our output.
#include <filesystem>

#include <gtest/gtest.h>

#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "diagnose/effect_ranking.h"
#include "fit/linear_fit.h"

namespace lpvid {
namespace {

const std::string kData = LPVID_SOURCE_DIR "/../shared/data/";

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

TEST(MeasuredData, CascadedTanksBeatsTheLinearReference) {
  const std::string f = kData + "cascaded-tanks/dataBenchmark.csv";
  if (!std::filesystem::exists(f)) GTEST_SKIP() << f << " not present";
  const TextTable t = read_table(f);
  const ColumnMap cols{{"uEst"}, {"yEst"}, {}};
  const Experiment<double> est_all = make_experiment<double>(t, cols);
  const Experiment<double> test = make_experiment<double>(t, ColumnMap{{"uVal"}, {"yVal"}, {}});
  const Eigen::Index cut = 716;  // estimation rows 0:716, selection rows 716:1024
  const Experiment<double> est = select_rows(est_all, 0, cut), sel = select_rows(est_all, cut, est_all.n());
  // the order and fit as `fit-linear --rows 0:716 --validation-rows 716:1024 --order auto` choose them
  const LpvModel<double> linear = choose_order(est, sel, cols, 5, true, 5).fit.model;
  const LpvModel<double> declared = with_input_scheduling(linear);
  RankingOptions o;
  o.candidates.max_degree = 3;
  const RankingResult r = rank_effects(declared, with_input_scheduling(est, linear, declared),
                                       with_input_scheduling(sel, linear, declared), o);
  // The test role, once.
  const Experiment<double> test_s = with_input_scheduling(test, linear, declared);
  const double before = validation_rms(r.before, test_s, 5), after = validation_rms(r.after, test_s, 5);
  ASSERT_FALSE(r.chosen.empty());
  EXPECT_LT(after, 0.7574);
  EXPECT_LT(after, before);
  EXPECT_LT(after, 0.45);  // the goal: inside the published nonlinear models' range (0.34-0.45 V)
  RecordProperty("tanks_test_rms_before", std::to_string(before));
  RecordProperty("tanks_test_rms_after", std::to_string(after));
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
