// Normal and chi-square quantiles (diagnose/quantiles.h) against printed
// table values (e.g. Abramowitz & Stegun, Table 26.8; any χ² table) and
// against their own distribution functions.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <stdexcept>

#include "diagnose/quantiles.h"

namespace lpvid {
namespace {

TEST(Quantiles, NormalTableValues) {
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-14);
  EXPECT_NEAR(normal_quantile(0.975), 1.959964, 1e-6);
  EXPECT_NEAR(normal_quantile(0.995), 2.575829, 1e-6);
  EXPECT_NEAR(normal_quantile(0.025), -1.959964, 1e-6);
  EXPECT_NEAR(normal_cdf(1.0), 0.841345, 1e-6);
}

TEST(Quantiles, ChiSquareTableValues) {
  struct Row {
    double p, dof, value;
  };
  const Row table[] = {{0.99, 10, 23.209}, {0.95, 25, 37.652}, {0.95, 1, 3.841},  {0.99, 1, 6.635},
                       {0.99, 25, 44.314}, {0.05, 10, 3.940},  {0.95, 2, 5.991},  {0.999, 5, 20.515},
                       {0.5, 3, 2.366},    {0.99, 100, 135.807}};
  for (const Row& r : table) {
    EXPECT_NEAR(chi_square_quantile(r.p, r.dof), r.value, 6e-4) << "p " << r.p << " dof " << r.dof;
    EXPECT_NEAR(chi_square_cdf(r.value, r.dof), r.p, 2e-4) << "p " << r.p << " dof " << r.dof;
  }
}

TEST(Quantiles, WilsonHilfertyIsCloseForModerateDof) {
  EXPECT_NEAR(chi_square_quantile_wilson_hilferty(0.99, 10), 23.209, 23.209 * 2e-3);
  EXPECT_NEAR(chi_square_quantile_wilson_hilferty(0.95, 25), 37.652, 37.652 * 1e-3);
}

RC_GTEST_PROP(Quantiles, ChiSquareQuantileInvertsTheCdf, ()) {
  const double p = *rc::gen::inRange(1, 999) / 1000.0;
  const int dof = *rc::gen::inRange(1, 300);
  const double x = chi_square_quantile(p, dof);
  RC_ASSERT(std::abs(chi_square_cdf(x, dof) - p) < 1e-9);
  // and Wilson–Hilferty is within 2 % of it away from the far tails
  if (dof >= 5 && p >= 0.05 && p <= 0.995)
    RC_ASSERT(std::abs(chi_square_quantile_wilson_hilferty(p, dof) - x) <= 0.02 * x);
}

TEST(Quantiles, BadArgumentsThrow) {
  EXPECT_THROW(normal_quantile(0.0), std::invalid_argument);
  EXPECT_THROW(normal_quantile(1.0), std::invalid_argument);
  EXPECT_THROW(normal_quantile(std::nan("")), std::invalid_argument);
  EXPECT_THROW(chi_square_quantile(0.5, 0), std::invalid_argument);
  EXPECT_THROW(chi_square_quantile(1.5, 3), std::invalid_argument);
  EXPECT_THROW(chi_square_cdf(1.0, -2), std::invalid_argument);
}

}  // namespace
}  // namespace lpvid
