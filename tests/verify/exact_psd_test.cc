#include "verify/psd/exact_psd.h"

#include <gmp.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/number_text.h"
#include "support/gen_matrices.h"
#include "verify/psd/psd_internal.h"

namespace lpvid {
namespace {

Mat<Rational> mat(const std::vector<std::vector<std::string>>& rows) {
  Mat<Rational> M(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.empty() ? 0 : rows[0].size()));
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < rows[i].size(); ++j)
      M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = rational_from_text(rows[i][j]);
  return M;
}

using Decider = std::function<PsdResult(const Mat<Rational>&)>;

/// Every exact implementation and the filtered one, by name.
std::vector<std::pair<std::string, Decider>> deciders() {
  return {
      {"exact", [](const Mat<Rational>& M) { return decide_psd_exact(M); }},
      {"exact_1thread", [](const Mat<Rational>& M) { return decide_psd_exact(M, 1); }},
      {"bareiss", [](const Mat<Rational>& M) { return decide_psd_bareiss(M, 1); }},
      {"bareiss_threads", [](const Mat<Rational>& M) { return decide_psd_bareiss(M, 2); }},
      {"rational", [](const Mat<Rational>& M) { return decide_psd_rational_ldlt(M); }},
      {"filtered", [](const Mat<Rational>& M) { return decide_psd(M); }},
  };
}

/// A NOT_PSD result must carry v with vᵀMv < 0, exactly.
void expect_valid_witness(const Mat<Rational>& M, const PsdResult& r, const std::string& who) {
  ASSERT_EQ(r.verdict, PsdVerdict::kNotPsd) << who;
  ASSERT_EQ(r.witness.size(), M.rows()) << who;
  EXPECT_LT(quadratic_form(M, r.witness), Rational(0)) << who;
}

void expect_all(const Mat<Rational>& M, PsdVerdict expected, long rank = -2) {
  for (const auto& [name, decide] : deciders()) {
    PsdResult r = decide(M);
    EXPECT_EQ(r.verdict, expected) << name << ": " << r.reason;
    if (expected == PsdVerdict::kNotPsd) expect_valid_witness(M, r, name);
    if (rank != -2 && r.rank >= 0) {
      EXPECT_EQ(r.rank, rank) << name;
    }
  }
}

TEST(ExactPsdTest, VerdictWords) {
  EXPECT_STREQ(verdict_word(PsdVerdict::kPositiveDefinite), "PD");
  EXPECT_STREQ(verdict_word(PsdVerdict::kPositiveSemidefinite), "PSD");
  EXPECT_STREQ(verdict_word(PsdVerdict::kNotPsd), "NOT_PSD");
}

TEST(ExactPsdTest, SmallKnownAnswers) {
  expect_all(mat({{"2"}}), PsdVerdict::kPositiveDefinite, 1);
  expect_all(mat({{"0"}}), PsdVerdict::kPositiveSemidefinite, 0);
  expect_all(mat({{"-1/7"}}), PsdVerdict::kNotPsd);
  expect_all(mat({{"2", "1"}, {"1", "2"}}), PsdVerdict::kPositiveDefinite, 2);
  expect_all(mat({{"1", "1"}, {"1", "1"}}), PsdVerdict::kPositiveSemidefinite, 1);
  expect_all(mat({{"1", "2"}, {"2", "1"}}), PsdVerdict::kNotPsd);
  expect_all(mat({{"0", "0", "0"}, {"0", "2", "1"}, {"0", "1", "2"}}), PsdVerdict::kPositiveSemidefinite, 2);
  expect_all(mat({{"0", "0"}, {"0", "0"}}), PsdVerdict::kPositiveSemidefinite, 0);
}

TEST(ExactPsdTest, EmptyMatrixIsPd) {
  Mat<Rational> M(0, 0);
  for (const auto& [name, decide] : deciders()) EXPECT_EQ(decide(M).verdict, PsdVerdict::kPositiveDefinite) << name;
}

