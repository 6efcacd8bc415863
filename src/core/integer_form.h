#pragma once
/// Exact sums of products of rationals in integers over one common
/// denominator, reduced once per result, instead of one gcd per product and
/// per addition. The same rational numbers (a sum of rationals is exact
/// whichever way it is formed), so no verdict or certificate depends on
/// which way was taken. Where the numbers carry thousands of digits (the
/// residual of an exactly simulated LPV model, a dual g projected exactly off
/// the free columns of a class) the gcds are most of the cost.
///
/// Common denominators can be far larger than any single one when the
/// denominators are unrelated (lcm of 2, 3, 5, 7, …): then integer_form
/// refuses and the functions below sum rational by rational.

#include <memory>

#include "core/gmp_raii.h"
#include "core/scalar.h"

namespace lpvid {

/// A rational matrix as integer numerators over one common denominator
/// (entry (i, j) = at(i, j) / den).
struct IntegerForm {
  Eigen::Index rows = 0, cols = 0;
  MpzArray num;
  Mpz den;
  explicit IntegerForm(const Mat<Rational>& m) : rows(m.rows()), cols(m.cols()), num(static_cast<std::size_t>(m.size())) {}
  mpz_srcptr at(Eigen::Index i, Eigen::Index j) const { return num[static_cast<std::size_t>(i * cols + j)]; }
};

/// The integer form of `m`, or null when the common denominator has more
/// than 4× the bits of the largest single denominator (+ 256 bits).
std::unique_ptr<IntegerForm> integer_form(const Mat<Rational>& m);

/// sum / (a.den · b.den) as a reduced Rational (q: scratch).
Rational over_product(mpz_srcptr sum, const IntegerForm& a, const IntegerForm& b, Mpq& q);

/// Σ_ij a_ij·b_ij exactly (a and b of the same shape).
Rational exact_dot(const Mat<Rational>& a, const Mat<Rational>& b);

/// AᵀB exactly (A m × p, B m × q).
Mat<Rational> exact_transpose_product(const Mat<Rational>& a, const Mat<Rational>& b);

/// g − F·x exactly (g m × 1, F m × p, x p × 1), each entry reduced once.
Vec<Rational> exact_minus_product(const Vec<Rational>& g, const Mat<Rational>& F, const Vec<Rational>& x);

}  // namespace lpvid
