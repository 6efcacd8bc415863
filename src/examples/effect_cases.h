#pragma once
/// Data with an effect the declared model lacks: a known
/// LPV system (2 states, one input u1, one output y1, one scheduling
/// variable rho1 excited independently of u) plus ONE effect, simulated on
/// an estimation and a validation record (different input realisations),
/// with white Gaussian output noise. The declared model is the LPV system
/// without the effect: `lpvid diagnose` must name the effect's kind.
///
///   output_offset      y = ŷ + 0.5
///   input_saturation   u' = sat(u, −0.6, 0.6)      (u has standard deviation 1)
///   basis_term         C(ρ) gains the term ρ1²·[0.5 −0.4]
///   abs_value          y = |ŷ|
///   output_polynomial  y = ŷ + 0.4 ŷ²
///   input_delay        u'_k = u_{k−2}
///   dead_zone          u' = dz(u, −0.4, 0.4)
///   output_saturation  y = min(ŷ, 1.2)            (a one-sided clip)
///   input_polynomial   u' = u + 0.3 u³
///   state_feedback     A gains x1²·[0 0; −0.006 0] (a cubic stiffness −0.006 x1³,
///                      scheduled on the system's own state: "@x1"); diagnose
///                      reports it as kind basis_term, entering A
///   scheduled_offset   y = ŷ + 0.3 + 0.6 ρ1 (Φ(ρ) of eq. 20; reported as output_offset)
///   none               nothing (the control case)
///
/// Every number written is an exact decimal (8 digits), so the certificates
/// of `diagnose` are checked against exactly these values.

#include <cstdint>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

struct EffectCase {
  LpvModel<Rational> declared;  ///< the LPV system without the effect
  LpvModel<Rational> truth;     ///< with it
  Experiment<Rational> estimation, validation;  ///< columns u1, y1, rho1
};

/// The effect kinds the generator knows (the list above).
/// The effect kind (docs/design.md §11.5) diagnose should report for a generated kind.
std::string reported_effect_kind(const std::string& kind);
const std::vector<std::string>& effect_case_kinds();

/// Throws InputError for an unknown kind or n < 20.
EffectCase make_effect_case(const std::string& kind, int n, uint64_t seed, double noise_std);

}  // namespace lpvid
