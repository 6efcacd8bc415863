// choose_start_by_folds (diagnose/effect_ranking.h): the start of a grid
// family is chosen by estimation MSE + the folds' held-out MSE, not by the
// whole-record training error alone. Known answers are the arithmetic of
// rms_s² + Σ_t SSE_t,s / Σ_t count_t over hand-made figures.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "diagnose/effect_ranking.h"

namespace lpvid {
namespace {

FitResult fit_with_rms(double rms, bool finite = true) {
  FitResult f;
  f.rms = rms;
  f.finite = finite;
  return f;
}

TEST(StartChoice, TheLowestTotalHeldOutErrorWinsOverTheLowestTrainingError) {
  // 2 folds, 3 starts; start 0 fits the whole record best but fails fold 1
  const std::vector<std::vector<double>> sse{{90.0, 4.0, 5.0}, {1.0, 6.0, 3.0}};
  const std::vector<Eigen::Index> count{10, 10};
  const std::vector<FitResult> whole{fit_with_rms(0.10), fit_with_rms(0.20), fit_with_rms(0.30)};
  const StartChoice c = choose_start_by_folds(sse, count, whole);
  // held-out MSE 91/20, 10/20, 8/20; + estimation MSE 0.01, 0.04, 0.09
  EXPECT_EQ(c.starts, 3u);
  EXPECT_EQ(c.chosen, 2);
  EXPECT_DOUBLE_EQ(c.held_out, std::sqrt(8.0 / 20.0));
  EXPECT_DOUBLE_EQ(c.score, 0.09 + 8.0 / 20.0);
  EXPECT_EQ(c.lowest_estimation, 0);
  EXPECT_DOUBLE_EQ(c.held_out_of_lowest_estimation, std::sqrt(91.0 / 20.0));
}

TEST(StartChoice, TheLowestHeldOutErrorLosesWhenItsWholeRecordFitIsPoor) {
  // the fold fits of start 0 generalise best, but its whole-record fit
  // landed in a poor basin: 1.0 + 0.1 against 0.01 + 0.2
  const std::vector<std::vector<double>> sse{{1.0, 2.0}, {1.0, 2.0}};
  const StartChoice c = choose_start_by_folds(sse, {10, 10}, {fit_with_rms(1.0), fit_with_rms(0.1)});
  EXPECT_EQ(c.chosen, 1);
  EXPECT_DOUBLE_EQ(c.score, 0.01 + 0.2);
}

TEST(StartChoice, AStartWhoseWholeRecordFitDivergedIsNeverChosen) {
  const std::vector<std::vector<double>> sse{{1.0, 5.0}, {1.0, 5.0}};
  const std::vector<Eigen::Index> count{4, 6};
  const std::vector<FitResult> whole{fit_with_rms(std::numeric_limits<double>::infinity(), false), fit_with_rms(0.5)};
  const StartChoice c = choose_start_by_folds(sse, count, whole);
  EXPECT_EQ(c.chosen, 1);
  EXPECT_DOUBLE_EQ(c.held_out, std::sqrt(10.0 / 10.0));
  EXPECT_EQ(c.lowest_estimation, 1);
}

TEST(StartChoice, AFoldWithoutFiniteHeldOutErrorRulesTheStartOut) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::vector<double>> sse{{0.1, 2.0}, {inf, 2.0}};
  const std::vector<Eigen::Index> count{5, 5};
  const StartChoice c = choose_start_by_folds(sse, count, {fit_with_rms(0.1), fit_with_rms(0.2)});
  EXPECT_EQ(c.chosen, 1);
  EXPECT_FALSE(std::isfinite(c.held_out_of_lowest_estimation));
}

TEST(StartChoice, GridsOfDifferentSizesMakeNoChoice) {
  const std::vector<std::vector<double>> sse{{1.0, 2.0}, {1.0}};
  const StartChoice c = choose_start_by_folds(sse, {5, 5}, {fit_with_rms(0.1), fit_with_rms(0.2)});
  EXPECT_EQ(c.chosen, -1);
}

TEST(StartChoice, NoStartHasAFiniteTotalMakesNoChoice) {
  const double inf = std::numeric_limits<double>::infinity();
  const StartChoice c = choose_start_by_folds({{inf, inf}}, {5}, {fit_with_rms(0.1), fit_with_rms(0.2)});
  EXPECT_EQ(c.chosen, -1);
  EXPECT_EQ(c.lowest_estimation, 0);
}

}  // namespace
}  // namespace lpvid
