#pragma once
/// The compact dual certificate of the full-horizon Δ form ("dual_delta_path";
/// docs/dual_certificates.md, "The compact form"): a dual point whose size
/// grows linearly with the record, rebuilt by the verifier from a recipe.
///
/// A barrier method's dual point is μ·C1⁻¹ (lmi/delta_form_barrier.h):
///   Y1 = [I; −Tᵀ] U [I; −Tᵀ]ᵀ + diag(0, μI),   U = μ (t·I − T Tᵀ)⁻¹,
/// i.e. it is fixed by the taps h of T, t and μ. The certificate stores those
/// (L·ny·nz + 2 numbers) instead of the L·(ny+nz)-square Y1, and the verifier
/// builds the point itself:
///  1. U_d = μ (t·I − T Tᵀ)⁻¹ in floating point (any value would do: nothing
///     below trusts it), rounded to the integer grid Ũ = round(U_d·2^−e), so
///     U = Ũ·2^e exactly;
///  2. the residual of the dual equality for W0 = −UT,
///       R_l = C_l(g) + Ω_l(UT)          (l = 0 … L−1),
///     is removed by E with blocks E_{(b+l), b} = R_l/(L − l) (exactly as the
///     dense builder spreads it), so that W = E − UT satisfies Ω_l(W) = C_l(g);
///  3. the dual point is
///       Y1 = J [U, E; Eᵀ, x·I] Jᵀ,   J = [I, 0; −Tᵀ, I]   (x > 0),
///     with blocks U, W = E − UT and V = TᵀUT − TᵀE − EᵀT + x·I.
///     J is invertible, so Y1 ⪰ 0 ⇔ [U, E; Eᵀ, x·I] ⪰ 0 ⇔ U − EEᵀ/x ⪰ 0,
///     which holds when U − γ·I ⪰ 0 and ‖E‖_F² ≤ x·γ for the stored floor
///     γ ≥ 0 (since ‖EEᵀ‖ ≤ ‖E‖_F²): the first is decided exactly (the
///     rigorous filter on the exact integer matrix, then exact elimination),
///     the second is a rational inequality. (U is positive definite on the
///     central path, λ_min(U) ≈ μ/t, so a small floor is available; a margin
///     added to U instead would move W and the residual with it.)
///  4. tr U = 2^e·tr Ũ, tr V = tr(TᵀUT) − 2 Σ_l ⟨h_l, R_l⟩ + x·L·nz
///     (⟨Tᵀ, E⟩ = Σ_l ⟨h_l, R_l⟩), and the bound follows as for the dense
///     form (toeplitz/delta_form_dual.h).
/// The sums Ω_l(UT) = Σ_k D(l,k)·h_k and tr(TᵀUT) = Σ_{k,k'} h_kᵀ D(k,k') h_k'
/// use the partial block-diagonal sums D(l,k) = Σ_b U_{(b+l),(b+k)}
/// (D(l,k) = U_{l,k} + D(l+1,k+1)): O(L²) exact integer operations, with the
/// taps dyadic (h = H·2^f, H integer). Nothing is cubic in exact arithmetic.

#include <string>

#include "core/scalar.h"
#include "toeplitz/delta_form_dual.h"
#include "verify/psd/exact_psd.h"

