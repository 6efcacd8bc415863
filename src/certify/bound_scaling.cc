#include "certify/bound_scaling.h"

#include <algorithm>
#include <cmath>

#include "core/integer_power.h"
#include "core/rms.h"
#include "lmi/delta_form_lmi.h"

namespace lpvid {

int decimal_exponent(double rms) {
  if (!(rms > 0.0) || !std::isfinite(rms)) return 0;
  return static_cast<int>(std::lround(std::log10(rms)));
}

double SignalScales::scaled_delta(double delta) const { return delta * double_power_of_ten(z_exponent - y_exponent); }
double SignalScales::scaled_dmax(double dmax) const { return dmax * double_power_of_ten(-y_exponent); }
std::string SignalScales::y_scale_text() const { return "10^" + std::to_string(y_exponent); }
std::string SignalScales::z_scale_text() const { return "10^" + std::to_string(z_exponent); }

SignalScales signal_scales(const Mat<double>& z, const Mat<double>& y, const BoundObjective& objective,
                           bool z_output_side) {
  SignalScales s;
  s.y_exponent = decimal_exponent(rms(y));
  s.z_exponent = z_output_side ? s.y_exponent : decimal_exponent(rms(z));
  s.lambda_scaled = s.lambda_original = objective.lambda;
  if (objective.kind != BoundObjective::Kind::kWeighted) return s;
  s.applied = true;
  // λ s_z² / (λ s_z² + 1 − λ), written to stay finite for any exponent
  const double l = objective.lambda;
  if (l <= 0.0 || l >= 1.0) return s;  // λ = 0 or 1: one bound only, unchanged
  const double log_ratio = std::log(l / (1.0 - l)) + 2.0 * s.z_exponent * std::log(10.0);  // log(λ s_z² / (1 − λ))
  // kept strictly inside (0, 1) like the given λ: both bounds stay in the objective
  s.lambda_original = std::clamp(1.0 / (1.0 + std::exp(-log_ratio)), 1e-15, 1.0 - 0x1.0p-40);
  return s;
}

BoundObjective objective_in_original_units(const BoundObjective& scaled, const SignalScales& s) {
  BoundObjective o = scaled;
  if (s.applied) o.lambda = s.lambda_original;
  return o;
}

}  // namespace lpvid
