#pragma once
/// The mathematics of a class claim (docs/class_lower_bound.md), exact: what
/// the verifier rebuilds and the builder (certify/class_dual.h) evaluates the
/// same way, so that a certificate the builder accepts is one the verifier accepts.
///
/// Theorem 3.1 of "Robust identification and invalidation of LPV systems" with
/// the residual affine in the parameters p (toeplitz/affine_residual.h):
/// z(p) = z0 + Jz p, r(p) = r0 − Jr p. For a leaf box p = p_c + e
/// (|e_i| ≤ ρ_i on the boxed coordinates, e_i free on the free ones, whose Jz
/// columns are zero) and a dual point (Y1, g, σ) of the fixed model p_c with
/// its dual equality at z(p_c), every feasible (Δ, t = δ², s = d_max²) of
/// every p in the leaf satisfies (weak duality, Lagrangian of (C1'), (C2)):
///   t·tr U + N·s·σ ≥ β(p_c) − 2|gᵀJr e| − 2|gᵀ T_Δ Jz e|
///                  ≥ β(p_c) − lin − c·√t,
///   lin = 2 Σ_{boxed} ρ_i |⟨Jr_i, g⟩|,  c ≥ 2‖g‖·Σ_{boxed} ρ_i ‖Jz_i‖
/// (‖T_Δ‖ ≤ √t by (C1'); the free terms vanish because g is first projected
/// onto the orthogonal complement of the free columns of Jr). With
/// c·√t ≤ c·t/(2ε) + c·ε/2 (any ε > 0) this is the fixed model's inequality
/// with tr U + c/(2ε) and β − lin − c·ε/2, and dual_bound gives the leaf's
/// lower end on every objective.

#include <string>
#include <vector>

#include "core/scalar.h"
#include "toeplitz/affine_residual.h"
#include "toeplitz/delta_form_dual.h"

namespace lpvid {

/// The class's exact affine signals and the split of its parameters.
struct ClassSignals {
  AffineResidual<Rational> a;
  std::vector<long> free, boxed;
  Mat<Rational> free_columns;  ///< N × |free|: the columns of Jr of the free parameters
  Eigen::Index horizon = 0;    ///< n − (leading samples where z0 and every column of Jz are zero)
};

/// Splits `a` by `free` (indices). Empty string when well posed; else why not
/// (a free parameter that moves z, an index out of range, z ≡ 0 for every p).
std::string class_signals(AffineResidual<Rational> a, const std::vector<long>& free, ClassSignals& out);

/// g − F (FᵀF)⁺ Fᵀ g exactly (g n × ny in the stacking of r, F = free_columns):
/// the orthogonal projection of g onto the complement of range(F).
Mat<Rational> project_out_free(const Mat<Rational>& g, const Mat<Rational>& free_columns);

/// z(p_c) (n × nz) and r(p_c) (n × ny).
Mat<Rational> class_z(const ClassSignals& s, const Vec<Rational>& center);
Mat<Rational> class_r(const ClassSignals& s, const Vec<Rational>& center);

/// lin and an upper bound c of the file comment for a leaf of radii ρ and the
/// projected g; `problem` set when a number leaves the range of a double.
struct ClassPenalty {
  Rational linear, bilinear;
  std::string problem;
};
ClassPenalty class_penalty(const ClassSignals& s, const Vec<Rational>& radius, const Mat<Rational>& g);

/// The fixed model's terms turned into the leaf's: tr U + c/(2ε), β − lin − c·ε/2.
DualTerms<Rational> leaf_terms(DualTerms<Rational> terms, const ClassPenalty& p, const Rational& epsilon);

}  // namespace lpvid
