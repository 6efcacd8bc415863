#pragma once
/// The uncertainty channel z of docs/design.md §5 (paper eq. 1 with G11 = 0, eq. 8–10):
///
///   z_k = C1(ρ_k) x_k + D1(ρ_k) u_k          (nz rows)
///
/// by uncertainty structure (paper Section 3.1, docs/design.md §5.3):
///   multiplicative:  C1 = W·C,  D1 = W·D   so z = W·ŷ   (ŷ = C x + D u,
///                    *without* the output offset Φ; nz = ny)
///   additive:        C1 = 0,    D1 = W·I   so z = W·u   (nz = nu)
///   general:         C1, D1 as given in `model.uncertainty`
///
/// Both are returned as parameter-dependent matrices (ParamMatrix), so that
/// the same code evaluates them along a trajectory as A, B, C, D.
/// The C1_i, D1_i corrections of Theorem 3.1 are solver unknowns and are not
/// included (for the multiplicative structure they equal W·C_i, W·D_i, i.e.
/// ∂z/∂θ = W·∂ŷ/∂θ; see output_jacobian in model/simulate.h).

#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "core/scalar.h"
#include "model/lpv_model.h"
#include "model/param_matrix.h"

namespace lpvid {

namespace detail {

/// W·M (each term scaled).
template <typename T>
ParamMatrix<T> scaled(const ParamMatrix<T>& m, const T& w) {
  ParamMatrix<T> out(m.rows, m.cols);
  for (const auto& t : m.terms) out.terms.push_back({t.basis, (w * t.value).eval()});
  return out;
}

/// A model matrix checked to be rows × cols (and every term's value too);
/// a 0×0 matrix without terms means "not given" and becomes the zero matrix
/// of that size. Throws std::invalid_argument naming `name` otherwise.
template <typename T>
ParamMatrix<T> given_or_zero(const ParamMatrix<T>& m, Eigen::Index rows, Eigen::Index cols,
                             const std::string& name) {
  if (m.rows == 0 && m.cols == 0 && m.empty()) return ParamMatrix<T>(rows, cols);
  if (m.rows != rows || m.cols != cols)
    throw std::invalid_argument("model matrix " + name + " is " + shape_text(m.rows, m.cols) + ", expected " +
                                shape_text(rows, cols));
  for (size_t j = 0; j < m.terms.size(); ++j)
    if (m.terms[j].value.rows() != rows || m.terms[j].value.cols() != cols)
      throw std::invalid_argument("model matrix " + name + ": term " + std::to_string(j) + " is " +
                                  shape_text(m.terms[j].value.rows(), m.terms[j].value.cols()) + ", expected " +
                                  shape_text(rows, cols));
  return m;
}

}  // namespace detail

/// C1(ρ) of docs/design.md §5, nz × nx (see the file comment for each structure).
template <typename T>
ParamMatrix<T> uncertainty_C1(const LpvModel<T>& model) {
  const Eigen::Index nz = model.nz();
  switch (model.uncertainty.structure) {
    case UncertaintyStructure::kMultiplicative:
      return detail::scaled(detail::given_or_zero(model.C, model.ny, model.nx, "C"), model.uncertainty.weight);
    case UncertaintyStructure::kAdditive:
      return ParamMatrix<T>(nz, model.nx);  // identically zero
    case UncertaintyStructure::kGeneral:
      return detail::given_or_zero(model.uncertainty.C1, nz, model.nx, "uncertainty C1");
  }
  throw std::invalid_argument("unknown uncertainty structure");
}

/// D1(ρ) of docs/design.md §5, nz × nu (see the file comment for each structure).
template <typename T>
ParamMatrix<T> uncertainty_D1(const LpvModel<T>& model) {
  const Eigen::Index nz = model.nz();
  switch (model.uncertainty.structure) {
    case UncertaintyStructure::kMultiplicative:
      return detail::scaled(detail::given_or_zero(model.D, model.ny, model.nu, "D"), model.uncertainty.weight);
    case UncertaintyStructure::kAdditive: {
      ParamMatrix<T> d1(nz, model.nu);
      const Mat<T> wI = model.uncertainty.weight * Mat<T>::Identity(nz, model.nu);
      d1.add(constant_monomial(static_cast<size_t>(model.n_rho())), wI);
      return d1;
    }
    case UncertaintyStructure::kGeneral:
      return detail::given_or_zero(model.uncertainty.D1, nz, model.nu, "uncertainty D1");
  }
  throw std::invalid_argument("unknown uncertainty structure");
}

}  // namespace lpvid
