#pragma once
/// Signal Toeplitz matrices (paper eq. 3, docs/design.md §6.1) and the stacked-vector
/// convention of docs/design.md §4. Templated on the scalar; no tolerance (docs/design.md §13.4).
///
/// A signal h_0 … h_{n−1} with h_k ∈ R^p is held as an n × p matrix whose
/// row k is h_kᵀ (as in Experiment and Simulation).

#include <stdexcept>
#include <string>

#include "core/scalar.h"

namespace lpvid {

/// Eq. (3): T_h, (n·p) × n, block (k, j) = h_{k−j} (a p × 1 column) for
/// k ≥ j, zero above the block diagonal. For p = 1 it is the lower-triangular
/// Toeplitz matrix of h, so T_a·T_b = T_{a∗b} (truncated convolution).
/// `h` is n × p, row k = h_kᵀ.
template <typename T>
Mat<T> signal_toeplitz(const Mat<T>& h) {
  const Eigen::Index n = h.rows(), p = h.cols();
  Mat<T> out = Mat<T>::Zero(n * p, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index k = j; k < n; ++k)
      out.block(k * p, j, p, 1) = h.row(k - j).transpose();
  return out;
}

/// Stacked vector [h_0; h_1; …; h_{n−1}] (length n·p) of an n × p signal
/// (docs/design.md §4). Column 0 of signal_toeplitz(h) equals stack_rows(h).
template <typename T>
Vec<T> stack_rows(const Mat<T>& h) {
  const Eigen::Index n = h.rows(), p = h.cols();
  Vec<T> v(n * p);
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index r = 0; r < p; ++r) v(k * p + r) = h(k, r);
  return v;
}

/// Inverse of stack_rows: the n × p signal of a stacked vector of length n·p.
/// Throws std::invalid_argument if p < 1 or p does not divide the length.
template <typename T>
Mat<T> unstack_rows(const Vec<T>& v, Eigen::Index p) {
  if (p < 1 || v.size() % p != 0)
    throw std::invalid_argument("unstack_rows: length " + std::to_string(v.size()) +
                                " is not a multiple of the signal dimension " + std::to_string(p));
  const Eigen::Index n = v.size() / p;
  Mat<T> h(n, p);
  for (Eigen::Index k = 0; k < n; ++k)
    for (Eigen::Index r = 0; r < p; ++r) h(k, r) = v(k * p + r);
  return h;
}

}  // namespace lpvid
