#pragma once
/// A parameter-dependent matrix M(ρ) = Σ_j g_j(ρ) M_j (paper eq. 9, 10).

#include <vector>

#include "core/scalar.h"
#include "model/monomial.h"

namespace lpvid {

template <typename T>
struct ParamTerm {
  Monomial basis;
  Mat<T> value;
};

/// rows × cols matrix function of ρ; no terms means identically zero.
template <typename T>
struct ParamMatrix {
  Eigen::Index rows = 0;
  Eigen::Index cols = 0;
  std::vector<ParamTerm<T>> terms;

  ParamMatrix() = default;
  ParamMatrix(Eigen::Index r, Eigen::Index c) : rows(r), cols(c) {}

  /// M(ρ) for one sample ρ.
  Mat<T> at(const Vec<T>& rho) const {
    Mat<T> m;
    at_into(rho, m);
    return m;
  }

  /// M(ρ) written into `m` (resized only when its size differs, so a loop
  /// over samples allocates it once); the same operations as at().
  void at_into(const Vec<T>& rho, Mat<T>& m) const {
    m.setZero(rows, cols);
    for (const auto& t : terms) m += t.basis.template eval<T>(rho) * t.value;
  }

  /// Adds f(ρ)·M (same size required; throws std::invalid_argument otherwise).
  void add(const Monomial& f, const Mat<T>& value) {
    if (value.rows() != rows || value.cols() != cols)
      throw std::invalid_argument("ParamMatrix::add: size mismatch");
    terms.push_back({f, value});
  }

  bool empty() const { return terms.empty(); }
};

}  // namespace lpvid
