// (C1) of Theorem 2.1 as the certificate checker decides it
// (verify/certificate/c1_check.h) against the PSD decision of the full (C1) matrix,
// built here from its definition and decided by the rational LDLᵀ reference
// (no filter, no balancing, no Schur step):
//  - form "w": [T_zᵀT_z, T_wᵀ; T_w, δ²I] with T_zᵀT_z the plain product;
//  - form "delta": [δ²I, T_Δ; T_Δᵀ, I] with T_Δ from the taps, unbalanced.
// Exact boundaries are built where the answer is known without any PSD
// decision: w = α·Q·z with Q orthogonal gives T_wᵀT_w = α²·T_zᵀT_z, so (C1)
// holds iff δ² ≥ α² (or z = 0); a single tap h gives ‖T_Δ‖ = |h|.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "support/gen_matrices.h"
#include "support/gen_numbers.h"
#include "toeplitz/signal_toeplitz.h"
#include "verify/certificate/c1_check.h"
#include "verify/certificate/tap_gram.h"
#include "verify/psd/exact_psd.h"
#include "verify/psd/power_of_two.h"

namespace lpvid {
namespace {

Rational pow10(int k) {
  Rational p(1);
  for (int i = 0; i < (k < 0 ? -k : k); ++i) p *= Rational(10);
  return k < 0 ? Rational(1) / p : p;
}

bool full_psd(const Mat<Rational>& M) { return decide_psd_rational_ldlt(M).verdict != PsdVerdict::kNotPsd; }

/// [T_zᵀT_z, T_wᵀ; T_w, δ²I], T_w = signal_toeplitz(w).
Mat<Rational> full_w_matrix(const Mat<Rational>& Tz, const Mat<Rational>& w, const Rational& delta2) {
  const Eigen::Index n = Tz.cols(), m = n * w.cols();
  const Mat<Rational> Tw = signal_toeplitz(w);
  Mat<Rational> M = Mat<Rational>::Zero(n + m, n + m);
  M.topLeftCorner(n, n) = Tz.transpose() * Tz;
  M.bottomLeftCorner(m, n) = Tw;
  M.topRightCorner(n, m) = Tw.transpose();
  for (Eigen::Index i = n; i < n + m; ++i) M(i, i) = delta2;
  return M;
}

/// [δ²I, T_Δ; T_Δᵀ, I] on `L` samples, T_Δ block (a, b) = Δ_{a−b} (ny × nz).
/// T_Δ written out: block (a, b) = Δ_{a−b} for 0 ≤ a − b < K.
Mat<Rational> dense_tap_toeplitz(const Mat<Rational>& taps, Eigen::Index L, Eigen::Index ny, Eigen::Index nz) {
  Mat<Rational> T = Mat<Rational>::Zero(L * ny, L * nz);
  for (Eigen::Index a = 0; a < L; ++a)
    for (Eigen::Index b = 0; b <= a; ++b)
      if (a - b < taps.rows())
        for (Eigen::Index i = 0; i < ny; ++i)
          for (Eigen::Index j = 0; j < nz; ++j) T(a * ny + i, b * nz + j) = taps(a - b, i * nz + j);
  return T;
}

Mat<Rational> full_delta_matrix(const Mat<Rational>& taps, Eigen::Index L, Eigen::Index ny, Eigen::Index nz,
                                const Rational& delta2) {
  const Mat<Rational> T = dense_tap_toeplitz(taps, L, ny, nz);
  Mat<Rational> M = Mat<Rational>::Zero(L * (ny + nz), L * (ny + nz));
  M.topLeftCorner(L * ny, L * ny) = delta2 * Mat<Rational>::Identity(L * ny, L * ny);
  M.topRightCorner(L * ny, L * nz) = T;
  M.bottomLeftCorner(L * nz, L * ny) = T.transpose();
  M.bottomRightCorner(L * nz, L * nz) = Mat<Rational>::Identity(L * nz, L * nz);
  return M;
}

/// A scale 10^k, k ∈ {0, ±1, ±100, ±200}: beyond ±77 the entries of the
/// Schur complement pass 2^±256 and the checker rescales them.
rc::Gen<int> decade() { return rc::gen::element(0, 0, 0, 1, -1, 100, -100, 200, -200); }

/// δ² for a random case: 0, a small rational, or one scaled by 10^k.
Rational random_delta2() {
  const int kind = *rc::gen::inRange(0, 4);
  if (kind == 0) return Rational(0);
  return *gen::positive_rational() * pow10(kind == 1 ? 0 : *decade());
}

C1Outcome w_form(const Mat<Rational>& Tz, const Mat<Rational>& w, const Rational& delta2) {
  return check_c1_w_form(Mat<Rational>(Tz.transpose() * Tz), w, delta2);
}

// Random T_z (any matrix: the Schur step does not need a Toeplitz T_z),
// sometimes with a zero column (singular), random or zero w, δ² random.
RC_GTEST_PROP(VerifyC1WForm, ReducedCheckAgreesWithTheFullMatrix, ()) {
  const int n = *rc::gen::inRange(1, 5), nz = *rc::gen::inRange(1, 3), ny = *rc::gen::inRange(1, 3);
  const Rational scale = pow10(*decade());
  Mat<Rational> Tz = *gen::rational_matrix(n * nz, n, gen::small_rational()) * scale;
  if (*rc::gen::arbitrary<bool>()) Tz.col(*rc::gen::inRange(0, n)).setZero();
  Mat<Rational> w = *gen::rational_matrix(n, ny, gen::small_integer());
  if (*rc::gen::inRange(0, 5) == 0) w.setZero();
  // δ² random, or near the threshold: a Rayleigh quotient vᵀT_wᵀT_w v / vᵀT_zᵀT_z v
  // (a lower bound of the smallest feasible δ²) times 1/2, 1, 5/4 or 2.
  Rational delta2 = random_delta2();
  if (*rc::gen::arbitrary<bool>()) {
    const Vec<Rational> v = *gen::rational_matrix(n, 1, gen::small_integer());
    const Mat<Rational> Tw = signal_toeplitz(w);
    const Rational num = (Tw * v).squaredNorm(), den = (Tz * v).squaredNorm();
    if (den > 0) delta2 = num / den * *rc::gen::element(Rational(1, 2), Rational(1), Rational(5, 4), Rational(2));
  }
  const C1Outcome got = w_form(Tz, w, delta2);
  const bool expected = full_psd(full_w_matrix(Tz, w, delta2));
  RC_CLASSIFY(expected, "holds");
  RC_CLASSIFY(delta2 == 0, "delta2 = 0");
  RC_LOG() << got.text << "\n";
  RC_ASSERT(got.holds() == expected);
}

// Exact boundary: z random (z_0 = 0 sometimes: T_z singular), w = α·Q·z with
// Q = 1 (ny = nz = 1) or the rational rotation [3/5, −4/5; 4/5, 3/5]. Then
// T_w = (I ⊗ αQ)·T_z and T_wᵀT_w = α²·T_zᵀT_z: (C1) holds iff δ² ≥ α² or
// z = 0. δ² = α² exactly, just below (by 10^−30 relative) and above.
RC_GTEST_PROP(VerifyC1WForm, ExactBoundaryDeltaSquaredEqualsAlphaSquared, ()) {
  const int n = *rc::gen::inRange(1, 6), nz = *rc::gen::element(1, 2);
  Mat<Rational> z = *gen::rational_matrix(n, nz, gen::small_rational());
  if (*rc::gen::arbitrary<bool>()) z.row(0).setZero();
  Mat<Rational> Q = Mat<Rational>::Identity(nz, nz);
  if (nz == 2) Q << Rational(3, 5), Rational(-4, 5), Rational(4, 5), Rational(3, 5);
  const Rational alpha = *gen::positive_rational() * pow10(*decade());
  const Mat<Rational> w = alpha * z * Q.transpose();  // row k: (α·Q·z_k)ᵀ
  const Mat<Rational> Tz = signal_toeplitz(z);
  const bool z_zero = z.isZero();
  const Rational a2 = alpha * alpha;
  const Rational eps = pow10(-30);
  for (const auto& [delta2, expected] : std::vector<std::pair<Rational, bool>>{
           {a2, true}, {a2 * (Rational(1) - eps), z_zero}, {a2 * (Rational(1) + eps), true}, {Rational(0), z_zero}}) {
    const C1Outcome got = w_form(Tz, w, delta2);
    RC_LOG() << got.text << "\n";
    RC_ASSERT(full_psd(full_w_matrix(Tz, w, delta2)) == expected);
    RC_ASSERT(got.holds() == expected);
  }
}

// Causality: z_0 = … = z_{m−1} = 0 but w_0 ≠ 0 fails for every δ², however
// large (the zero columns of T_z leave nothing to bound T_w with).
RC_GTEST_PROP(VerifyC1WForm, NonCausalWFailsForEveryDelta, ()) {
  const int n = *rc::gen::inRange(2, 6), m = *rc::gen::inRange(1, n);
  Mat<Rational> z = *gen::rational_matrix(n, 1, gen::small_rational());
  z.topRows(m).setZero();
  Mat<Rational> w = z * *gen::positive_rational();
  w(0, 0) = *gen::positive_rational();
  const Rational delta2 = *gen::positive_rational() * pow10(*rc::gen::element(0, 10, 200));
  const Mat<Rational> Tz = signal_toeplitz(z);
  RC_ASSERT(!full_psd(full_w_matrix(Tz, w, delta2)));
  RC_ASSERT(!w_form(Tz, w, delta2).holds());
}

TEST(VerifyC1WForm, TextNamesTheMatrixAndTheCase) {
  Mat<Rational> z(3, 1), w(3, 1);
  z << Rational(1), Rational(2), Rational(0);
  w << Rational(1, 2), Rational(1), Rational(0);  // w = z/2: δ² ≥ 1/4
  const Mat<Rational> Tz = signal_toeplitz(z);
  const C1Outcome holds = w_form(Tz, w, Rational(1, 4));
  EXPECT_TRUE(holds.holds());
  EXPECT_NE(holds.text.find("(C1) holds: delta2*T_z'T_z - T_w'T_w"), std::string::npos) << holds.text;
  EXPECT_NE(holds.text.find("(size 3)"), std::string::npos) << holds.text;
  const C1Outcome fails = w_form(Tz, w, Rational(1, 5));
  EXPECT_FALSE(fails.holds());
  EXPECT_NE(fails.text.find("(C1) fails: delta2*T_z'T_z - T_w'T_w"), std::string::npos) << fails.text;
  const C1Outcome zero = w_form(Tz, w, Rational(0));
  EXPECT_FALSE(zero.holds());
  EXPECT_NE(zero.text.find("delta2 = 0 but w(0,0)"), std::string::npos) << zero.text;
  const C1Outcome no_w = w_form(Tz, Mat<Rational>::Zero(3, 1), Rational(0));
  EXPECT_TRUE(no_w.holds());
  EXPECT_NE(no_w.text.find("w = 0"), std::string::npos) << no_w.text;
}

TEST(VerifyC1WForm, SizeMismatchIsAnError) {
  EXPECT_THROW(check_c1_w_form(Mat<Rational>::Identity(3, 3), Mat<Rational>::Ones(2, 1), Rational(1)),
               std::invalid_argument);
}

// δ² with thousands of digits (1e−5000, 1e4000): balanced, decided at once.
TEST(VerifyC1WForm, DeltaSquaredFarOutsideTheDoubleRange) {
  const int n = 40;
  Mat<Rational> z(n, 1);
  z(0, 0) = Rational(4);  // Σ_{k≥1} |z_k| < z_0: T_z well conditioned, so the filter decides
  for (int k = 1; k < n; ++k) z(k, 0) = Rational((k * 7) % 5 - 2, (k + 1) * (k + 1));
  const Mat<Rational> Tz = signal_toeplitz(z);
  for (int k : {-5000, 4000}) {
    const Rational alpha2 = pow10(k);
    const Mat<Rational> w = z * pow10(k / 2);  // T_wᵀT_w = 10^k·T_zᵀT_z
    const C1Outcome at = w_form(Tz, w, alpha2);
    EXPECT_TRUE(at.holds()) << at.text;
    const C1Outcome above = w_form(Tz, w, alpha2 * (Rational(1) + pow10(-20)));
    EXPECT_TRUE(above.holds()) << above.text;
    EXPECT_NE(above.text.find("scaled by 2^"), std::string::npos) << above.text;
    EXPECT_NE(above.text.find("PD (floating filter"), std::string::npos) << above.text;
    const C1Outcome below = w_form(Tz, w, alpha2 * (Rational(1) - pow10(-20)));
    EXPECT_FALSE(below.holds()) << below.text;
  }
}

// Form "delta": random taps (K may exceed L: taps beyond the horizon do not
// enter T_Δ), δ² random, against the unbalanced full matrix.
RC_GTEST_PROP(VerifyC1DeltaForm, AgreesWithTheUnbalancedFullMatrix, ()) {
  const int K = *rc::gen::inRange(1, 6), L = *rc::gen::inRange(1, 7);
  const int ny = *rc::gen::inRange(1, 4), nz = *rc::gen::inRange(1, 4);
  const Rational scale = pow10(*decade());
  Mat<Rational> taps = *gen::rational_matrix(K, ny * nz, gen::small_rational()) * scale;
  if (*rc::gen::inRange(0, 5) == 0) taps.setZero();
  const Rational delta2 = random_delta2() * scale * scale;
  const C1Outcome got = check_c1_delta_form(taps, L, ny, nz, delta2);
  const bool expected = full_psd(full_delta_matrix(taps, L, ny, nz, delta2));
  RC_CLASSIFY(expected, "holds");
  RC_LOG() << got.text << "\n";
  RC_ASSERT(got.holds() == expected);
}

// The Schur complement by the displacement recurrence (verify/certificate/
// tap_gram.h) equals d2·I − T Tᵀ (ny ≤ nz) or d2·I − TᵀT (ny > nz) of the
// written-out T_Δ, entry by entry, for K below, at and above L.
RC_GTEST_PROP(VerifyC1DeltaForm, TapGramRecurrenceEqualsTheDenseProduct, ()) {
  const int K = *rc::gen::inRange(1, 9), L = *rc::gen::inRange(1, 9);
  const int ny = *rc::gen::inRange(1, 4), nz = *rc::gen::inRange(1, 4);
  const Mat<Rational> taps = *gen::rational_matrix(K, ny * nz, gen::small_rational());
  const Rational d2 = *gen::small_rational();
  const Mat<Rational> T = dense_tap_toeplitz(taps, L, ny, nz);
  const Mat<Rational> gram = ny <= nz ? Mat<Rational>(T * T.transpose()) : Mat<Rational>(T.transpose() * T);
  const Mat<Rational> expected = d2 * Mat<Rational>::Identity(gram.rows(), gram.cols()) - gram;
  const Mat<Rational> got = tap_gram_complement(taps, L, ny, nz, d2);
  RC_ASSERT(got.rows() == expected.rows());
  RC_ASSERT(got.cols() == expected.cols());
  for (Eigen::Index i = 0; i < got.rows(); ++i)
    for (Eigen::Index j = 0; j < got.cols(); ++j) RC_ASSERT(got(i, j) == expected(i, j));
}

// A single scalar tap h: T_Δ = h·I, ‖T_Δ‖ = |h|, so (C1) holds iff δ² ≥ h².
RC_GTEST_PROP(VerifyC1DeltaForm, SingleTapBoundary, ()) {
  const int L = *rc::gen::inRange(1, 5);
  const Rational h = *gen::small_rational() * pow10(*rc::gen::element(0, 300, -300, 1000, -1000));
  Mat<Rational> taps(1, 1);
  taps(0, 0) = h;
  const Rational eps = pow10(-40);
  for (const auto& [delta2, expected] : std::vector<std::pair<Rational, bool>>{
           {h * h, true}, {h * h * (Rational(1) - eps), h == 0}, {h * h * (Rational(1) + eps), true}}) {
    const C1Outcome got = check_c1_delta_form(taps, L, 1, 1, delta2);
    RC_LOG() << got.text << "\n";
    RC_ASSERT(got.holds() == expected);
  }
}

// One rank-one tap Δ_0 = u vᵀ (ny × nz): T_Δ = blockdiag(Δ_0), ‖T_Δ‖² =
// |u|²|v|² exactly, so (C1) holds at δ² = |u|²|v|² and fails just below, in
// both Schur orientations (ny ≤ nz and ny > nz).
RC_GTEST_PROP(VerifyC1DeltaForm, RankOneTapBoundary, ()) {
  const int L = *rc::gen::inRange(1, 5);
  const int ny = *rc::gen::inRange(1, 4), nz = *rc::gen::inRange(1, 4);
  const Mat<Rational> u = *gen::rational_matrix(ny, 1, gen::small_rational());
  const Mat<Rational> v = *gen::rational_matrix(nz, 1, gen::small_rational());
  Mat<Rational> taps(1, ny * nz);
  for (int i = 0; i < ny; ++i)
    for (int j = 0; j < nz; ++j) taps(0, i * nz + j) = u(i, 0) * v(j, 0);
  const Rational norm2 = (u.transpose() * u)(0, 0) * (v.transpose() * v)(0, 0);
  RC_PRE(norm2 > 0);
  const C1Outcome at = check_c1_delta_form(taps, L, ny, nz, norm2);
  RC_LOG() << at.text << "\n";
  RC_ASSERT(at.holds());
  const C1Outcome below = check_c1_delta_form(taps, L, ny, nz, norm2 * (Rational(1) - pow10(-30)));
  RC_LOG() << below.text << "\n";
  RC_ASSERT(!below.holds());
}

// A hostile input: δ² = 10^−5000 on a horizon of 40 samples.
TEST(VerifyC1DeltaForm, TinyDeltaSquaredIsDecidedAtOnce) {
  const Rational delta2 = pow10(-5000);
  Mat<Rational> taps = Mat<Rational>::Zero(3, 1);
  const C1Outcome zero = check_c1_delta_form(taps, 40, 1, 1, delta2);
  EXPECT_TRUE(zero.holds()) << zero.text;
  EXPECT_NE(zero.text.find("T_Delta = 0"), std::string::npos) << zero.text;  // no taps: decided without a scale
  taps(1, 0) = Rational(1, 1000);
  const C1Outcome big = check_c1_delta_form(taps, 40, 1, 1, delta2);
  EXPECT_FALSE(big.holds());
  EXPECT_NE(big.text.find("tap 1 entry (0,0)"), std::string::npos) << big.text;
  taps(1, 0) = pow10(-2501);  // |h| < δ: the norm of T_Δ = h·S decides
  taps(2, 0) = pow10(-2501);
  const C1Outcome small = check_c1_delta_form(taps, 40, 1, 1, delta2);
  EXPECT_TRUE(small.holds()) << small.text;
  EXPECT_NE(small.text.find("s = 2^-8305"), std::string::npos) << small.text;
  taps(0, 0) = Rational(9, 10) * pow10(-2500);  // ‖T_Δ‖ ≈ 1.1·δ > δ
  const C1Outcome over = check_c1_delta_form(taps, 40, 1, 1, delta2);
  EXPECT_FALSE(over.holds()) << over.text;
}

TEST(VerifyPowerOfTwo, MagnitudeAndSqrtScale) {
  EXPECT_EQ(power_of_two(3), Rational(8));
  EXPECT_EQ(power_of_two(-2), Rational(1, 4));
  EXPECT_FALSE(binary_magnitude(Rational(0)).has_value());
  for (const Rational& q : {Rational(1), Rational(3), Rational(1, 3), Rational(1000), pow10(-5000), pow10(4000)}) {
    const long e = *binary_magnitude(q);
    EXPECT_LT(power_of_two(e - 1), q);
    EXPECT_LT(q, power_of_two(e + 1));
    const Rational s = sqrt_scale(q);
    EXPECT_LT(q / (s * s), Rational(4));
    EXPECT_GT(q / (s * s), Rational(1, 4));
  }
}

}  // namespace
}  // namespace lpvid
