// Blocked folds and their acceptance rule (diagnose/fold_plan.h), the
// held-out block of the output-error fit (FitOptions::skip_first/skip_last)
// and the benchmark score with a warm-up (warmup_score).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "diagnose/fold_plan.h"
#include "examples/random_stream.h"
#include "fit/output_error_fit.h"
#include "fit/observer_form.h"

namespace lpvid {
namespace {

RC_GTEST_PROP(FoldPlan, BlocksTileTheRecordInOrder, ()) {
  const int k = *rc::gen::inRange(2, 9);
  const auto warmup = static_cast<Eigen::Index>(*rc::gen::inRange(1, 20));
  const Eigen::Index n = k * (2 * warmup + 1) + *rc::gen::inRange(0, 500);
  const std::vector<FoldBlock> b = blocked_folds(n, k, warmup);
  RC_ASSERT(b.size() == static_cast<size_t>(k));
  RC_ASSERT(b.front().first == 0);
  RC_ASSERT(b.back().last == n);
  Eigen::Index smallest = n, largest = 0;
  for (size_t j = 0; j < b.size(); ++j) {
    if (j > 0) RC_ASSERT(b[j].first == b[j - 1].last);
    smallest = std::min(smallest, b[j].last - b[j].first);
    largest = std::max(largest, b[j].last - b[j].first);
  }
  RC_ASSERT(largest - smallest <= 1);
  RC_ASSERT(smallest > 2 * warmup);
}

TEST(FoldPlan, RefusesFoldsTooShortForTheWarmup) {
  EXPECT_THROW(blocked_folds(100, 4, 13), InputError);  // blocks of 25 <= 2*13
  EXPECT_NO_THROW(blocked_folds(100, 4, 12));
  EXPECT_THROW(blocked_folds(100, 1, 5), InputError);
}

FoldFigures figures(std::vector<double> rms, Eigen::Index count = 100) {
  FoldFigures f;
  for (double r : rms) {
    f.sse.push_back(r * r * static_cast<double>(count));
    f.count.push_back(count);
  }
  return f;
}

TEST(FoldPlan, AcceptanceNeedsAClearMajorityAndTheTotalGain) {
  const FoldFigures ref = figures({1, 1, 1, 1});
  // 3 of 4 folds and 20 % on the total: accepted
  EXPECT_TRUE(accepts(figures({0.7, 0.7, 0.7, 1.1}), ref, 0.05));
  // a big win on 2 folds only (the total is far better): refused, 2 of 4 is no majority
  EXPECT_EQ(folds_won(figures({0.1, 0.1, 1.01, 1.01}), ref), 2);
  EXPECT_FALSE(accepts(figures({0.1, 0.1, 1.01, 1.01}), ref, 0.05));
  // every fold a little better but less than 5 % on the total: refused
  EXPECT_FALSE(accepts(figures({0.97, 0.97, 0.97, 0.97}), ref, 0.05));
  EXPECT_TRUE(accepts(figures({0.97, 0.97, 0.97, 0.97}), ref, 0.0));
  // a fold whose free run diverged never helps
  FoldFigures inf = figures({0.5, 0.5, 0.5, 0.5});
  inf.sse[3] = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(accepts(inf, ref, 0.05));
  // 3 of 5 is a majority, so is 2 of 3; 2 of 4 is not
  EXPECT_TRUE(accepts(figures({0.5, 0.5, 0.5, 1.1, 1.1}), figures({1, 1, 1, 1, 1}), 0.05));
  EXPECT_TRUE(accepts(figures({0.5, 0.5, 1.1}), figures({1, 1, 1}), 0.05));
}

TEST(FoldPlan, TotalIsThePooledRms) {
  const FoldFigures f = figures({1, 2}, 10);
  EXPECT_NEAR(f.total_rms(), std::sqrt((10.0 * 1 + 10.0 * 4) / 20.0), 1e-15);
  EXPECT_NEAR(f.rms(1), 2.0, 1e-15);
}

/// A first-order system y = x, x+ = 0.8 x + 0.5 u, and its data.
struct FirstOrder {
  LpvModel<double> model;
  Experiment<double> exp;
};

FirstOrder first_order(int n) {
  ObserverForm f = zero_observer_form(1, 1, false);
  f.a(0) = -0.8;
  f.B(0, 0) = 0.5;
  FirstOrder s;
  s.model = to_lpv_model(f, ColumnMap{{"u1"}, {"y1"}, {}});
  RandomStream rs(3);
  s.exp.u = Mat<double>(n, 1);
  for (int k = 0; k < n; ++k) s.exp.u(k, 0) = rs.normal();
  s.exp.rho = Mat<double>(n, 0);
  s.exp.y = Mat<double>(n, 1);
  double x = 0;
  for (int k = 0; k < n; ++k) {
    s.exp.y(k, 0) = x + 0.01 * rs.normal();
    x = 0.8 * x + 0.5 * s.exp.u(k, 0);
  }
  return s;
}

TEST(FoldPlan, TheHeldOutBlockDoesNotReachTheFit) {
  // Corrupting y on the held-out block must not change the fitted parameters
  // at all; corrupting a row outside it must.
  const FirstOrder s = first_order(200);
  LpvModel<double> start = s.model;
  start.B.terms[0].value(0, 0) = 0.2;  // fit B from a wrong start
  const std::vector<ParameterSlot> slots = dynamics_slots(start);
  FitOptions o;
  o.skip_first = 50;
  o.skip_last = 100;
  Experiment<double> bad = s.exp;
  for (int k = 50; k < 100; ++k) bad.y(k, 0) += 100.0 * std::sin(k);
  const Vec<double> clean = slot_values(fit_slots(start, slots, s.exp, o).model, slots);
  const Vec<double> dirty = slot_values(fit_slots(start, slots, bad, o).model, slots);
  EXPECT_EQ(clean, dirty);
  EXPECT_NEAR(clean(1), 0.5, 0.01);  // B is recovered (slot order: A column, then B)
  Experiment<double> outside = s.exp;
  outside.y(120, 0) += 5.0;
  EXPECT_NE(slot_values(fit_slots(start, slots, outside, o).model, slots), clean);
}

TEST(FoldPlan, WarmupScoreLeavesTheWarmupOutAndGivesTheFitPercent) {
  const FirstOrder s = first_order(300);
  // the true model from any x0: after a warm-up of 20 the error is only the noise (std 0.01)
  const FreeRunScore sc = warmup_score(s.model, s.exp, 20);
  EXPECT_EQ(sc.warmup, 20);
  EXPECT_EQ(sc.scored, 280);
  EXPECT_NEAR(sc.rms, 0.01, 0.002);
  // fit % by its definition, computed here from the same rows
  const Mat<double> y = s.exp.y.bottomRows(280);
  const double spread = (y.array() - y.mean()).matrix().norm();
  EXPECT_NEAR(sc.fit_percent, 100.0 * (1.0 - sc.rms * std::sqrt(280.0) / spread), 1e-9);
  // a scored sample's error counts: one spike of 10 after the warm-up
  Experiment<double> spike = s.exp;
  spike.y(150, 0) += 10;
  EXPECT_NEAR(warmup_score(s.model, spike, 20).rms, std::sqrt(sc.rms * sc.rms + 100.0 / 280.0), 0.01);
  EXPECT_THROW(warmup_score(s.model, s.exp, 300), std::invalid_argument);
}

}  // namespace
}  // namespace lpvid

namespace lpvid {
namespace {

TEST(HoldoutCut, TheLastShareSelectsAndBothSidesKeepTenSamples) {
  EXPECT_EQ(holdout_cut(100, 0.3), 70);   // floor(100 · (1 − 0.3)) in double is 70
  EXPECT_EQ(holdout_cut(25, 0.5), 12);    // floor(12.5): 12 fit, 13 select
  EXPECT_EQ(holdout_cut(20, 0.5), 10);    // exactly ten on each side
  EXPECT_THROW(holdout_cut(19, 0.5), InputError);   // 9 fit
  EXPECT_THROW(holdout_cut(100, 0.05), InputError);  // 5 select
  EXPECT_THROW(holdout_cut(100, 1.0), InputError);
  EXPECT_THROW(holdout_cut(100, 0.0), InputError);
}

}  // namespace
}  // namespace lpvid
