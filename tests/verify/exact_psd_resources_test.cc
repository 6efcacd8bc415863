/// Bounded resources of the exact PSD decision (issue 10): the multi-modular
/// path falls back to Bareiss instead of giving up when it runs out of primes.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/number_text.h"
#include "verify/exact_psd.h"
#include "verify/psd_internal.h"

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

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

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

}  // namespace
}  // namespace lpvid