TEST(ExactPsdTest, ZeroPivotWithNonzeroRowIsNotPsd) {
  const Mat<Rational> swap = mat({{"0", "1"}, {"1", "0"}});
  expect_all(swap, PsdVerdict::kNotPsd);
  EXPECT_EQ(decide_psd_bareiss(swap).pivot_index, 0);
  EXPECT_EQ(decide_psd_rational_ldlt(swap).pivot_index, 0);

  const Mat<Rational> ones = mat({{"1", "1", "1"}, {"1", "1", "1"}, {"1", "1", "0"}});
  expect_all(ones, PsdVerdict::kNotPsd);
  for (const PsdResult& r : {decide_psd_exact(ones), decide_psd_bareiss(ones), decide_psd_rational_ldlt(ones)}) {
    EXPECT_EQ(r.pivot_index, 2) << r.reason;
    EXPECT_EQ(r.step, 1) << r.reason;
  }
  // Zero diagonal after a positive pivot: [[4,0,0],[0,0,b],[0,b,0]].
  expect_all(mat({{"4", "0", "0"}, {"0", "0", "-3/7"}, {"0", "-3/7", "0"}}), PsdVerdict::kNotPsd);
}

TEST(ExactPsdTest, TinyPerturbationsAreSeen) {
  expect_all(mat({{"1", "1"}, {"1", "1.000000000000000000000000000001"}}), PsdVerdict::kPositiveDefinite, 2);
  expect_all(mat({{"1", "1"}, {"1", "0.999999999999999999999999999999"}}), PsdVerdict::kNotPsd);
  // x = 1 + 2^-53 - 2^-110 rounds to 1 in double: fl(M) is numerically PD, M is not.
  const std::string x = "1298074214633707051247812158160895/1298074214633706907132624082305024";
  expect_all(mat({{"1", x}, {x, "4503599627370497/4503599627370496"}}), PsdVerdict::kNotPsd);
}

TEST(ExactPsdTest, NonSymmetricOrNonSquareThrows) {
  for (const auto& [name, decide] : deciders()) {
    EXPECT_THROW(decide(mat({{"1", "2"}, {"2.0000001", "1"}})), std::invalid_argument) << name;
    EXPECT_THROW(decide(mat({{"1", "2", "3"}, {"2", "1", "0"}})), std::invalid_argument) << name;
  }
  EXPECT_NO_THROW(require_symmetric(mat({{"1", "0.5"}, {"1/2", "1"}})));
}

TEST(ExactPsdTest, HilbertMatricesArePd) {
  for (int n : {5, 12, 20}) {
    Mat<Rational> H(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) H(i, j) = Rational(1) / Rational(i + j + 1);
    expect_all(H, PsdVerdict::kPositiveDefinite, n);
    // The filter cannot prove such an ill-conditioned matrix; exact decides.
    if (n >= 12) {
      EXPECT_FALSE(decide_psd(H).decided_by_filter);
    }
  }
}

/// Large enough that Hadamard's bound needs several primes: a dense
/// congruence Tᵀ·D·T of D = diag(d) with T unit upper triangular.
Mat<Rational> congruent_to_diagonal(const std::vector<Rational>& d, unsigned seed) {
  const int n = static_cast<int>(d.size());
  Mat<Rational> T = Mat<Rational>::Identity(n, n);
  unsigned s = seed;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      s = s * 1103515245u + 12345u;
      T(i, j) = Rational(static_cast<int>((s >> 16) % 7) - 3);
    }
  Mat<Rational> M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) {
      Rational sum(0);
      for (int k = 0; k <= std::min(i, j); ++k) sum += T(k, i) * d[static_cast<size_t>(k)] * T(k, j);
      M(i, j) = M(j, i) = sum;
    }
  return M;
}

