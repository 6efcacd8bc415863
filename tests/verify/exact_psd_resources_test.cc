/// Bounded resources of the exact PSD decision: the multi-modular
/// path falls back to Bareiss instead of giving up when it runs out of primes,
/// and the leading-block screen decides easy NOT_PSD matrices early.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/number_text.h"
#include "support/input_error_text.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/psd_internal.h"

namespace lpvid {
namespace {

using psd_detail::ExactPsdLimits;

/// v vᵀ + sign·10^-exponent·I with v_i = (i mod 17) + 1 (bench/psd_rank1_matrix.py).
Mat<Rational> rank_one_shift(int n, int sign, int exponent) {
  const Rational shift = Rational(sign) * rational_from_text("1e-" + std::to_string(exponent));
  Mat<Rational> M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = Rational((i % 17 + 1) * (j % 17 + 1));
  for (int i = 0; i < n; ++i) M(i, i) += shift;
  return M;
}

Mat<Rational> diagonal(const std::vector<std::string>& d) {
  const auto n = static_cast<Eigen::Index>(d.size());
  Mat<Rational> M = Mat<Rational>::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) M(i, i) = rational_from_text(d[static_cast<std::size_t>(i)]);
  return M;
}

using gen::contains;

TEST(ExactPsdResources, OutOfPrimesReportsUndecided) {
  const Mat<Rational> M = rank_one_shift(6, 1, 20);
  const psd_detail::ModularOutcome none = psd_detail::decide_psd_modular(M, 1, 0);
  EXPECT_FALSE(none.decided);
  EXPECT_TRUE(contains(none.why, "out of 31-bit primes")) << none.why;
  // One prime short of Hadamard's bound (20-digit entries: several primes).
  const psd_detail::ModularOutcome enough = psd_detail::decide_psd_modular(M, 1);
  ASSERT_TRUE(enough.decided) << enough.why;
  EXPECT_EQ(enough.result.verdict, PsdVerdict::kPositiveDefinite);
  const std::size_t used = std::stoul(enough.result.reason.substr(enough.result.reason.find("multi-modular: ") + 15));
  ASSERT_GE(used, 2u);
  EXPECT_FALSE(psd_detail::decide_psd_modular(M, 1, used - 1).decided);
  EXPECT_TRUE(psd_detail::decide_psd_modular(M, 1, used).decided);
}

TEST(ExactPsdResources, OutOfPrimesFallsBackToBareiss) {
  ExactPsdLimits no_primes;
  no_primes.max_primes = 0;
  no_primes.screen_divisor = 0;
  const std::vector<Mat<Rational>> cases = {
      rank_one_shift(7, 1, 30),                    // PD
      rank_one_shift(7, 0, 0),                     // PSD of rank 1
      rank_one_shift(7, -1, 30),                   // NOT_PSD (negative pivot)
      diagonal({"1", "0", "0", "2"}),              // PSD of rank 2
      [] {                                         // NOT_PSD (zero pivot, nonzero row)
        Mat<Rational> Z = diagonal({"3", "0", "0"});
        Z(1, 2) = Z(2, 1) = Rational(-2, 7);
        return Z;
      }(),
  };
  for (const Mat<Rational>& M : cases) {
    const PsdResult ref = decide_psd_rational_ldlt(M);
    const PsdResult r = psd_detail::decide_psd_exact_limited(M, 1, no_primes);
    EXPECT_EQ(r.verdict, ref.verdict) << r.reason;
    EXPECT_EQ(r.rank, ref.rank) << r.reason;
    EXPECT_EQ(r.pivot_index, ref.pivot_index) << r.reason;  // Bareiss follows the reference's pivot rule
    EXPECT_EQ(r.step, ref.step) << r.reason;
    EXPECT_TRUE(contains(r.reason, "out of 31-bit primes")) << r.reason;
    EXPECT_TRUE(contains(r.reason, "Bareiss")) << r.reason;
    if (r.verdict == PsdVerdict::kNotPsd) {
      EXPECT_LT(quadratic_form(M, r.witness), Rational(0));
    }
    // With the real supply the multi-modular path decides it alone.
    const PsdResult full = decide_psd_exact(M, 1);
    EXPECT_EQ(full.verdict, ref.verdict);
    EXPECT_FALSE(contains(full.reason, "Bareiss")) << full.reason;
  }
}

TEST(ExactPsdResources, LeadingBlockScreenDecidesRankOneMinusTinyIdentity) {
  // The floating filter sees the rank-one v vᵀ; the leading 2×2 block has
  // determinant −ε(v₀² + v₁²) + ε² < 0 (ε = 10⁻⁵⁰).
  const Mat<Rational> M = rank_one_shift(60, -1, 50);
  const PsdResult ref = decide_psd_rational_ldlt(M);
  ASSERT_EQ(ref.verdict, PsdVerdict::kNotPsd);
  const PsdResult r = decide_psd_exact(M);
  EXPECT_EQ(r.verdict, ref.verdict);
  EXPECT_TRUE(contains(r.reason, "leading 2x2 principal submatrix")) << r.reason;
  ASSERT_EQ(r.witness.size(), 60);
  EXPECT_LT(quadratic_form(M, r.witness), Rational(0));
  for (Eigen::Index i = 2; i < 60; ++i) EXPECT_EQ(r.witness(i), Rational(0)) << i;
  EXPECT_EQ(r.pivot_index, 1);
  EXPECT_EQ(r.step, 1);
  // Through the filter, and with the screen off (the full path agrees).
  const PsdResult f = decide_psd(M);
  EXPECT_EQ(f.verdict, PsdVerdict::kNotPsd) << f.reason;
  EXPECT_LT(quadratic_form(M, f.witness), Rational(0));
  ExactPsdLimits off;
  off.screen_divisor = 0;
  const PsdResult all = psd_detail::decide_psd_exact_limited(M, 0, off);
  EXPECT_EQ(all.verdict, PsdVerdict::kNotPsd);
  EXPECT_FALSE(contains(all.reason, "leading")) << all.reason;
  EXPECT_LT(quadratic_form(M, all.witness), Rational(0));
}

TEST(ExactPsdResources, ScreenGrowsGeometricallyAndStopsAtAQuarter) {
  std::vector<std::string> d(40, "1");
  d[6] = "-1/3";  // first in the leading 8×8 block
  const PsdResult at8 = decide_psd_exact(diagonal(d));
  EXPECT_EQ(at8.verdict, PsdVerdict::kNotPsd);
  EXPECT_TRUE(contains(at8.reason, "leading 8x8 principal submatrix")) << at8.reason;
  EXPECT_EQ(at8.pivot_index, 6);
  d[6] = "1";
  d[12] = "-1/3";  // beyond 40/4 = 10: the full decision finds it
  const PsdResult full = decide_psd_exact(diagonal(d));
  EXPECT_EQ(full.verdict, PsdVerdict::kNotPsd);
  EXPECT_FALSE(contains(full.reason, "leading")) << full.reason;
  EXPECT_EQ(full.pivot_index, 12);
  EXPECT_LT(quadratic_form(diagonal(d), full.witness), Rational(0));
}

TEST(ExactPsdResources, ScreenLeavesPdAndPsdToTheFullDecision) {
  const Mat<Rational> pd = rank_one_shift(60, 1, 50);
  const PsdResult r = decide_psd_exact(pd);
  EXPECT_EQ(r.verdict, PsdVerdict::kPositiveDefinite) << r.reason;
  EXPECT_EQ(r.rank, 60);
  EXPECT_TRUE(contains(r.reason, "all 60 pivots are positive")) << r.reason;
  const PsdResult s = decide_psd_exact(rank_one_shift(60, 0, 0));
  EXPECT_EQ(s.verdict, PsdVerdict::kPositiveSemidefinite) << s.reason;
  EXPECT_EQ(s.rank, 1);
}

}  // namespace
}  // namespace lpvid
