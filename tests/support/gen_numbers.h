#pragma once
/// Generators for exact numbers: small rationals and small-integer matrices.

#include <rapidcheck.h>

#include "core/scalar.h"

namespace lpvid::gen {

/// p/q with |p| <= 9*scale... small numerator, denominator in 1..9.
inline rc::Gen<Rational> small_rational() {
  return rc::gen::map(rc::gen::pair(rc::gen::inRange(-9, 10), rc::gen::inRange(1, 10)),
                      [](const std::pair<int, int>& pq) { return Rational(pq.first) / Rational(pq.second); });
}

/// Integer in [-4, 4] as a Rational (double and rational paths agree exactly).
inline rc::Gen<Rational> small_integer() {
  return rc::gen::map(rc::gen::inRange(-4, 5), [](int v) { return Rational(v); });
}

/// rows × cols matrix with entries from `entry`.
inline rc::Gen<Mat<Rational>> rational_matrix(int rows, int cols, rc::Gen<Rational> entry) {
  return rc::gen::map(rc::gen::container<std::vector<Rational>>(static_cast<size_t>(rows * cols), entry),
                      [rows, cols](const std::vector<Rational>& v) {
                        Mat<Rational> m(rows, cols);
                        for (int i = 0; i < rows; ++i)
                          for (int j = 0; j < cols; ++j) m(i, j) = v[static_cast<size_t>(i * cols + j)];
                        return m;
                      });
}

/// The 1 × 1 matrix [v].
inline Mat<Rational> scalar_matrix(int v) { return Mat<Rational>::Constant(1, 1, Rational(v)); }

/// Exact conversion Rational matrix -> double matrix (only for entries that
/// are exactly representable, e.g. small integers; tests use it that way).
inline Mat<double> to_double_matrix(const Mat<Rational>& m) {
  Mat<double> d(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) d(i, j) = CGAL::to_double(m(i, j));
  return d;
}

}  // namespace lpvid::gen
