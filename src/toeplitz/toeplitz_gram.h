#pragma once
/// Gram matrices of signal Toeplitz matrices, T_aᵀ T_b (paper eq. 3, 7, 11),
/// in O(n²·p) operations instead of the O(n³·p) of the plain product.
///
/// For signals a, b (n × p, row k = a_kᵀ) and T as in eq. (3),
///   G_ij = (T_aᵀ T_b)_ij = Σ_{k = max(i,j)}^{n−1} a_{k−i}ᵀ b_{k−j},
/// so G depends only on the sums along each diagonal, and
///   G_{i, j} = G_{i+1, j+1} + a_{n−1−i}ᵀ b_{n−1−j}
/// with G_{n−1, j} = a_0ᵀ b_{n−1−j} and G_{i, n−1} = a_{n−1−i}ᵀ b_0.
/// Templated on the scalar; exact over ℚ.

#include <stdexcept>

#include "core/scalar.h"

namespace lpvid {

/// T_aᵀ T_b, n × n, for n × p signals a, b (same n and p).
template <typename T>
Mat<T> toeplitz_gram(const Mat<T>& a, const Mat<T>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols())
    throw std::invalid_argument("toeplitz_gram: signals have different sizes");
  const Eigen::Index n = a.rows();
  Mat<T> G(n, n);
  if (n == 0) return G;
  auto dot = [&](Eigen::Index ka, Eigen::Index kb) {
    T s(0);
    for (Eigen::Index r = 0; r < a.cols(); ++r) s += a(ka, r) * b(kb, r);
    return s;
  };
  // Last row and last column, then every diagonal from the bottom right up:
  // G_ij = G_{i+1,j+1} + a_{n−1−i}ᵀ b_{n−1−j} (the k = n−1 term).
  for (Eigen::Index j = 0; j < n; ++j) G(n - 1, j) = dot(0, n - 1 - j);
  for (Eigen::Index i = 0; i < n - 1; ++i) G(i, n - 1) = dot(n - 1 - i, 0);
  for (Eigen::Index i = n - 2; i >= 0; --i)
    for (Eigen::Index j = n - 2; j >= 0; --j) G(i, j) = G(i + 1, j + 1) + dot(n - 1 - i, n - 1 - j);
  return G;
}

}  // namespace lpvid
