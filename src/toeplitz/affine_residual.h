#pragma once
/// The model-dependent signals of Theorems 2.1 and 3.1 as affine functions
/// of the unknown parameters p (docs/design.md §5, §8):
///
///   z(p) = z0 + Jz p        stacked uncertainty-channel signal (n·nz)
///   r(p) = r0 − Jr p        stacked residual y − ŷ − Φ (n·ny), = w + d
///
/// p = [θ_out | θ_unc | φ | x0]:
///   θ_out  the correction C_i, D_i of the output (eq. 10, layout of
///          output_correction_layout: basis major, C_i then D_i row-major);
///   θ_unc  for the `general` structure only, C1_i, D1_i of z (same layout, nz rows);
///   φ      the unknown offset values φ_j (eq. 20), j major, ny each;
///   x0     the change of the initial state from the model's x0, when free
///          (`--free-x0`): z0, r0 are simulated from the model's x0, so
///          x0 = model.x0 + p_x0 (apply_parameters adds it). Several
///          records (Experiment::records): each record's own initial state,
///          nx per record, record k's columns the response of record k alone
///          (zero on the other records' rows), names "x0[k](c)"; p_x0 is the
///          change from each record's own x0 (record_initial_states).
/// The state does not depend on θ (A_i, B_i are fixed), so all of this is
/// exact: the output is affine in θ, φ and x0. Exception: with a state
/// offset E(ρ) (model.state_offset) the x0 columns are the secant
/// sim(x0 + e_c) − sim(x0), an approximation; the certificate of the folded
/// model is still checked by its exact simulation.
/// Multiplicative structure: z = W·ŷ, so Jz = W·(∂ŷ/∂θ_out, ∂ŷ/∂x0), 0 for φ.

#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "toeplitz/record_segments.h"

namespace lpvid {

/// Which unknowns the identification has (besides w, δ², d_max²).
struct Unknowns {
  bool correction = true;  ///< C_i, D_i of the correction basis (Theorem 3.1)
  bool offset = true;      ///< φ_j, when the model declares an offset basis without values
  bool x0 = false;         ///< the initial state (`--free-x0`)
};

/// Where each kind of unknown sits in p (sizes of the four segments).
struct ParameterLayout {
  Eigen::Index n_theta_out = 0, n_theta_unc = 0, n_phi = 0, n_x0 = 0;
  /// Records whose initial states the x0 block holds (nx each): 1 = the
  /// model's x0 (one record); K ≥ 2 = each record's own (n_x0 = K·nx).
  Eigen::Index x0_records = 1;
  Eigen::Index size() const { return n_theta_out + n_theta_unc + n_phi + n_x0; }
};

template <typename T>
struct AffineResidual {
  Eigen::Index n = 0, ny = 0, nz = 0;
  RecordLengths records;  ///< the experiment's records (empty: one record of all n rows)
  Vec<T> z0, r0;
  Mat<T> Jz, Jr;
  ParameterLayout layout;
  std::vector<std::string> names;  ///< one per parameter, e.g. "C[rho2^2](1,1)"

  Eigen::Index num_params() const { return Jz.cols(); }
  Vec<T> z(const Vec<T>& p) const { return p.size() ? Vec<T>(z0 + Jz * p) : z0; }
  Vec<T> r(const Vec<T>& p) const { return p.size() ? Vec<T>(r0 - Jr * p) : r0; }
};

/// Why z(p) and r(p) are NOT affine in the unknowns for this model (empty
/// when they are). Every class claim of Theorem 3.1 (docs/class_lower_bound.md)
/// rests on that premise; the class bound is built and the verifier checks a
/// class certificate only when this is empty. The state does not depend on θ
/// or φ (A_i, B_i are fixed), so only a free initial state can break it:
///  - with a correction basis, ŷ = (C + Σ θ_i C_i)·x(x0) (and z = (C1 +
///    Σ θ_i C1_i)·x(x0) for `general`) holds the product θ_i·x0;
///  - a scheduling column that follows the state ("@x<i>", "@sqrt(x<i>-c)", …)
///    makes ρ, hence A(ρ), B(ρ), C(ρ), depend on x0;
///  - a state offset E(ρ) is simulated from x = 0 and, with state columns,
///    follows x: its x0 columns are secants (apply_parameters' comment).
/// A free x0 with none of these is affine (the response to x0 is the free
/// response of the fixed state equation along the measured ρ).
template <typename T>
std::string non_affine_unknowns(const LpvModel<T>& model, const Unknowns& unknowns);

/// Builds z0, r0, Jz, Jr for the model along the experiment (docs/design.md §5, §8).
/// Throws InputError for an LTI/LPV mismatch and std::invalid_argument for
/// inconsistent sizes.
template <typename T>
AffineResidual<T> build_affine_residual(const LpvModel<T>& model, const Experiment<T>& exp, const Unknowns& unknowns);

/// The model with parameters p folded in: correction terms added to C, D
/// (and C1, D1 for `general`), offset values set, x0 = model.x0 + p_x0. The correction
/// basis is kept (its fixed A_i, B_i still act on the state); the unknowns
/// that were solved for are no longer unknown. Several records' own initial
/// states (layout.x0_records ≥ 2) are not the model's: the model's x0 is
/// kept, and record_initial_states gives them.
template <typename T>
LpvModel<T> apply_parameters(const LpvModel<T>& model, const ParameterLayout& layout, const Vec<T>& p);

/// Each record's initial state with p folded in (for Experiment::record_x0):
/// when layout.x0_records ≥ 2, record k's x0 = its own (record_x0[k], or the
/// model's x0 when that is empty or absent) + its segment of p_x0; otherwise
/// `record_x0` unchanged.
template <typename T>
std::vector<Vec<T>> record_initial_states(const LpvModel<T>& model, const std::vector<Vec<T>>& record_x0,
                                          const ParameterLayout& layout, const Vec<T>& p);

}  // namespace lpvid
