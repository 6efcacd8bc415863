// The exact FIR convolution and its adjoint (toeplitz/exact_convolution.h,
// used by apply_fir_records / fir_adjoint_records for Rational) against the
// formulas written out term by term, for several records, on both the
// common-denominator path and its fall-back (unrelated prime denominators).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "support/gen_numbers.h"
#include "toeplitz/exact_convolution.h"
#include "toeplitz/record_segments.h"

using namespace lpvid;

namespace {

/// w_j = Σ_{l ≤ j − m'} h_l z_{j−l} per record (record_segments.h), term by term.
Mat<Rational> convolution_by_definition(const Mat<Rational>& taps, const Mat<Rational>& z, Eigen::Index ny, Eigen::Index L,
                                        const RecordLengths& lengths) {
  const Eigen::Index nz = z.cols();
  Mat<Rational> w = Mat<Rational>::Zero(z.rows(), ny);
  Eigen::Index s = 0;
  for (const Eigen::Index n : lengths) {
    const Eigen::Index m = std::max<Eigen::Index>(0, n - L);
    for (Eigen::Index k = m; k < n; ++k)
      for (Eigen::Index l = 0; l <= k - m && l < taps.rows(); ++l)
        for (Eigen::Index i = 0; i < ny; ++i)
          for (Eigen::Index j = 0; j < nz; ++j) w(s + k, i) = w(s + k, i) + taps(l, i * nz + j) * z(s + k - l, j);
    s += n;
  }
  return w;
}

/// The i-th prime from 1009 on: denominators with a huge common multiple.
Rational over_prime(int numerator, int i) {
  static const std::vector<int> primes = [] {
    std::vector<int> p;
    for (int c = 1009; p.size() < 400; ++c) {
      bool prime = true;
      for (int d = 2; d * d <= c; ++d) prime = prime && c % d != 0;
      if (prime) p.push_back(c);
    }
    return p;
  }();
  return Rational(numerator) / Rational(primes[static_cast<size_t>(i) % primes.size()]);
}

struct Case {
  Mat<Rational> taps, z, g;
  RecordLengths lengths;
  Eigen::Index ny = 1, L = 1;
};

Case random_case(bool unrelated_denominators) {
  Case c;
  const int records = *rc::gen::inRange(1, 4), nz = *rc::gen::inRange(1, 3);
  c.ny = *rc::gen::inRange(1, 3);
  Eigen::Index n = 0;
  for (int r = 0; r < records; ++r) c.lengths.push_back(*rc::gen::inRange(unrelated_denominators ? 40 : 1, unrelated_denominators ? 60 : 30));
  for (const Eigen::Index l : c.lengths) n += l;
  c.L = *rc::gen::inRange<Eigen::Index>(1, *std::max_element(c.lengths.begin(), c.lengths.end()) + 1);
  const int K = *rc::gen::inRange<int>(1, static_cast<int>(c.L) + 1);
  c.taps = *gen::rational_matrix(K, static_cast<int>(c.ny) * nz, gen::small_rational());
  c.z = *gen::rational_matrix(static_cast<int>(n), nz, gen::small_rational());
  c.g = *gen::rational_matrix(static_cast<int>(n), static_cast<int>(c.ny), gen::small_rational());
  if (unrelated_denominators)
    for (Eigen::Index i = 0; i < n; ++i) {
      c.z(i, 0) = over_prime(*rc::gen::inRange(1, 10), static_cast<int>(i));  // 40+ distinct primes: > 400 bits
      c.g(i, 0) = over_prime(*rc::gen::inRange(1, 10), static_cast<int>(i) + 7);
    }
  return c;
}

void check_case(const Case& c, bool expect_integer_path) {
  Mat<Rational> direct;
  RC_ASSERT(apply_fir_records_exact(c.taps, c.z, c.ny, c.L, c.lengths, direct) == expect_integer_path);
  const Mat<Rational> w = apply_fir_records(c.taps, c.z, c.ny, c.L, c.lengths);
  RC_ASSERT(w == convolution_by_definition(c.taps, c.z, c.ny, c.L, c.lengths));
  // The adjoint: ⟨g, Δ∗z⟩ = Σ_l ⟨h_l, C_l(g)⟩ for every h, exactly (here the taps padded to L).
  Mat<Rational> h = Mat<Rational>::Zero(c.L, c.taps.cols());
  h.topRows(c.taps.rows()) = c.taps;
  const Mat<Rational> C = fir_adjoint_records(c.g, c.z, c.L, c.lengths);
  RC_ASSERT(C.rows() == c.L);
  Rational lhs(0), rhs(0);
  const Mat<Rational> wl = convolution_by_definition(h, c.z, c.ny, c.L, c.lengths);
  for (Eigen::Index i = 0; i < c.g.rows(); ++i)
    for (Eigen::Index j = 0; j < c.g.cols(); ++j) lhs += c.g(i, j) * wl(i, j);
  for (Eigen::Index i = 0; i < h.rows(); ++i)
    for (Eigen::Index j = 0; j < h.cols(); ++j) rhs += h(i, j) * C(i, j);
  RC_ASSERT(lhs == rhs);
}

}  // namespace

RC_GTEST_PROP(ExactConvolution, CommonDenominatorSumsEqualTheTermByTermFormula, ()) {
  check_case(random_case(false), true);
}

RC_GTEST_PROP(ExactConvolution, UnrelatedDenominatorsFallBackToTheSameNumbers, ()) {
  check_case(random_case(true), false);
}
