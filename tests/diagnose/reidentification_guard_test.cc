// Theorem 3.1 again after diagnosis starts from the fitted model, which meets
// the window's own Theorem 2.1 bounds; a result far above them is reported as
// a failed stage (diagnose/window_identification.h judge_against_window).
// Known answers by construction: bounds set here.
#include <gtest/gtest.h>

#include "diagnose/window_identification.h"

namespace lpvid {
namespace {

WindowBounds verified(double delta, double dmax, Eigen::Index begin, Eigen::Index end) {
  WindowBounds w;
  w.begin = begin;
  w.end = end;
  w.bounds.outcome = CertifyOutcome::kVerified;
  w.bounds.delta = delta;
  w.bounds.dmax = dmax;
  return w;
}

WindowIdentification identified(double delta, double dmax) {
  WindowIdentification id;
  id.applicable = true;
  id.basis = {"1"};
  id.bounds = verified(delta, dmax, 0, 200);
  id.bounds.certificate = "some.thm31.json";
  return id;
}

TEST(ReidentificationGuard, FarAboveTheWindowsOwnBoundIsAFailedStage) {
  WindowIdentification id = identified(0.01, 1.1e25);
  judge_against_window(id, verified(0.012, 0.0697, 0, 200));
  EXPECT_FALSE(id.failed.empty());
  EXPECT_NE(id.failed.find("the window's bounds stand"), std::string::npos) << id.failed;
  EXPECT_FALSE(id.bounds.bounds.verified());  // no bound of this stage is stated
  EXPECT_TRUE(id.bounds.certificate.empty());
  EXPECT_EQ(id.basis, std::vector<std::string>{"1"});
  // delta alone far above
  WindowIdentification d = identified(0.5, 0.05);
  judge_against_window(d, verified(0.01, 0.0697, 0, 200));
  EXPECT_FALSE(d.failed.empty());
}

TEST(ReidentificationGuard, WithinTheFactorOrOnOtherRowsItStands) {
  const double f = kReidentificationWorseFactor;
  WindowIdentification id = identified(0.01 * f, 0.0697 * f);  // exactly at the factor: stands
  judge_against_window(id, verified(0.01, 0.0697, 0, 200));
  EXPECT_TRUE(id.failed.empty());
  EXPECT_TRUE(id.bounds.bounds.verified());
  WindowIdentification other = identified(1, 1e25);  // the window's bound is over other rows
  judge_against_window(other, verified(0.01, 0.0697, 0, 150));
  EXPECT_TRUE(other.failed.empty());
  WindowIdentification unverified_own = identified(1, 1e25);
  WindowBounds own = verified(0.01, 0.0697, 0, 200);
  own.bounds.outcome = CertifyOutcome::kUndecided;
  judge_against_window(unverified_own, own);
  EXPECT_TRUE(unverified_own.failed.empty());
}

}  // namespace
}  // namespace lpvid
