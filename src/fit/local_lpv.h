#pragma once
/// From local LTI models to an initial LPV model, and the static gain Φ: the
/// first two parts of the paper's Example 2 experiment (Section 4.2, eq. 20,
/// Figure 4).
///
///  * Part 1: u* is held at a few operating points (a square wave); at each,
///    a MIMO ARX model (fit/mimo_arx.h) is fitted to the small-signal data.
///    Every entry of its coefficient matrices is then fitted by least
///    squares as Σ_j f_j(ρ) M_j over the points (ρ = u*), giving A(ρ), B(ρ)
///    of eq. 20 in one fixed state-space form, so matrices are comparable
///    across operating points.
///  * Part 2: u* moves slowly with û = 0, so y ≈ Φ(u*); Φ(ρ) = Σ_j h_j(ρ) φ_j
///    is fitted by polynomial least squares.

#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "fit/mimo_arx.h"
#include "model/lpv_model.h"
#include "model/monomial.h"

namespace lpvid {

struct OperatingPointFit {
  Vec<double> rho;  ///< the operating point
  MimoArx arx;      ///< fitted on the run at ρ without its first `skip` samples
};

/// Splits e into runs of constant ρ and fits an order-n ARX model to each
/// run after dropping its first `skip` samples (the settling after the step
/// of u*). Runs too short for the fit are left out.
std::vector<OperatingPointFit> fit_operating_points(const Experiment<double>& e, int order, long skip);

/// Least squares over the points: every entry of P_i, Q_i and c as
/// Σ_j f_j(ρ) M_j; returns one ARX "model" per basis function (same order).
std::vector<MimoArx> interpolate_arx(const std::vector<OperatingPointFit>& points,
                                     const std::vector<Monomial>& basis);

/// The LPV model of eq. 20 (without Φ's values) from interpolated ARX terms:
/// A(ρ) = Σ_j f_j(ρ) A_j, B(ρ) likewise (arx_realisation; the identity blocks
/// only in the term of the constant 1, which must be in the basis),
/// C = [I 0 … 0], D = 0, every entry rounded to `digits` significant digits.
/// Columns u1.., y1.., rho1.. (scheduling rho1..); multiplicative
/// uncertainty of weight W; no correction; no offset.
LpvModel<Rational> lpv_from_arx_terms(const std::vector<MimoArx>& terms, const std::vector<Monomial>& basis,
                                      const Rational& weight, int digits);

/// Φ(ρ) = Σ_j h_j(ρ) φ_j fitted to y by least squares (row j of the result
/// is φ_jᵀ, basis.size() × ny).
Mat<double> fit_static_gain(const Experiment<double>& e, const std::vector<Monomial>& basis);

}  // namespace lpvid
