#pragma once
/// Free linear unknowns in Theorem 2.1's noise residual: d = r − Δ∗z − G·q
/// with q ∈ R^P unconstrained (the identification class bound lets the model
/// parameters that enter the residual linearly move with Δ).
///
/// Layout of G: (n·ny) × P, column c the stacked signal of an n × ny matrix
/// g_c (the layout of r): row k·ny + i is output i at sample k, as
/// stack_rows (toeplitz/signal_toeplitz.h) and as d's rows 1 + k·ny + i in
/// (C2) (lmi/delta_form_lmi.h). Columns may be zero or dependent.
///
/// Minimising over q leaves d = P⊥(r − Δ∗z) with P⊥ = I − Q Qᵀ and Q an
/// orthonormal basis of range(G), found rank-revealingly: the nonzero columns
/// are normalised to unit length (their scales do not matter) and Q is the
/// left singular vectors of that matrix whose singular values exceed
/// kFreeRegressorRankTolerance times the largest. A column within that
/// tolerance of the span of the others (relative to its own length) adds
/// nothing; an exactly zero column adds nothing and gets the coefficient 0.

#include <string>

#include "core/scalar.h"

namespace lpvid {

inline constexpr double kFreeRegressorRankTolerance = 1e-10;

class FreeRegressors {
 public:
  FreeRegressors() = default;
  /// Throws std::invalid_argument when G has columns but not n·ny rows, or a
  /// non-finite entry (`what` names the caller).
  FreeRegressors(const Mat<double>& G, Eigen::Index n, Eigen::Index ny, const std::string& what);

  Eigen::Index count() const { return G_.cols(); }  ///< P
  Eigen::Index rank() const { return Q_.cols(); }   ///< columns of Q
  bool empty() const { return Q_.cols() == 0; }     ///< nothing to eliminate (P = 0 or G = 0)
  const Mat<double>& basis() const { return Q_; }   ///< Q: (n·ny) × rank, orthonormal
  const Mat<double>& matrix() const { return G_; }  ///< G as given (0 columns when P = 0) columns

  /// v ← P⊥ v = v − Q(Qᵀv) (v stacked like r), applied twice so that
  /// ‖Qᵀ(P⊥v)‖ is at rounding relative to ‖P⊥v‖, not to ‖v‖.
  void project(Vec<double>& v) const;
  /// The minimum-norm q with G q = Q Qᵀ e, i.e. argmin ‖e − G q‖ (over the
  /// numerical range above) of least norm, in G's coordinates (length P).
  Vec<double> coefficients(const Vec<double>& e) const;

 private:
  Mat<double> G_;
  Mat<double> Q_;     ///< orthonormal basis of range(G)
  Mat<double> pinv_;  ///< P × (n·ny): e ↦ a q with G q = Q Qᵀ e
  Mat<double> null_;  ///< P × (P − rank): orthonormal basis of G's null space in q
};

}  // namespace lpvid