TEST(ExactPsdTest, DenseCongruencesKeepTheInertia) {
  const Rational eps = rational_from_text("1e-40");
  std::vector<Rational> pd(40, Rational(1)), psd(40, Rational(1)), neg(40, Rational(1)), zero2(40, Rational(2));
  pd[39] = eps;
  psd[20] = Rational(0);
  psd[39] = Rational(0);
  neg[25] = -eps;
  expect_all(congruent_to_diagonal(pd, 1), PsdVerdict::kPositiveDefinite, 40);
  expect_all(congruent_to_diagonal(psd, 2), PsdVerdict::kPositiveSemidefinite, 38);
  expect_all(congruent_to_diagonal(neg, 3), PsdVerdict::kNotPsd);
  // A [[0,b],[b,0]] block hidden behind 30 pivots.
  Mat<Rational> M = congruent_to_diagonal(zero2, 4);
  Mat<Rational> B = Mat<Rational>::Zero(42, 42);
  B.topLeftCorner(40, 40) = M;
  B(40, 41) = B(41, 40) = Rational(5, 3);
  expect_all(B, PsdVerdict::kNotPsd);
}

TEST(ExactPsdTest, ThreadedEliminationsAgreeWithSingleThreaded) {
  // Large enough for the row-parallel Bareiss update and many primes.
  std::vector<Rational> psd(90, Rational(1, 3)), neg(90, Rational(2));
  psd[10] = psd[50] = Rational(0);
  neg[70] = Rational(-1, 1000);
  for (const Mat<Rational>& M : {congruent_to_diagonal(psd, 5), congruent_to_diagonal(neg, 6)}) {
    const PsdResult b1 = decide_psd_bareiss(M, 1), b2 = decide_psd_bareiss(M, 2);
    const PsdResult e1 = decide_psd_exact(M, 1), e2 = decide_psd_exact(M, 2);
    for (const PsdResult* r : {&b2, &e1, &e2}) {
      EXPECT_EQ(r->verdict, b1.verdict) << r->reason;
      EXPECT_EQ(r->rank, b1.rank) << r->reason;
      if (r->verdict == PsdVerdict::kNotPsd) {
        EXPECT_LT(quadratic_form(M, r->witness), Rational(0));
      }
    }
    EXPECT_EQ(b2.pivot_index, b1.pivot_index);
    EXPECT_EQ(e2.pivot_index, e1.pivot_index);
  }
  EXPECT_EQ(decide_psd_exact(congruent_to_diagonal(psd, 5)).rank, 88);
}

/// The first prime of the multi-modular path (primes above 2^31 − 2^24).
Rational first_modular_prime() {
  mpz_t z;
  mpz_init_set_ui(z, (1ul << 31) - (1ul << 24));
  mpz_nextprime(z, z);
  mpq_t q;
  mpq_init(q);
  mpq_set_z(q, z);
  Rational r(q);
  mpq_clear(q);
  mpz_clear(z);
  return r;
}

TEST(ExactPsdTest, PrimeDividingAPivotFallsBackCorrectly) {
  // Entries divisible by the first prime p0 look like zeros modulo p0; the
  // multi-modular path must not be fooled (it falls back to Bareiss).
  const Rational p0 = first_modular_prime();
  Mat<Rational> a = Mat<Rational>::Zero(2, 2), b = Mat<Rational>::Zero(2, 2), c(2, 2), d = Mat<Rational>::Zero(2, 2);
  a(0, 0) = Rational(1);
  a(1, 1) = p0;  // PD
  b(0, 0) = b(1, 1) = p0;  // PD
  c << p0, Rational(1), Rational(1), Rational(0);  // NOT_PSD
  d(0, 0) = p0;
  d(1, 1) = -Rational(1);  // NOT_PSD
  for (const auto& [name, decide] : deciders()) {
    EXPECT_EQ(decide(a).verdict, PsdVerdict::kPositiveDefinite) << name;
    EXPECT_EQ(decide(b).verdict, PsdVerdict::kPositiveDefinite) << name;
  }
  expect_all(c, PsdVerdict::kNotPsd);
  expect_all(d, PsdVerdict::kNotPsd);
  // PSD whose Schur complement is p0·(nonzero) after one pivot: not PSD.
  Mat<Rational> e(3, 3);
  e << Rational(1), Rational(0), Rational(0), Rational(0), p0, p0, Rational(0), p0, Rational(0);
  expect_all(e, PsdVerdict::kNotPsd);
}

