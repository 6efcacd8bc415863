#pragma once
/// System Toeplitz matrix of an LPV system along a scheduling trajectory
/// (paper eq. 2, docs/design.md §6.2). Templated on the scalar; no tolerance (docs/design.md §13.4).

#include <stdexcept>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/param_matrix.h"
#include "model/simulate.h"

namespace lpvid {

/// Eq. (2), docs/design.md §6.2: T_G of x_{k+1} = A(ρ_k)x_k + B(ρ_k)u_k,
/// out_k = C(ρ_k)x_k + D(ρ_k)u_k along ρ (n × nρ, row k = ρ_kᵀ; pass an
/// n × 0 matrix when nρ = 0). Returns the (n·ny) × (n·nu) block lower
/// triangular matrix with
///   block (k, k) = D(ρ_k),
///   block (k, j) = C(ρ_k) A(ρ_{k−1}) ⋯ A(ρ_{j+1}) B(ρ_j)   for k > j,
/// so that the output from x_0 = 0 is stack(out) = T_G · stack(u).
/// (ny = C.rows, nu = B.cols, nx = A.rows.) Throws std::invalid_argument on
/// inconsistent sizes.
template <typename T>
Mat<T> system_toeplitz(const ParamMatrix<T>& A, const ParamMatrix<T>& B, const ParamMatrix<T>& C,
                       const ParamMatrix<T>& D, const Mat<T>& rho) {
  const Eigen::Index nx = A.rows, nu = B.cols, ny = C.rows, n = rho.rows();
  const int n_rho = static_cast<int>(rho.cols());
  auto size = [](Eigen::Index r, Eigen::Index c) { return std::to_string(r) + "x" + std::to_string(c); };
  if (A.cols != nx || B.rows != nx || C.cols != nx || D.rows != ny || D.cols != nu)
    throw std::invalid_argument("system_toeplitz: inconsistent sizes A " + size(A.rows, A.cols) + ", B " +
                                size(B.rows, B.cols) + ", C " + size(C.rows, C.cols) + ", D " +
                                size(D.rows, D.cols));
  // Validate the terms (sizes and basis functions against nρ).
  detail::check_terms(detail::given_or_zero(A, nx, nx, "A"), n_rho, "A");
  detail::check_terms(detail::given_or_zero(B, nx, nu, "B"), n_rho, "B");
  detail::check_terms(detail::given_or_zero(C, ny, nx, "C"), n_rho, "C");
  detail::check_terms(detail::given_or_zero(D, ny, nu, "D"), n_rho, "D");

  // The matrices at each sample, evaluated once.
  std::vector<Mat<T>> Ak, Bk, Ck;
  Mat<T> TG = Mat<T>::Zero(n * ny, n * nu);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Vec<T> r = detail::rho_at(rho, k);
    Ak.push_back(A.at(r));
    Bk.push_back(B.at(r));
    Ck.push_back(C.at(r));
    TG.block(k * ny, k * nu, ny, nu) = D.at(r);  // block (k, k) = D(ρ_k)
  }
  // Column block j: propagate P = A(ρ_{k−1}) ⋯ A(ρ_{j+1}) B(ρ_j) (nx × nu).
  for (Eigen::Index j = 0; j < n; ++j) {
    Mat<T> P = Bk[static_cast<size_t>(j)];
    for (Eigen::Index k = j + 1; k < n; ++k) {
      TG.block(k * ny, j * nu, ny, nu) = Ck[static_cast<size_t>(k)] * P;
      if (k + 1 < n) P = (Ak[static_cast<size_t>(k)] * P).eval();
    }
  }
  return TG;
}

/// Which input–output channel of the model (paper eq. 1, 4) a system
/// Toeplitz matrix is built for.
enum class SystemChannel {
  kOutput,       ///< G22: u → ŷ with C = C2, D = D2 (no offset)
  kUncertainty,  ///< G12: u → z with C1, D1 (model/uncertainty_channel.h)
};

/// Eq. (2) for the model (docs/design.md §5, with the fixed correction A_i, B_i in the
/// state equation) along ρ (n × nρ; n × 0 when nρ = 0):
/// T_G22 ((n·ny) × (n·nu)) or T_G12 ((n·nz) × (n·nu)). Maps u to the output
/// from x_0 = 0, whatever model.x0 says. Throws std::invalid_argument for a
/// model with a state offset (model.state_offset): T_G would silently drop it.
template <typename T>
Mat<T> system_toeplitz(const LpvModel<T>& model, const Mat<T>& rho, SystemChannel channel = SystemChannel::kOutput) {
  const SystemMatrices<T> s = system_matrices(model);
  if (has_state_offset(model))
    throw std::invalid_argument("system_toeplitz: the model has a state_offset E(rho), which T_G (a linear map of u, "
                                "eq. 2) cannot hold; paper mode does not support state_offset");
  if (rho.cols() != model.n_rho())
    throw std::invalid_argument("system_toeplitz: rho has " + std::to_string(rho.cols()) +
                                " columns, model has n_rho = " + std::to_string(model.n_rho()));
  if (channel == SystemChannel::kOutput) return system_toeplitz(s.A, s.B, s.C, s.D, rho);
  return system_toeplitz(s.A, s.B, s.C1, s.D1, rho);
}

/// As above along the experiment's ρ (n = number of samples of u).
template <typename T>
Mat<T> system_toeplitz(const LpvModel<T>& model, const Experiment<T>& exp,
                       SystemChannel channel = SystemChannel::kOutput) {
  check_experiment(model, exp);
  const Mat<T> rho = model.n_rho() == 0 ? Mat<T>(exp.n(), 0) : exp.rho;
  return system_toeplitz(model, rho, channel);
}

}  // namespace lpvid
