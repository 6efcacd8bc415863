// The structured proof of (C1) for one output and one input
// (verify/certificate/tap_gram_filter.h) against answers known without it:
//  - one tap h: T = h·I, so d2·I − T Tᵀ is PD iff d2 > h² (exactly);
//  - random taps: a proof of PD must agree with the exact decision on the
//    exact complement (verify/certificate/tap_gram.h, decided by the
//    rational LDLᵀ reference), and a clear margin must be proved;
//  - taps that are not doubles: the rounding of the taps is part of the
//    radius, so a matrix that is PD only in doubles is never proved.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <vector>

#include "core/number_text.h"
#include "support/gen_numbers.h"
#include "verify/certificate/tap_gram.h"
#include "verify/certificate/tap_gram_filter.h"
#include "verify/psd/exact_psd.h"

namespace lpvid {
namespace {

bool exactly_pd(const std::vector<Rational>& t, long L, const Rational& d2) {
  const std::size_t K = std::min(t.size(), static_cast<std::size_t>(L));  // the taps T contains
  Mat<Rational> taps(static_cast<Eigen::Index>(K), 1);
  for (std::size_t k = 0; k < K; ++k) taps(static_cast<Eigen::Index>(k), 0) = t[k];
  return decide_psd_rational_ldlt(tap_gram_complement(taps, L, 1, 1, d2)).verdict == PsdVerdict::kPositiveDefinite;
}

/// ‖T‖² in doubles from the dense lower-triangular Toeplitz matrix.
double dense_norm2(const std::vector<Rational>& t, long L) {
  Mat<double> T = Mat<double>::Zero(L, L);
  for (long i = 0; i < L; ++i)
    for (long k = 0; k <= i && k < static_cast<long>(t.size()); ++k) T(i, i - k) = nearest_double(t[static_cast<std::size_t>(k)]);
  Eigen::SelfAdjointEigenSolver<Mat<double>> es(T * T.transpose(), Eigen::EigenvaluesOnly);
  return es.eigenvalues().maxCoeff();
}

TEST(TapGramFilter, OneTapIsProvedExactlyAboveItsSquare) {
  const Rational h(3, 7);  // not a double: the rounding term is exercised
  for (const long L : {1L, 9L, 300L}) {
    EXPECT_TRUE(prove_tap_gram_complement_pd({h}, L, h * h * Rational(1001, 1000)).proved_pd) << L;
    // Below h² and at it: not PD, never proved.
    EXPECT_FALSE(prove_tap_gram_complement_pd({h}, L, h * h).proved_pd) << L;
    EXPECT_FALSE(prove_tap_gram_complement_pd({h}, L, h * h - rational_from_text("1e-40")).proved_pd) << L;
  }
}

TEST(TapGramFilter, PdOnlyInDoublesIsNotProved) {
  // d2 = t² + 1e-40 with t = 1/3 + 1e-30: every double computation sees the
  // same matrix as for t = 1/3 and d2 = 1/9, whose complement is PSD only by
  // the ≈1e-17 of rounding; the exact matrix is PD by 1e-40 only. The proof
  // must not claim it, and for d2 just below t² nothing must be claimed.
  const Rational t = Rational(1, 3) + rational_from_text("1e-30");
  EXPECT_FALSE(prove_tap_gram_complement_pd({t}, 20, t * t - rational_from_text("1e-40")).proved_pd);
  EXPECT_FALSE(prove_tap_gram_complement_pd({t}, 20, t * t + rational_from_text("1e-40")).proved_pd);
}

TEST(TapGramFilter, RefusesWhatItCannotRead) {
  EXPECT_FALSE(prove_tap_gram_complement_pd({Rational(1)}, 0, Rational(2)).proved_pd);
  EXPECT_FALSE(prove_tap_gram_complement_pd({rational_from_text("1e400")}, 5, rational_from_text("1e900")).proved_pd);
}

RC_GTEST_PROP(TapGramFilterProperty, ProofAgreesWithTheExactDecision, ()) {
  const long L = *rc::gen::inRange(1, 40);
  const int K = *rc::gen::inRange(1, static_cast<int>(L) + 3);  // K > L: the extra taps are not in T
  std::vector<Rational> t(static_cast<std::size_t>(K));
  for (auto& x : t) x = *gen::small_rational();
  const double norm2 = dense_norm2(t, L);
  RC_PRE(norm2 > 0);  // T = 0: the answer is d2 > 0, not a question of margins
  // d2 around ‖T‖²: below (not PD), at a hair above (either), well above (proved).
  const double factor = *rc::gen::element(0.5, 0.999, 1.0 + 1e-13, 1.001, 2.0);
  const Rational d2 = exact_rational_of_double(norm2 * factor);
  const TapGramFilterResult f = prove_tap_gram_complement_pd(t, L, d2);
  if (f.proved_pd) RC_ASSERT(exactly_pd(t, L, d2));
  if (factor >= 1.001) RC_ASSERT(f.proved_pd);
  if (factor <= 0.999) RC_ASSERT(!f.proved_pd);
  RC_TAG(f.proved_pd ? "proved" : "not proved");
}

}  // namespace
}  // namespace lpvid