// ---------------------------------------------------------------------------
// Properties (matrices with known verdicts by construction, gen_matrices.h).

RC_GTEST_PROP(PsdProperty, GramMatrixIsPsdAndSingularGramIsNotPd, ()) {
  const auto k = *gen::psd_gram(true);
  for (const auto& [name, decide] : deciders()) {
    const PsdResult r = decide(k.M);
    RC_ASSERT(r.verdict == PsdVerdict::kPositiveSemidefinite);
    if (r.rank >= 0) RC_ASSERT(r.rank <= k.rank_bound);
  }
  const auto full = *gen::psd_gram(false);
  RC_ASSERT(decide_psd_exact(full.M).verdict != PsdVerdict::kNotPsd);
}

RC_GTEST_PROP(PsdProperty, GramPlusTinyIdentityIsPd, ()) {
  const auto k = *gen::pd_gram_plus();
  for (const auto& [name, decide] : deciders()) RC_ASSERT(decide(k.M).verdict == PsdVerdict::kPositiveDefinite);
}

RC_GTEST_PROP(PsdProperty, SingularGramMinusTinyIdentityIsNotPsd, ()) {
  const auto k = *gen::singular_minus();
  for (const auto& [name, decide] : deciders()) {
    const PsdResult r = decide(k.M);
    RC_ASSERT(r.verdict == PsdVerdict::kNotPsd);
    RC_ASSERT(r.witness.size() == k.M.rows());
    RC_ASSERT(quadratic_form(k.M, r.witness) < Rational(0));
  }
}

RC_GTEST_PROP(PsdProperty, KnownNegativeDirectionGivesNotPsdWithExactWitness, ()) {
  const auto k = *gen::with_negative();
  RC_ASSERT(quadratic_form(k.M, k.v) == Rational(-1));  // the construction itself
  for (const auto& [name, decide] : deciders()) {
    const PsdResult r = decide(k.M);
    RC_ASSERT(r.verdict == PsdVerdict::kNotPsd);
    RC_ASSERT(quadratic_form(k.M, r.witness) < Rational(0));
  }
}

/// Any symmetric matrix with entries in {-2..2} (many zero pivots).
rc::Gen<gen::KnownMatrix> arbitrary_symmetric() {
  return rc::gen::mapcat(gen::psd_dimension(), [](int n) {
    const auto cells = static_cast<size_t>(n * n);
    return rc::gen::map(rc::gen::container<std::vector<int>>(cells, rc::gen::inRange(-2, 3)),
                        [n](const std::vector<int>& upper) {
                          gen::KnownMatrix k;
                          k.n = k.rank_bound = n;
                          k.M.resize(n, n);
                          for (int i = 0; i < n; ++i)
                            for (int j = i; j < n; ++j)
                              k.M(i, j) = k.M(j, i) = Rational(upper[static_cast<size_t>(i * n + j)]);
                          return k;
                        });
  });
}

