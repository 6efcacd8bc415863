#include "certify/closed_form.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <gmp.h>

#include "certify/path_dual_build.h"
#include "core/decimal_rounding.h"
#include "core/limits.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/closed_form_check.h"

namespace lpvid {
namespace {

/// ‖r‖²/N as the certificates carry it: exact, or outward rounded when its text is too long.
struct LeastDmax2 {
  Rational up, down;
  bool exact = true;
  long digits = 0;  ///< decimal digits of the exact numerator plus denominator
};

LeastDmax2 least_dmax2(const Mat<Rational>& r) {
  LeastDmax2 m;
  const Rational q = zero_delta_dmax2(r);
  m.digits = static_cast<long>(mpz_sizeinbase(mpq_numref(q.mpq()), 10) + mpz_sizeinbase(mpq_denref(q.mpq()), 10));
  m.exact = m.digits <= std::min(kMaxExactDigits, input_limits().max_number_digits);
  m.up = m.exact ? q : round_up_to_digits(q, 30);
  m.down = m.exact ? q : round_down_to_digits(q, 30);
  return m;
}

/// What the closed form answers: the primal point Δ = 0 at (δ², d_max²), or
/// (fixed bounds) an invalidation; the lower end's form and value.
struct Plan {
  Rational delta2, dmax2;
  bool consistent = true;
  CertificateForm lower_form = CertificateForm::kNonnegative;
  Rational lower{0};
  std::string how;   ///< "closed form (delta = 0)" …
  std::string note;  ///< the rounding, when ‖r‖²/N is not exact; a tie N·d_max² = ‖r‖²
};

/// The plan for `obj`, when it is one of the cases of closed_form.h.
std::optional<Plan> plan_for(const BoundObjective& obj, const Mat<Rational>& r) {
  const Rational rr = residual_energy(r), N(static_cast<long>(r.size()));
  Plan p;
  p.delta2 = obj.delta_fixed() ? obj.delta.exact * obj.delta.exact : Rational(0);  // δ² = 0 unless fixed
  const Rational dmax2 = obj.dmax_fixed() ? obj.dmax.exact * obj.dmax.exact : Rational(0);
  const bool zero_delta = obj.delta_fixed() && p.delta2 == 0, zero_r = rr == 0;
  p.how = zero_delta ? "closed form (delta = 0)" : zero_r ? "closed form (r = 0)" : "closed form (objective 0 at Delta = 0)";
  switch (obj.kind) {
    case BoundObjective::Kind::kFeasibility:  // Δ = 0 is the only point (δ = 0) or explains r = 0
      if (!zero_delta && !zero_r) return std::nullopt;
      p.dmax2 = dmax2;
      p.consistent = N * dmax2 >= rr;
      if (N * dmax2 == rr) p.note = "n*ny*dmax^2 = ||r||^2 exactly: a tie, consistent (Delta = 0 attains it)";
      p.lower_form = CertificateForm::kZeroDelta;
      return p;
    case BoundObjective::Kind::kMinDelta:  // δ² = 0 is attained when the noise alone explains r
      if (N * dmax2 < rr) return std::nullopt;
      p.dmax2 = dmax2;
      return p;
    case BoundObjective::Kind::kMinDmax:
      if (!zero_delta && !zero_r) return std::nullopt;
      break;
    case BoundObjective::Kind::kWeighted:
      break;
  }
  const LeastDmax2 m = least_dmax2(r);
  p.dmax2 = m.up;
  if (zero_delta) {  // minimise d_max² at δ = 0: both ends are ‖r‖²/N
    p.lower_form = CertificateForm::kZeroDelta;
    p.lower = m.down;
    if (!m.exact)
      p.note = "||r||^2/(n*ny) has " + std::to_string(m.digits) + " digits exactly: the ends are rounded outward to 30 digits";
    return p;
  }
  // the objective is 0 at Δ = 0: r = 0 (d_max² = 0), or the weighted λ = 1 (d_max² does not count)
  if (objective_at(obj, p.delta2, p.dmax2) != 0) return std::nullopt;
  return p;
}

/// The primal point Δ = 0 at (δ², d_max²): no taps on the horizon of z, or w = 0.
Certificate zero_point(const ClosedFormInput& in, const Rational& delta2, const Rational& dmax2) {
  Certificate c;
  c.model = in.model;
  c.mode = in.mode;
  if (in.mode == ToeplitzMode::kSignal) {
    c.form = CertificateForm::kDelta;
    c.taps = Mat<Rational>(0, in.model.ny * in.model.nz());
    c.horizon = std::max<Eigen::Index>(1, in.horizon);
  } else {
    c.form = CertificateForm::kW;
    c.w = Mat<Rational>::Zero(in.exp.n(), in.model.ny);
  }
  c.delta2 = delta2;
  c.dmax2 = dmax2;
  return c;
}

/// A claim in a closed form: "lower_bound" at `value`, or "invalidated".
Certificate closed_claim(const ClosedFormInput& in, const CertifyOptions& o, CertificateClaim claim, CertificateForm form,
                         const Rational& value) {
  Certificate c;
  c.model = in.model;
  c.mode = in.mode;
  c.claim = claim;
  c.form = form;
  c.objective = claim_of(o.objective);
  const FixedValues f = fixed_values(o, c.objective);
  c.delta2 = f.delta2;
  c.dmax2 = f.dmax2;
  c.lambda = f.lambda;
  if (claim == CertificateClaim::kLowerBound) c.lower_bound = value;
  return c;
}

/// Names the data, fills the info and checks `c` as a file would carry it.
CertificateVerdict checked(Certificate& c, const ClosedFormInput& in, const CertifyOptions& o, const Plan& p) {
  name_certificate_data(c, o, in.exp);
  c.info["tool"] = "lpvid";
  c.info["objective"] = o.objective.describe();
  c.info["solver"] = p.how;
  c.info["solver_status"] = "no solve";
  if (!p.note.empty()) c.info["note"] = p.note;
  return check_round_trip(c, in.exp, "the closed-form certificate (in memory)");
}

}  // namespace

namespace {

/// `c` checked (checked()), the seconds of the exact check added to `seconds`.
CertificateVerdict timed_check(Certificate& c, const ClosedFormInput& in, const CertifyOptions& o, const Plan& p,
                               double& seconds) {
  const Stopwatch watch;
  CertificateVerdict v = checked(c, in, o, p);
  seconds += watch.seconds();
  return v;
}

/// The primal point Δ = 0 as the upper end (or the verdict "consistent").
bool certify_upper(const ClosedFormInput& in, const CertifyOptions& o, const Plan& p, CertifiedBounds& b) {
  Certificate c = zero_point(in, p.delta2, p.dmax2);
  const CertificateVerdict v = timed_check(c, in, o, p, b.verify_seconds);
  if (!v.holds) {
    b.reason = "exact check failed: " + v.reason;
    return false;
  }
  b.outcome = CertifyOutcome::kVerified;
  b.verifier_details = v.details;
  b.delta2 = c.delta2;
  b.dmax2 = c.dmax2;
  b.delta = sqrt_up(c.delta2);
  b.dmax = sqrt_up(c.dmax2);
  b.upper = objective_at(o.objective, b.delta2, b.dmax2);
  b.certificate = std::move(c);
  return true;
}

/// The lower end in the plan's closed form ("zero_delta" or "nonnegative").
bool certify_lower(const ClosedFormInput& in, const CertifyOptions& o, const Plan& p, CertifiedBounds& b) {
  Certificate c = closed_claim(in, o, CertificateClaim::kLowerBound, p.lower_form, p.lower);
  const CertificateVerdict v = timed_check(c, in, o, p, b.lower.check_seconds);
  if (!v.holds) {
    b.lower.outcome = LowerEndOutcome::kNotCertified;
    b.lower.reason = "exact check failed: " + v.reason;
    return false;
  }
  b.lower.outcome = LowerEndOutcome::kCertified;
  b.lower.value = p.lower;
  b.lower.verifier_details = v.details;
  b.lower.certificate = std::move(c);
  return true;
}

/// Fixed bounds at δ = 0 with N·d_max² < ‖r‖²: the "invalidated" certificate.
bool certify_invalidation(const ClosedFormInput& in, const CertifyOptions& o, const Plan& p, CertifiedBounds& b) {
  Certificate c = closed_claim(in, o, CertificateClaim::kInvalidated, CertificateForm::kZeroDelta, Rational(0));
  const CertificateVerdict v = timed_check(c, in, o, p, b.lower.check_seconds);
  if (!v.holds) return false;
  b.outcome = CertifyOutcome::kInvalidated;
  b.reason = "delta = 0 forces Delta = 0, so d = r, and ||r||^2 > n*ny*dmax^2: no consistency certificate exists";
  b.lower.verifier_details = v.details;
  b.certificate = std::move(c);
  return true;
}

/// The progress line after the closed form: the verdict or the interval, and the time.
std::string done_line(const CertifiedBounds& b, const BoundObjective& objective, double seconds) {
  std::string what;
  if (objective.kind == BoundObjective::Kind::kFeasibility) {
    what = b.invalidated() ? "invalidated (form zero_delta)" : "consistent (Delta = 0)";
  } else {
    what = "interval [" + lower_text(b.lower.value, 17) + ", " + upper_text(b.upper, 17) + "], relative gap " +
           double_to_text(relative_gap(b));
  }
  return b.closed_form + ": " + what + "; certified and checked exactly in " + double_to_text(std::round(seconds * 100) / 100) +
         " s";
}

}  // namespace

std::optional<CertifiedBounds> certify_closed_form(const ClosedFormInput& in, const CertifyOptions& o) {
  const std::optional<Plan> plan = plan_for(o.objective, in.r);
  if (!plan) return std::nullopt;
  const Stopwatch watch;
  if (o.progress)
    o.progress(plan->how + ": Delta = 0 leaves d = r, so n*ny*dmax^2 >= ||r||^2 decides; no solve" +
               (plan->note.empty() ? "" : " (" + plan->note + ")"));
  CertifiedBounds b;
  b.closed_form = plan->how;
  b.full_horizon = true;
  b.horizon = in.mode == ToeplitzMode::kSignal ? std::max<Eigen::Index>(1, in.horizon) : 0;
  bool made = true;
  if (plan->consistent) {
    made = certify_upper(in, o, *plan, b);
    if (made && o.objective.kind != BoundObjective::Kind::kFeasibility) {
      if (o.lower_end) made = certify_lower(in, o, *plan, b);
      else b.lower.reason = "not requested";
    }
  } else if (o.lower_end) {
    made = certify_invalidation(in, o, *plan, b);
  } else {
    b.reason = "delta = 0 and ||r||^2 > n*ny*dmax^2, but no invalidation certificate was requested";
  }
  if (!made) {  // cannot happen for a correct verifier: say so and let the caller solve
    if (o.progress) o.progress(plan->how + " not certified (" + (b.reason.empty() ? b.lower.reason : b.reason) + "); solving instead");
    return std::nullopt;
  }
  b.lower.seconds = b.lower.check_seconds;
  b.upper_build_seconds = watch.seconds() - b.verify_seconds - b.lower.check_seconds;
  b.outcome = outcome_of(b, o.objective);
  if (o.progress) o.progress(done_line(b, o.objective, watch.seconds()));
  return b;
}

}  // namespace lpvid
