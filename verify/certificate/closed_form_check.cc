#include "verify/certificate/closed_form_check.h"

#include <sstream>

#include "verify/certificate/verdict_text.h"

namespace lpvid {
namespace {

/// Form "zero_delta" (the file comment of closed_form_check.h): ‖r‖² against n·ny times the claimed value.
CertificateVerdict check_zero_delta(const Certificate& c, const Experiment<Rational>& exp, const Simulation<Rational>& sim,
                                    std::ostringstream& d) {
  d << ", form zero_delta (delta^2 = 0 forces w = 0, so d = r)";
  const bool lower = c.claim == CertificateClaim::kLowerBound && c.objective == DualClaim::kMinDmax2;
  const bool invalidated = c.claim == CertificateClaim::kInvalidated && c.objective == DualClaim::kInvalidated;
  if (!lower && !invalidated)
    return invalid_verdict("form zero_delta decides only dmax^2 at a fixed delta^2 = 0: claim \"lower_bound\" with objective "
                           "\"min_dmax\", or \"invalidated\" with objective \"feasibility\"",
                           d.str());
  if (c.delta2 != 0)
    return invalid_verdict("form zero_delta needs delta2 = 0 exactly, not " + approx_text(c.delta2, 8), d.str());
  const Mat<Rational> r = exp.y - sim.output;
  const Rational rr = residual_energy(r);
  const Rational N(static_cast<long>(r.size()));
  if (lower) {
    const Rational claimed = N * c.lower_bound;
    if (claimed > rr)
      return invalid_verdict("n*ny*lower_bound = " + approx_text(claimed, 17) + " exceeds ||r||^2 = " + approx_text(rr, 17) +
                                 " (exact comparison of rationals): the least dmax^2 at delta^2 = 0 is ||r||^2/(n*ny)",
                             d.str());
    d << "; n*ny*lower_bound = " << approx_text(claimed, 17) << " <= ||r||^2 = " << approx_text(rr, 17)
      << " (exact), so every feasible dmax^2 >= lower_bound";
  } else {
    const Rational allowed = N * c.dmax2;
    if (!(allowed < rr))
      return invalid_verdict("n*ny*dmax2 = " + approx_text(allowed, 17) + " is not below ||r||^2 = " + approx_text(rr, 17) +
                                 " (exact comparison of rationals): Delta = 0, d = r is consistent",
                             d.str());
    d << "; n*ny*dmax2 = " << approx_text(allowed, 17) << " < ||r||^2 = " << approx_text(rr, 17)
      << " (exact), so no noise with RMS <= dmax explains d = r";
  }
  return CertificateVerdict::holding(d.str());
}

/// Form "nonnegative": every objective is ≥ 0, so a lower end ≤ 0 holds.
CertificateVerdict check_nonnegative(const Certificate& c, std::ostringstream& d) {
  d << ", form nonnegative (delta^2 >= 0 and dmax^2 >= 0 at every feasible point)";
  if (c.claim != CertificateClaim::kLowerBound || c.objective == DualClaim::kInvalidated)
    return invalid_verdict("form nonnegative proves only a lower end <= 0 of an objective (claim \"lower_bound\"), "
                           "never an invalidation",
                           d.str());
  if (c.objective == DualClaim::kWeighted && (c.lambda < 0 || c.lambda > 1))
    return invalid_verdict("lambda must be in [0, 1]", d.str());
  if (c.lower_bound > 0)
    return invalid_verdict("the claimed lower end " + approx_text(c.lower_bound, 8) +
                               " is > 0: form nonnegative proves only lower ends <= 0",
                           d.str());
  d << "; claimed lower end " << approx_text(c.lower_bound, 8) << " <= 0";
  return CertificateVerdict::holding(d.str());
}

}  // namespace

Rational residual_energy(const Mat<Rational>& r) {
  Rational s(0);
  for (Eigen::Index i = 0; i < r.rows(); ++i)
    for (Eigen::Index j = 0; j < r.cols(); ++j) s += r(i, j) * r(i, j);
  return s;
}

Rational zero_delta_dmax2(const Mat<Rational>& r) {
  if (r.size() == 0) return Rational(0);
  return residual_energy(r) / Rational(static_cast<long>(r.size()));
}

CertificateVerdict check_closed_form_claim(const Certificate& c, const Experiment<Rational>& exp,
                                           const Simulation<Rational>& sim, std::string details) {
  std::ostringstream d;
  d << details;
  if (c.form == CertificateForm::kNonnegative) return check_nonnegative(c, d);
  if (c.form == CertificateForm::kZeroDelta) return check_zero_delta(c, exp, sim, d);
  return invalid_verdict(std::string("form ") + to_string(c.form) + " is not a closed form", d.str());
}

}  // namespace lpvid