/// Symmetric matrices of every kind: arbitrary small integers, PD (BᵀB + εI),
/// PSD of lower rank (BᵀB, B r×n, r < n) and indefinite rationals (BᵀB − εI
/// with B singular, BᵀB − c·vvᵀ). Every implementation agrees on the verdict
/// with the rational reference; Bareiss also on the pivot row, rank and step;
/// so does decide_psd_exact when it must fall back to Bareiss for want of
/// primes; the leading-block screen run on every block size (up to n) changes
/// no verdict; the fast path never contradicts the exact one.
RC_GTEST_PROP(PsdProperty, AllImplementationsAgreeOnArbitrarySymmetricMatrices, ()) {
  const auto k = *rc::gen::oneOf(arbitrary_symmetric(), gen::pd_gram_plus(), gen::psd_gram(true),
                                 gen::singular_minus(), gen::with_negative());
  const Mat<Rational>& M = k.M;
  psd_detail::ExactPsdLimits screen_all, no_primes;
  screen_all.screen_divisor = 1;
  no_primes.max_primes = 0;
  const PsdResult ref = decide_psd_rational_ldlt(M);
  const PsdResult bar = decide_psd_bareiss(M);
  const PsdResult exa = decide_psd_exact(M);
  const PsdResult fast = decide_psd(M);
  const PsdResult screened = psd_detail::decide_psd_exact_limited(M, 0, screen_all);
  const PsdResult fallback = psd_detail::decide_psd_exact_limited(M, 0, no_primes);
  for (const PsdResult* r : {&bar, &exa, &fast, &screened, &fallback}) RC_ASSERT(r->verdict == ref.verdict);
  for (const PsdResult* r : {&bar, &fallback}) {
    RC_ASSERT(r->pivot_index == ref.pivot_index);
    RC_ASSERT(r->rank == ref.rank);
    RC_ASSERT(r->step == ref.step);
  }
  if (ref.verdict != PsdVerdict::kNotPsd) {
    RC_ASSERT(exa.rank == ref.rank);
    RC_ASSERT(screened.rank == ref.rank);
  }
  for (const PsdResult* r : {&ref, &bar, &exa, &fast, &screened, &fallback})
    if (r->verdict == PsdVerdict::kNotPsd) RC_ASSERT(quadratic_form(M, r->witness) < Rational(0));
  RC_TAG(verdict_word(ref.verdict));
  RC_TAG(screened.reason.find("leading") != std::string::npos ? "screen decided" : "full decision");
}

RC_GTEST_PROP(PsdProperty, FastPathNeverDisagreesWithExactPath, ()) {
  const auto k = *rc::gen::oneOf(gen::psd_gram(true), gen::psd_gram(false), gen::pd_gram_plus(),
                                 gen::singular_minus(), gen::with_negative());
  const PsdResult fast = decide_psd(k.M);
  const PsdResult exact = decide_psd_exact(k.M);
  RC_ASSERT(fast.verdict == exact.verdict);
  if (fast.decided_by_filter && fast.method == PsdMethod::kFloatingFilter)
    RC_ASSERT(exact.verdict != PsdVerdict::kNotPsd);
  RC_TAG(fast.decided_by_filter ? "filter" : "exact");
}

RC_GTEST_PROP(PsdProperty, SymmetricPermutationKeepsTheVerdict, ()) {
  const auto k = *rc::gen::oneOf(gen::psd_gram(true), gen::pd_gram_plus(), gen::singular_minus(),
                                 gen::with_negative());
  const auto p = *gen::permutation(k.n);
  const Mat<Rational> P = gen::permuted(k.M, p);
  const PsdResult a = decide_psd_exact(k.M), b = decide_psd_exact(P);
  RC_ASSERT(a.verdict == b.verdict);
  RC_ASSERT(a.rank == b.rank || a.verdict == PsdVerdict::kNotPsd);
  RC_ASSERT(decide_psd(P).verdict == a.verdict);
}

RC_GTEST_PROP(PsdProperty, PositiveScalingKeepsTheVerdict, ()) {
  const auto k = *rc::gen::oneOf(gen::psd_gram(true), gen::pd_gram_plus(), gen::singular_minus(),
                                 gen::with_negative());
  const Rational c = *gen::positive_rational();
  const Rational tiny = *gen::tiny_positive();
  const PsdVerdict v = decide_psd_exact(k.M).verdict;
  for (const Rational& s : {c, tiny, Rational(1) / tiny}) {
    const Mat<Rational> S = k.M * s;
    RC_ASSERT(decide_psd_exact(S).verdict == v);
    RC_ASSERT(decide_psd(S).verdict == v);
  }
}

}  // namespace
}  // namespace lpvid
