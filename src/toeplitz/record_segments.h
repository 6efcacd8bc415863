#pragma once
/// Several records (experiments) of one system under one uncertainty Δ,
/// stacked row-wise in one signal matrix: record k holds rows
/// [start_k, start_k + n_k), start_k = n_1 + … + n_{k−1}. Each record starts
/// from rest for Δ (docs/several_records.md), so Δ ∗ z is taken record by
/// record, and Theorem 2.1's horizon is the longest record's
/// L = max_k (n_k − m_k), m_k the leading zero samples of record k's z.
/// An empty list means one record of all rows: every function below then
/// computes exactly what the one-record formulas of the paper give.
/// Templated on the scalar (double for the solvers, Rational for the verifier).

#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "core/scalar.h"
#include "toeplitz/exact_convolution.h"
#include "toeplitz/record_lengths.h"

namespace lpvid {

/// Number of leading rows k of z.middleRows(first, count) with z_k = 0 exactly.
template <typename T>
Eigen::Index leading_zero_rows(const Mat<T>& z, Eigen::Index first, Eigen::Index count) {
  Eigen::Index m = 0;
  while (m < count) {
    for (Eigen::Index j = 0; j < z.cols(); ++j)
      if (z(first + m, j) != T(0)) return m;
    ++m;
  }
  return m;
}

/// Theorem 2.1's horizon over the records: max_k (n_k − m_k) (0 when every
/// record's z is zero). One record: n − m.
template <typename T>
Eigen::Index records_horizon(const Mat<T>& z, const RecordLengths& lengths_in) {
  const RecordLengths lengths = record_lengths_of(lengths_in, z.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  Eigen::Index L = 0;
  for (size_t k = 0; k < lengths.size(); ++k)
    L = std::max(L, lengths[k] - leading_zero_rows(z, start[k], lengths[k]));
  return L;
}

/// w = Δ ∗ z record by record on the horizon L: in record k (rows start_k …),
/// w_j = Σ_{l=0}^{min(j − m'_k, K−1)} h_l z_{j−l} for j ≥ m'_k = max(0, n_k − L),
/// 0 before. `taps` is K × (ny·nz) (K ≤ L), row l = h_l row-major. One
/// record: the convolution of the paper's Poolla form with m' = n − L.
/// Callers check that each record's z is 0 before its m'_k. Exact sums go
/// through integers over common denominators (toeplitz/exact_convolution.h).
template <typename T>
Mat<T> apply_fir_records(const Mat<T>& taps, const Mat<T>& z, Eigen::Index ny, Eigen::Index horizon,
                         const RecordLengths& lengths_in) {
  if constexpr (std::is_same_v<T, Rational>) {
    Mat<Rational> exact;
    if (apply_fir_records_exact(taps, z, ny, horizon, lengths_in, exact)) return exact;
  }
  const RecordLengths lengths = record_lengths_of(lengths_in, z.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  const Eigen::Index nz = z.cols(), K = taps.rows();
  Mat<T> w = Mat<T>::Zero(z.rows(), ny);
  for (size_t r = 0; r < lengths.size(); ++r) {
    const Eigen::Index s = start[r], m = std::max<Eigen::Index>(0, lengths[r] - horizon);
    for (Eigen::Index k = m; k < lengths[r]; ++k)
      for (Eigen::Index l = 0; l <= k - m && l < K; ++l)
        for (Eigen::Index i = 0; i < ny; ++i) {
          T acc(0);
          for (Eigen::Index j = 0; j < nz; ++j) acc += taps(l, i * nz + j) * z(s + k - l, j);
          w(s + k, i) += acc;
        }
  }
  return w;
}

/// The adjoint of apply_fir_records: C_l(g) = Σ_records Σ_{j ≥ m'_k + l}
/// g_j z_{j−l}ᵀ for l = 0 … L−1 (⟨g, Δ∗z⟩ = Σ_l ⟨h_l, C_l(g)⟩). g is n × ny,
/// z is n × nz. Returns L × (ny·nz), row l = C_l row-major.
template <typename T>
Mat<T> fir_adjoint_records(const Mat<T>& g, const Mat<T>& z, Eigen::Index horizon, const RecordLengths& lengths_in) {
  if constexpr (std::is_same_v<T, Rational>) {
    Mat<Rational> exact;
    if (fir_adjoint_records_exact(g, z, horizon, lengths_in, exact)) return exact;
  }
  const RecordLengths lengths = record_lengths_of(lengths_in, z.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  const Eigen::Index nz = z.cols(), ny = g.cols();
  Mat<T> c = Mat<T>::Zero(horizon, ny * nz);
  for (size_t r = 0; r < lengths.size(); ++r) {
    const Eigen::Index s = start[r], n = lengths[r], m = std::max<Eigen::Index>(0, n - horizon);
    for (Eigen::Index l = 0; l < horizon; ++l)
      for (Eigen::Index k = m + l; k < n; ++k)
        for (Eigen::Index i = 0; i < ny; ++i) {
          if (g(s + k, i) == T(0)) continue;
          for (Eigen::Index j = 0; j < nz; ++j) c(l, i * nz + j) += g(s + k, i) * z(s + k - l, j);
        }
  }
  return c;
}

}  // namespace lpvid
