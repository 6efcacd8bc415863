// Physics first (diagnose/physical_alternative.h): a physical candidate whose
// per-fold held-out RMS is not worse than a black-box choice's by more than
// one standard error of the fold-to-fold differences is indistinguishable on
// these data; it is taken when it passes the acceptance rule. Known answers
// by construction: fold figures set here (SSE = RMS² with one entry a fold).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "diagnose/physical_alternative.h"

namespace lpvid {
namespace {

RankedFigures candidate(const std::string& kind, const std::vector<double>& fold_rms) {
  RankedFigures c;
  c.kind = kind;
  for (double r : fold_rms) {
    c.folds.sse.push_back(r * r);
    c.folds.count.push_back(1);
  }
  return c;
}

TEST(PhysicalAlternative, KindsOfAMechanismArePhysical) {
  for (const char* k : {"input_delay", "input_saturation", "output_saturation", "dead_zone", "abs_value",
                        "state_nonlinearity", "output_offset"})
    EXPECT_TRUE(is_physical_kind(k)) << k;
  for (const char* k : {"input_polynomial", "output_polynomial", "output_piecewise_linear", "basis_term"})
    EXPECT_FALSE(is_physical_kind(k)) << k;
}

TEST(PhysicalAlternative, WithinTheSpreadAndAcceptedThePhysicalFormIsTaken) {
  // differences 0.02, -0.01, 0.03, -0.02: mean 0.005, s = 0.02380, s/2 = 0.01190
  const std::vector<RankedFigures> ranked = {candidate("output_polynomial", {0.30, 0.40, 0.50, 0.60}),
                                               candidate("abs_value", {0.32, 0.39, 0.53, 0.58})};
  const auto a = physical_alternative(ranked, {0, 1}, 0);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->black_box, 0);
  EXPECT_EQ(a->physical, 1);
  ASSERT_EQ(a->differences.size(), 4u);
  EXPECT_NEAR(a->differences[2], 0.03, 1e-12);
  EXPECT_NEAR(a->mean, 0.005, 1e-12);
  const double s = std::sqrt((0.015 * 0.015 + 0.015 * 0.015 + 0.025 * 0.025 + 0.025 * 0.025) / 3);
  EXPECT_NEAR(a->standard_error, s / 2, 1e-12);
  EXPECT_TRUE(a->taken);
  // not accepted by the rule: reported, not taken
  const auto b = physical_alternative(ranked, {0}, 0);
  ASSERT_TRUE(b.has_value());
  EXPECT_FALSE(b->taken);
}

TEST(PhysicalAlternative, AClearDifferenceOrAPhysicalChoiceLeavesItAlone) {
  // worse on every fold by 0.05 +- 0.01: mean 0.05 > its standard error
  const std::vector<RankedFigures> clear = {candidate("basis_term", {0.30, 0.40, 0.50, 0.60}),
                                              candidate("dead_zone", {0.34, 0.46, 0.55, 0.65})};
  EXPECT_FALSE(physical_alternative(clear, {0, 1}, 0).has_value());
  // the choice is physical already
  const std::vector<RankedFigures> physical = {candidate("abs_value", {0.30, 0.40}),
                                                 candidate("output_polynomial", {0.30, 0.40})};
  EXPECT_FALSE(physical_alternative(physical, {0, 1}, 0).has_value());
  // no choice, or one fold (no spread)
  EXPECT_FALSE(physical_alternative(clear, {}, -1).has_value());
  const std::vector<RankedFigures> one = {candidate("basis_term", {0.3}), candidate("abs_value", {0.3})};
  EXPECT_FALSE(physical_alternative(one, {0, 1}, 0).has_value());
}

TEST(PhysicalAlternative, OnlyTheBestRankedPhysicalCandidateIsCompared) {
  // rank 2 (physical) is clearly worse; rank 3 (physical) would be within the spread but ranks below it
  const std::vector<RankedFigures> ranked = {candidate("output_piecewise_linear", {0.30, 0.40, 0.50, 0.60}),
                                               candidate("input_saturation", {0.40, 0.50, 0.60, 0.70}),
                                               candidate("abs_value", {0.30, 0.40, 0.50, 0.60})};
  EXPECT_FALSE(physical_alternative(ranked, {0, 1, 2}, 0).has_value());
}

}  // namespace
}  // namespace lpvid
