// Signal ranges of a test record against the estimation record
// (diagnose/signal_ranges.h). Known answers by construction: counts, shares
// and the farthest excursion of hand-made records.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "diagnose/signal_ranges.h"

namespace lpvid {
namespace {

Experiment<double> record(const std::vector<double>& u, const std::vector<double>& y) {
  Experiment<double> e;
  const auto n = static_cast<Eigen::Index>(u.size());
  e.u = Mat<double>(n, 1);
  e.y = Mat<double>(n, 1);
  e.rho = Mat<double>(n, 0);
  for (Eigen::Index i = 0; i < n; ++i) {
    e.u(i, 0) = u[static_cast<size_t>(i)];
    e.y(i, 0) = y[static_cast<size_t>(i)];
  }
  return e;
}

TEST(SignalRanges, CountsTheSamplesOutsideAndTheFarthestExcursion) {
  // estimation: u in [0, 4], y in [2, 3]
  const Experiment<double> est = record({0, 1, 4, 2}, {2, 3, 2.5, 2.2});
  // test: u inside ([0.5, 4] with the edge 4 itself inside); y below 2 twice
  // (1.5 and 1.0) and above 3 once (3.25)
  const Experiment<double> test = record({0.5, 4, 1, 2, 3}, {1.5, 2.5, 1.0, 3.25, 2});
  const std::vector<SignalExcursion> ex = signal_excursions(est, test);
  ASSERT_EQ(ex.size(), 2u);
  EXPECT_EQ(ex[0].role, SignalRole::kInput);
  EXPECT_EQ(ex[0].outside(), 0);
  EXPECT_EQ(ex[0].beyond(), 0.0);
  EXPECT_EQ(ex[0].estimation_lo, 0.0);
  EXPECT_EQ(ex[0].estimation_hi, 4.0);
  EXPECT_EQ(ex[0].test_lo, 0.5);
  EXPECT_EQ(ex[1].role, SignalRole::kOutput);
  EXPECT_EQ(ex[1].below, 2);
  EXPECT_EQ(ex[1].above, 1);
  EXPECT_EQ(ex[1].samples, 5);
  EXPECT_DOUBLE_EQ(ex[1].outside_share(), 3.0 / 5.0);
  // farthest: 1.0 is 1.0 below 2 (3.25 is 0.25 above 3); width 1
  EXPECT_DOUBLE_EQ(ex[1].beyond(), 1.0);
}

TEST(SignalRanges, AConstantEstimationSignalMeasuresTheDistanceItselfAndNaNIsNotCounted) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Experiment<double> est = record({1, 1, 1}, {0, 1, 2});
  const Experiment<double> test = record({1, 3.5, nan}, {0.5, nan, 1});
  const std::vector<SignalExcursion> ex = signal_excursions(est, test);
  EXPECT_EQ(ex[0].samples, 2);
  EXPECT_EQ(ex[0].above, 1);
  EXPECT_DOUBLE_EQ(ex[0].beyond(), 2.5);
  EXPECT_EQ(ex[1].samples, 2);
  EXPECT_EQ(ex[1].outside(), 0);
}

TEST(SignalRanges, RefusesRecordsOfOtherColumns) {
  Experiment<double> est = record({0, 1}, {0, 1});
  Experiment<double> test = record({0, 1}, {0, 1});
  test.y = Mat<double>::Zero(2, 2);
  EXPECT_THROW(signal_excursions(est, test), std::invalid_argument);
}

}  // namespace
}  // namespace lpvid
