#pragma once
/// Signals scaled to unit size before the bound search (docs/bound_scaling.md
/// has the derivation).
///
/// Theorem 2.1 in the Δ form (paper eq. 4–7 with G11 = 0, docs/design.md §7; lmi/
/// delta_form_lmi.h) sees the data only through z (the uncertainty channel's
/// input) and r = y − ŷ − Φ. Divide y (with ŷ, Φ: every output-side
/// quantity, so r by the same) by s_y = 10^b, the power of ten nearest the
/// RMS of the measured y on the window, and z by s_z = 10^a. For the
/// multiplicative structure z = W·ŷ is itself output-side, so s_z = s_y;
/// otherwise (additive z = W·u, general) s_z is the power of ten nearest
/// the RMS of z. Then
///   w' = w/s_y,  Δ' = (s_z/s_y)·Δ,  d' = d/s_y,
/// and (C1) δ²T_zᵀT_z ⪰ T_wᵀT_w, (C2) ‖d‖² ≤ n·ny·d_max² hold for the
/// original signals at (δ, d_max) exactly when they hold for the scaled ones at
///   δ' = (s_z/s_y)·δ,   d_max' = d_max/s_y          (*)
/// (both sides of (C1) scale by 1/s_y², of (C2) by 1/s_y²). For the
/// multiplicative structure s_z = s_y: δ' = δ, a relative gain, keeps its value.
///
/// So a certificate of the scaled problem IS a certificate of the original
/// one, converted by (*) exactly (powers of ten). The project keeps the
/// certificate in original units (Δ = (s_y/s_z)·Δ', exact), so lpvid-verify
/// checks the data file as it is and needs no notion of scale.
///
/// What the scaling changes is the weighted objective: λδ'² + (1−λ)d_max'²
/// = (1/s_y²)·[λ s_z² δ² + (1−λ) d_max²], i.e. in original units the weight
///   λ_orig = λ s_z² / (λ s_z² + 1 − λ).
/// Without it, λ trades a dimensionless δ against d_max in the data's units
/// and a large signal makes the search sacrifice δ entirely. The other
/// objectives (one bound fixed) have the same minimiser in either units.
/// The solvers' own numerical scaling (σ_z, σ_r in delta_form_lmi.h) is
/// separate and unchanged.

#include <string>

#include "core/scalar.h"
#include "lmi/bound_objective.h"

namespace lpvid {

struct SignalScales {
  bool applied = false;  ///< the weighted objective was stated on scaled signals
  int y_exponent = 0;    ///< s_y = 10^y_exponent
  int z_exponent = 0;    ///< s_z = 10^z_exponent
  double lambda_scaled = 0.5;    ///< λ as given (on the scaled signals)
  double lambda_original = 0.5;  ///< the same objective's λ in original units

  /// δ' = (s_z/s_y)·δ and d_max' = d_max/s_y (doubles, for display).
  double scaled_delta(double delta) const;
  double scaled_dmax(double dmax) const;
  /// "10^3" etc.
  std::string y_scale_text() const;
  std::string z_scale_text() const;
};

/// e with 10^e nearest to rms on a log scale (0 for rms = 0 or non-finite).
int decimal_exponent(double rms);

/// The scales of z and y (n × nz, n × ny; `z_output_side`: the
/// multiplicative structure, s_z = s_y) and, for a weighted objective, λ in
/// original units (applied = false for the other kinds: nothing to convert).
SignalScales signal_scales(const Mat<double>& z, const Mat<double>& y, const BoundObjective& objective,
                           bool z_output_side);

/// The weighted objective in original units (kind kWeighted, λ_orig).
BoundObjective objective_in_original_units(const BoundObjective& scaled, const SignalScales& s);

}  // namespace lpvid
