#include "verify/psd/psd_filter.h"

#include <cfenv>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/number_text.h"
#include "support/gen_matrices.h"
#include "verify/psd/exact_psd.h"

namespace lpvid {
namespace {

Mat<Rational> identity(int n, const Rational& scale = Rational(1)) {
  Mat<Rational> M = Mat<Rational>::Zero(n, n);
  for (int i = 0; i < n; ++i) M(i, i) = scale;
  return M;
}

TEST(PsdFilterTest, EnvironmentMeetsTheAssumptions) {
  EXPECT_EQ(floating_environment_problem(), "");
}

TEST(PsdFilterTest, ProvesWellConditionedMatricesPd) {
  for (int n : {1, 2, 10, 300}) {
    PsdFilterResult f = run_psd_filter(identity(n));
    EXPECT_TRUE(f.proved_pd) << n << ": " << f.reason;
    EXPECT_GT(f.shift, 0.0);
  }
  // Diagonally dominant with p/q entries that are not doubles.
  Mat<Rational> M(3, 3);
  M << Rational(3), Rational(1, 3), Rational(1, 7), Rational(1, 3), Rational(2), Rational(-1, 10), Rational(1, 7),
      Rational(-1, 10), Rational(1);
  EXPECT_TRUE(run_psd_filter(M).proved_pd);
}

TEST(PsdFilterTest, NeverProvesSingularOrBarelyDefiniteMatrices) {
  Mat<Rational> ones(2, 2);
  ones << Rational(1), Rational(1), Rational(1), Rational(1);
  EXPECT_FALSE(run_psd_filter(ones).proved_pd);  // singular PSD
  Mat<Rational> barely = ones;
  barely(1, 1) = rational_from_text("1.000000000000000000000000000001");
  EXPECT_FALSE(run_psd_filter(barely).proved_pd);  // PD by 1e-30: too close to prove
  // fl(M) = [[1,1],[1,1+2^-52]] is numerically PD, yet M is NOT PSD: the
  // unshifted floating Cholesky succeeds; the shifted one must not.
  Mat<Rational> fools(2, 2);
  const Rational x = rational_from_text("1298074214633707051247812158160895/1298074214633706907132624082305024");
  fools << Rational(1), x, x, rational_from_text("4503599627370497/4503599627370496");
  const PsdFilterResult f = run_psd_filter(fools);
  EXPECT_FALSE(f.proved_pd) << f.reason;
  EXPECT_EQ(decide_psd_exact(fools).verdict, PsdVerdict::kNotPsd);
}

TEST(PsdFilterTest, ExtremeMagnitudes) {
  // Near the top of the double range: still provable.
  EXPECT_TRUE(run_psd_filter(identity(3, rational_from_text("1e300"))).proved_pd);
  // Beyond it: "don't know", the exact path decides.
  const Mat<Rational> huge = identity(3, rational_from_text("1e400"));
  EXPECT_FALSE(run_psd_filter(huge).proved_pd);
  EXPECT_EQ(decide_psd(huge).verdict, PsdVerdict::kPositiveDefinite);
  // Subnormal and below: the underflow terms of the bound must keep it honest.
  for (const char* tiny : {"1e-310", "1e-320", "1e-400"}) {
    const Mat<Rational> M = identity(4, rational_from_text(tiny));
    const PsdFilterResult f = run_psd_filter(M);
    if (f.proved_pd) {
      EXPECT_EQ(decide_psd_exact(M).verdict, PsdVerdict::kPositiveDefinite) << tiny;
    }
    EXPECT_EQ(decide_psd(M).verdict, PsdVerdict::kPositiveDefinite) << tiny;
  }
  EXPECT_FALSE(run_psd_filter(identity(4, rational_from_text("1e-400"))).proved_pd);
}

TEST(PsdFilterTest, GivesCandidateDirectionsOnlyAsHints) {
  Mat<Rational> M(2, 2);
  M << Rational(1), Rational(2), Rational(2), Rational(1);
  const PsdFilterResult f = run_psd_filter(M);
  EXPECT_FALSE(f.proved_pd);
  ASSERT_EQ(f.negative_direction.size(), 2);
  EXPECT_EQ(f.failed_row, 1);
  const PsdResult r = decide_psd(M);
  EXPECT_EQ(r.verdict, PsdVerdict::kNotPsd);
  EXPECT_EQ(r.method, PsdMethod::kWitnessCheck);
  EXPECT_LT(quadratic_form(M, r.witness), Rational(0));
}

TEST(PsdFilterTest, WrongRoundingModeMeansDontKnow) {
  ASSERT_EQ(std::fesetround(FE_UPWARD), 0);
  const std::string problem = floating_environment_problem();
  const PsdFilterResult f = run_psd_filter(identity(3));
  std::fesetround(FE_TONEAREST);
  EXPECT_NE(problem, "");
  EXPECT_FALSE(f.proved_pd) << f.reason;
  EXPECT_TRUE(run_psd_filter(identity(3)).proved_pd);
}

TEST(PsdFilterTest, ZeroRowsDoNotStopTheFilter) {
  Mat<Rational> M = identity(5);
  M(2, 2) = Rational(0);
  const PsdResult r = decide_psd(M);
  EXPECT_EQ(r.verdict, PsdVerdict::kPositiveSemidefinite);
  EXPECT_TRUE(r.decided_by_filter);
  EXPECT_EQ(r.rank, 4);
  EXPECT_EQ(r.pivot_index, 2);
}

/// S·A·S with S = diag(10^e_i): the inertia of A, a diagonal spanning
/// 10^(2·min e) .. 10^(2·max e).
Mat<Rational> spread(const Mat<Rational>& A, const std::vector<int>& e) {
  Mat<Rational> M = A;
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j)
      M(i, j) = A(i, j) * rational_from_text("1e" + std::to_string(e[static_cast<std::size_t>(i)] + e[static_cast<std::size_t>(j)]));
  return M;
}

TEST(PsdFilterTest, BalancingLetsTheFilterDecideWideDiagonals) {
  // A = tridiag(-1, 2, -1) is PD (eigenvalues 2 − 2cos(kπ/7) > 0.19).
  Mat<Rational> A = Mat<Rational>::Zero(6, 6);
  for (int i = 0; i < 6; ++i) {
    A(i, i) = Rational(2);
    if (i > 0) A(i, i - 1) = A(i - 1, i) = Rational(-1);
  }
  const Mat<Rational> M = spread(A, {-150, -90, -30, 30, 90, 150});
  EXPECT_FALSE(run_psd_filter(M).proved_pd);  // unbalanced, the small rows drown in the error terms
  const PsdResult r = decide_psd(M);
  EXPECT_EQ(r.verdict, PsdVerdict::kPositiveDefinite);
  EXPECT_EQ(r.method, PsdMethod::kFloatingFilter) << r.reason;
  // Not PSD: the 2×2 block [[1, 2], [2, 1]] (eigenvalue −1) spread far apart.
  Mat<Rational> B = A;
  B(2, 2) = B(3, 3) = Rational(1);
  B(2, 3) = B(3, 2) = Rational(2);
  const Mat<Rational> N = spread(B, {-150, -90, -30, 30, 90, 150});
  const PsdResult q = decide_psd(N);
  EXPECT_EQ(q.verdict, PsdVerdict::kNotPsd);
  EXPECT_EQ(q.method, PsdMethod::kWitnessCheck) << q.reason;
  EXPECT_LT(quadratic_form(N, q.witness), Rational(0));
}

RC_GTEST_PROP(PsdFilterProperty, BalancedDecisionAgreesWithTheExactOne, ()) {
  const auto k = *rc::gen::oneOf(gen::psd_gram(true), gen::pd_gram_plus(), gen::singular_minus(), gen::with_negative());
  std::vector<int> e;
  for (Eigen::Index i = 0; i < k.M.rows(); ++i) e.push_back(*rc::gen::inRange(-80, 81));
  const Mat<Rational> M = spread(k.M, e);
  const PsdResult fast = decide_psd(M), exact = decide_psd_exact(M);
  RC_ASSERT(fast.verdict == exact.verdict);
  if (fast.verdict == PsdVerdict::kNotPsd) RC_ASSERT(quadratic_form(M, fast.witness) < Rational(0));
  RC_TAG(fast.decided_by_filter ? "filter" : "exact");
}

RC_GTEST_PROP(PsdFilterProperty, FilterPdImpliesExactPd, ()) {
  const auto k = *rc::gen::oneOf(gen::psd_gram(true), gen::psd_gram(false), gen::pd_gram_plus(),
                                 gen::singular_minus(), gen::with_negative());
  const PsdFilterResult f = run_psd_filter(k.M);
  if (f.proved_pd) RC_ASSERT(decide_psd_exact(k.M).verdict == PsdVerdict::kPositiveDefinite);
  RC_TAG(f.proved_pd ? "proved PD" : "don't know");
}

RC_GTEST_PROP(PsdFilterProperty, SingularGramIsNeverProvedPd, ()) {
  // Integer Gram matrices of rank-deficient B: every entry is a double, the
  // floating Cholesky may well "succeed"; the proof must not.
  const int n = *rc::gen::inRange(2, 12);
  const int r = *rc::gen::inRange(1, n);
  const Mat<Rational> B = *gen::rational_matrix(r, n, rc::gen::map(rc::gen::inRange(-1000, 1001), [](int v) {
    return Rational(v);
  }));
  const Mat<Rational> G = gen::gram(B);
  RC_ASSERT(!run_psd_filter(G).proved_pd);
  RC_ASSERT(decide_psd(G).verdict == PsdVerdict::kPositiveSemidefinite);
}

/// The factor of the theorem's formula, row by row with no blocking: the
/// independent reference for the filter's blocked loop (this file turns
/// contraction off below, so each product and difference is rounded).
Mat<double> row_by_row_cholesky(const Mat<double>& A);

TEST(PsdFilterTest, BlockedCholeskyGivesTheRowByRowDoubles) {
  // Sizes across the row blocks (16) and the column tiles (1024), with
  // entries that are not exact in any short sum, so that a changed order of
  // subtraction would change last bits; 2100 is where the helper thread
  // takes half of the columns (two columns tiles or more to the right).
  for (const int n : {1, 15, 17, 50, 1030, 2100}) {
    Mat<double> B = Mat<double>::Zero(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) B(i, j) = std::sin(1.0 + 0.37 * i + 0.11 * j * j) / 3.0;
    Mat<double> A = B.transpose() * B / n;
    A.diagonal().array() += 1.0 / 7.0;
    const Mat<double> R = floating_cholesky_factor(A), expected = row_by_row_cholesky(A);
    ASSERT_EQ(R.rows(), n);
    EXPECT_TRUE((R.array() == expected.array()).all()) << "n = " << n;
  }
  Mat<double> indefinite(2, 2);
  indefinite << 1, 2, 2, 1;
  EXPECT_EQ(floating_cholesky_factor(indefinite).size(), 0);
}

TEST(PsdFilterTest, ProvedRadiusIsHonoured) {
  // A = I proves PD for every X within r < 1/N of it (then X ⪰ (1 − N·r)·I
  // by Gershgorin); with r = 1 the ball contains X = I − J, the singular
  // all-ones complement, so the proof must fail.
  const int n = 40;
  std::vector<double> upper(static_cast<std::size_t>(n * n), 0.0);
  for (int i = 0; i < n; ++i) upper[static_cast<std::size_t>(i * n + i)] = 1.0;
  EXPECT_TRUE(run_psd_filter_within_radius(upper, n, Rational(1, 10 * n)).proved_pd);
  EXPECT_FALSE(run_psd_filter_within_radius(upper, n, Rational(1)).proved_pd);
  EXPECT_FALSE(run_psd_filter_within_radius(upper, n, Rational(-1)).proved_pd);
  EXPECT_FALSE(run_psd_filter_within_radius(upper, n + 1, Rational(0)).proved_pd);
}

}  // namespace

#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

namespace {

Mat<double> row_by_row_cholesky(const Mat<double>& A) {
  const Eigen::Index n = A.rows();
  Mat<double> R = Mat<double>::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i; j < n; ++j) {
      double s = A(i, j);
      for (Eigen::Index k = 0; k < i; ++k) {
        const double p = R(k, i) * R(k, j);
        s = s - p;
      }
      if (j == i) {
        if (!(s > 0)) return {};
        R(i, i) = std::sqrt(s);
      } else {
        R(i, j) = s / R(i, i);
      }
    }
  }
  return R;
}

}  // namespace
}  // namespace lpvid
