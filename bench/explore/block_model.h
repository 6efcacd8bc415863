#pragma once
/// The linear starting model (observer_form.h) with the candidate effects of
/// docs/design.md §9.2 around it, simulated in free run and fitted by output error.
/// This is the evidence engine of bench/effect_explore.cc:
/// which effect, added to the linear model, lowers the validation error.
///
///   v_k  = u_{k−d}                                   input delay d (input_delay)
///   u'_k = g_in(v_k)                                 static input block:
///            v + Σ_{p=2..P} α_p (v − v̄)^p             input_polynomial
///            min(v, L_in)                             input_saturation (L_in fixed)
///            sign(v)·max(|v| − w, 0)                  dead_zone (w fixed)
///   φ_k  = [u'_k, (u'_k − ū')², …, (u'_k − ū')^R]      parallel input paths (R > 1):
///                                                    x_{k+1} = A x_k + Σ_r B_r φ_{k,r}, i.e. B(ρ)
///                                                    polynomial in ρ = u' (basis_term in B)
///   x_{k+1} = A x_k + B φ_k,  ℓ_k = C x_k + D φ_k      linear part (observer form)
///   ŷ_k  = ℓ_k + (ρ_k − ρ̄)(C₁ x_k + D₁ u'_k)         LPV output term (docs/design.md §5 eq. 10
///                                                    with f(ρ) = ρ − ρ̄: basis_term in C, D)
///   y_k  = g_out(ŷ_k) + c                            static output block + offset:
///            ŷ + Σ_{q=2..Q} β_q (ŷ − ȳ)^q             output_polynomial
///            min(·, L_out) after the polynomial       output_saturation (L_out fitted)
///
/// ρ is either the measured input u_k or the model's own output one sample
/// back, y_{k−1} (in free run the simulated one, as the benchmark requires;
/// y_{−1} := y_0's linear part). v̄, ȳ, ρ̄ are estimation-data means (they only
/// condition the polynomial coefficients).

#include <string>

#include "core/scalar.h"
#include "fit/observer_form.h"

namespace lpvid {

enum class Scheduling { kNone, kInput, kOutputLag };

/// Which effects are present, and the fixed (grid-searched) levels.
struct EffectSet {
  int delay = 0;                    ///< input delay d >= 0 (samples)
  int input_degree = 1;             ///< P (1: no input polynomial)
  int input_paths = 1;              ///< R (1: single path; B, D get R columns)
  bool input_saturation = false;    ///< with level input_level
  double input_level = 0;
  bool dead_zone = false;           ///< with width dead_zone_width
  double dead_zone_width = 0;
  Scheduling lpv = Scheduling::kNone;
  int output_degree = 1;            ///< Q (1: no output polynomial)
  bool output_saturation = false;   ///< L_out is a fitted parameter
  /// Short readable name, e.g. "offset+input_poly3+output_sat".
  std::string name(bool offset) const;
};

/// Linear part + effect parameters. Parameter vector: the observer-form
/// parameters (a, B, D, x0[, c]; B and D have R columns) then α_2..α_P, C₁ (n), D₁, β_2..β_Q, L_out.
struct BlockModel {
  ObserverForm linear;
  EffectSet effects;
  Vec<double> alpha, c1, beta;  ///< α_2.., C₁ (n, when lpv), β_2..
  double d1 = 0;                ///< D₁ (scalar: one input)
  double output_level = 0;      ///< L_out
  double v_mean = 0, y_mean = 0, rho_mean = 0, path_mean = 0;

  Vec<double> parameters() const;
  void set_parameters(const Vec<double>& p);
  int parameter_count() const { return static_cast<int>(parameters().size()); }
};

/// The block model around `linear` (one input) with every effect parameter
/// neutral (α = β = C₁ = D₁ = 0, extra B/D columns 0, L_out = max of y);
/// means taken from (u, y).
BlockModel neutral_block_model(const ObserverForm& linear, const EffectSet& effects, const Vec<double>& u,
                               const Vec<double>& y);

/// Free-run output y_k, k = 0 … N−1, for the single input u (N-vector), from
/// x_0 = m.linear.x0.
Vec<double> simulate_block_model(const BlockModel& m, const Vec<double>& u);

/// Output-error fit on (u, y): Levenberg–Marquardt on y − y(θ). With
/// `fix_dynamics` the denominator a and B stay as given (only D, x0, c and the
/// effect parameters move: the "re-fit given A, B" stage); otherwise all move,
/// keeping A stable. Returns the free-run RMS on (u, y).
double fit_block_model(BlockModel& m, const Vec<double>& u, const Vec<double>& y, bool fix_dynamics,
                       int max_iterations = 400);

/// Free-run RMS on validation data, x0 fitted (Levenberg–Marquardt, from the
/// steady state of the first input) to the first init_samples samples.
double block_validation_rms(const BlockModel& m, const Vec<double>& u, const Vec<double>& y, int init_samples);

}  // namespace lpvid
