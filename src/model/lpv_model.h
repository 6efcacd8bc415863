#pragma once
/// The LPV model of docs/design.md §5 (paper eq. 1 with G11 = 0, G21 = I, and eq. 8–10):
///
///   x_{k+1} = A(ρ_k) x_k + B(ρ_k) u_k + E(ρ_k)   (E: state_offset, zero by default)
///   z_k     = C1(ρ_k) x_k + D1(ρ_k) u_k      (uncertainty channel)
///   y_k     = C2(ρ_k) x_k + D2(ρ_k) u_k + w_k + d_k + Φ(ρ_k)
///
/// A, B, C2, D2 hold the initial model S_I *and* any known correction terms
/// (a certificate stores the identified model with θ folded in). The unknown
/// correction S_C of Theorem 3.1 is described by `correction` (basis f_i and
/// the fixed A_i, B_i); its C_i, D_i are solver unknowns, not stored here.

#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/column_map.h"
#include "data/signal_info.h"
#include "model/monomial.h"
#include "model/param_matrix.h"
#include "model/static_blocks.h"

namespace lpvid {

enum class UncertaintyStructure {
  kMultiplicative,  ///< z = W·ŷ: C1 = W·C2, D1 = W·D2 (default, W = 1)
  kAdditive,        ///< z = W·u: C1 = 0, D1 = W·I (nz = nu)
  kGeneral,         ///< C1, D1 given explicitly (`c1`, `d1` below)
};

const char* to_string(UncertaintyStructure s);

template <typename T>
struct Uncertainty {
  UncertaintyStructure structure = UncertaintyStructure::kMultiplicative;
  T weight = T(1);        ///< W (docs/design.md §5.3: "weight": 0.01 means 1 % relative)
  ParamMatrix<T> C1, D1;  ///< only for kGeneral (nz × nx, nz × nu)
};

/// Unknown correction S_C (paper eq. 10): basis f_i and fixed A_i, B_i.
template <typename T>
struct Correction {
  std::vector<Monomial> basis;
  std::vector<Mat<T>> A;  ///< A_i (nx × nx) per basis function; zero by default
  std::vector<Mat<T>> B;  ///< B_i (nx × nu) per basis function; zero by default
};

/// A correction over `basis` whose fixed parts A_i, B_i are all zero (the
/// unknowns C_i, D_i are what identification adds on top).
template <typename T>
Correction<T> zero_correction(const std::vector<Monomial>& basis, Eigen::Index nx, Eigen::Index nu) {
  Correction<T> c;
  c.basis = basis;
  c.A.assign(basis.size(), Mat<T>::Zero(nx, nx));
  c.B.assign(basis.size(), Mat<T>::Zero(nx, nu));
  return c;
}

/// Output offset Φ(ρ) = Σ_j h_j(ρ) φ_j (paper eq. 20). `values` empty means
/// the φ_j are unknown (identified); otherwise one ny-vector per basis fn.
template <typename T>
struct Offset {
  std::vector<Monomial> basis;
  std::vector<Vec<T>> values;
};

/// Affine term of the state equation (beyond the paper, docs/design.md §5.4):
/// E(ρ) = Σ_j h_j(ρ) e_j, e_j ∈ R^nx, so x_{k+1} = A(ρ_k) x_k + B(ρ_k) u'_k + E(ρ_k).
/// With a scheduling column "@sqrt(x1-c)" (model/state_scheduling.h) a basis
/// term ρ with value e adds e·√|x1 − c|: a tank's outflow. The values are
/// always given (no unknowns: Theorem 3.1's state must not depend on θ).
/// Empty basis: no term.
template <typename T>
struct StateOffset {
  std::vector<Monomial> basis;
  std::vector<Vec<T>> values;  ///< one nx-vector per basis function

  bool empty() const { return basis.empty() && values.empty(); }
};

template <typename T>
struct LpvModel {
  int nx = 0, nu = 0, ny = 0;
  std::vector<std::string> scheduling;  ///< names of ρ components (may be empty: LTI)
  ColumnMap columns;

  ParamMatrix<T> A, B, C, D;  ///< A (nx×nx), B (nx×nu), C = C2 (ny×nx), D = D2 (ny×nu)
  Correction<T> correction;
  Uncertainty<T> uncertainty;
  Offset<T> offset;
  StateOffset<T> state_offset;  ///< E(ρ) in the state equation; none by default
  Vec<T> x0;  ///< length nx; zero unless given
  /// Initial states of records 2, 3, … of the several-record data the model
  /// was fitted on (each record its own x0; x0 is record 1's). Empty for one
  /// record and in a model read from a file, which holds x0 alone. simulate()
  /// starts record k ≥ 2 from later_x0[k-2] when the data give no initial
  /// state of their own (Experiment::record_x0) and the entry has nx values.
  std::vector<Vec<T>> later_x0;
  StaticBlocks<T> statics;  ///< input delay, static input/output maps (model/static_blocks.h); none by default
  SignalInfo signal_info;   ///< sample time and units (plots and reports only)

  int n_rho() const { return static_cast<int>(scheduling.size()); }
  /// Size of the uncertainty channel z (ny for multiplicative, nu for additive,
  /// rows of C1 for general).
  int nz() const;
};

/// Converts every number of a model from one scalar to another (e.g. the
/// exact model to double for the solver path).
template <typename To, typename From>
LpvModel<To> convert_model(const LpvModel<From>& m);

}  // namespace lpvid