namespace lpvid {

/// The recipe of a compact dual point (all exact; the taps dyadic).
struct PathDualRecipe {
  Mat<Rational> taps;   ///< L × (ny·nz), row l = h_l row-major: the T of the recipe and of J
  Rational t, mu;       ///< U_d = μ (t·I − T Tᵀ)⁻¹ (used in floating point only)
  long u_exponent = 0;  ///< e: U = Ũ·2^e, Ũ integer
  Rational x;           ///< the multiplier of the lower-right identity (> 0)
  Rational floor;       ///< γ ≥ 0: U − γ·I ⪰ 0 and ‖E‖_F² ≤ x·γ are required
};

/// The work of one compact dual point of order m = L·ny as the budget counts
/// it (its floating rebuild, m³; verify/certificate/work_budget.h): the
/// scale at which its stages are announced (verify/psd/check_progress.h).
inline double dual_step_work(Eigen::Index order) {
  const double m = static_cast<double>(order);
  return m * m * m;
}

/// Step 1: Ũ (integers held exactly in doubles, |Ũ| < 2^53), symmetric.
/// `problem` is non-empty when the recipe does not produce one (t·I − TTᵀ not
/// positive definite in floating point, or entries off the grid's range).
struct PathDualGrid {
  Mat<double> U;
  std::string problem;
};
PathDualGrid path_dual_grid(const PathDualRecipe& recipe, Eigen::Index ny, Eigen::Index nz);

/// The two halves of path_dual_grid, for the builder (which picks e from U_d):
/// U_d = μ (t·I − T Tᵀ)⁻¹ in floating point (empty with `problem` set on
/// failure), and its rounding to the grid 2^e.
Mat<double> path_dual_floating_u(const PathDualRecipe& recipe, Eigen::Index ny, Eigen::Index nz, std::string& problem);
PathDualGrid path_dual_round(const Mat<double>& U_d, long u_exponent);
/// The e that puts max |U_d| just below 2^52 grid units.
long path_dual_exponent(const Mat<double>& U_d);

/// The exact sums that do not depend on g or σ (U = Ũ·2^e):
/// Ω_l(U T) (L × ny·nz), tr(Tᵀ U T), tr U.
struct PathDualSums {
  Mat<Rational> omega_UT;
  Rational tr_TUT, tr_U;
  std::string problem;  ///< non-empty when a tap is not dyadic
};
PathDualSums path_dual_sums(const PathDualRecipe& recipe, const Mat<double>& U_grid, Eigen::Index ny, Eigen::Index nz);

/// Step 2's sums for one U (they depend neither on g's σ nor on x):
/// ‖E‖_F² = Σ_l ‖R_l‖²/(L − l) and Σ_l ⟨h_l, R_l⟩, with R_l = C_l(g) + Ω_l(UT)
/// (written to `R`, L × ny·nz, when given).
struct PathDualResidual {
  Rational E_norm2, h_dot_R;
};
PathDualResidual path_dual_residual(const PathDualRecipe& recipe, const PathDualSums& sums, const Mat<Rational>& C,
                                    Mat<Rational>* R = nullptr);

/// gᵀg and gᵀr (g and r n × ny).
struct GProducts {
  Rational gg, gr;
};
GProducts g_products(const Mat<Rational>& g, const Mat<Rational>& r);

/// Step 4: tr U, N·σ and β = −(tr V + gᵀg/σ + 2gᵀr), tr V = tr(TᵀUT) − 2 Σ⟨h_l, R_l⟩ + x·L·nz.
DualTerms<Rational> path_dual_terms(const PathDualRecipe& recipe, const PathDualSums& sums, const PathDualResidual& res,
                                    const GProducts& gp, const Rational& sigma, Eigen::Index N, Eigen::Index nz);

/// Steps 2 and 4 for g (n × ny), σ > 0, the residual r and C = fir_adjoint(g, z, L).
struct PathDualValue {
  Rational E_norm2;        ///< ‖E‖_F² = Σ_l ‖R_l‖²/(L − l)
  DualTerms<Rational> terms;
};
PathDualValue path_dual_value(const PathDualRecipe& recipe, const PathDualSums& sums, const Mat<Rational>& C,
                              const Mat<Rational>& g, const Rational& sigma, const Mat<Rational>& r, Eigen::Index ny,
                              Eigen::Index nz);

/// Step 3's PSD half: U − γ·I ⪰ 0 (filter on the exact integer matrix with
/// the diagonal rounded down; then, when `exact_fallback`, exact
/// elimination). Returns kNotPsd with the filter's reason when the filter
/// cannot prove it and the exact path is not asked for.
PsdResult path_dual_psd(const PathDualRecipe& recipe, const Mat<double>& U_grid, bool exact_fallback);

/// The dense Y1 of step 3 (tests and small cases: L·(ny+nz) square).
Mat<Rational> path_dual_expand(const PathDualRecipe& recipe, const Mat<double>& U_grid, const Mat<Rational>& R,
                               Eigen::Index ny, Eigen::Index nz);

}  // namespace lpvid
