#include "certify/certify_types.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/number_text.h"

namespace lpvid {

Rational objective_at(const BoundObjective& obj, const Rational& delta2, const Rational& dmax2) {
  switch (obj.kind) {
    case BoundObjective::Kind::kMinDelta:
      return delta2;
    case BoundObjective::Kind::kMinDmax:
      return dmax2;
    case BoundObjective::Kind::kWeighted: {
      const Rational lambda = rational_from_text(double_to_text(obj.lambda));
      return lambda * delta2 + (Rational(1) - lambda) * dmax2;
    }
    case BoundObjective::Kind::kFeasibility:
      break;
  }
  return Rational(0);
}


void name_certificate_data(Certificate& c, const CertifyOptions& o, const Experiment<Rational>& exp) {
  if (o.records.empty()) return;  // an experiment made in memory: no data named
  const size_t records = exp.record_count();
  if (o.records.size() != records)
    throw std::invalid_argument("certification: " + std::to_string(o.records.size()) + " record reference" +
                                (o.records.size() == 1 ? "" : "s") + " for " + std::to_string(records) + " record" +
                                (records == 1 ? "" : "s") + " of data");
  set_record_references(c, o.records, exp.record_x0);
}

BoundObjective solver_objective(BoundObjective objective) {
  if (objective.dmax_fixed()) objective.dmax.approx *= 1.0 - 1e-7;
  if (objective.delta_fixed()) objective.delta.approx *= 1.0 - 1e-7;
  return objective;
}

CertifyOutcome outcome_of(const CertifiedBounds& b, const BoundObjective& objective) {
  if (b.verified()) return CertifyOutcome::kVerified;
  if (b.invalidated()) return CertifyOutcome::kInvalidated;
  if (objective.kind == BoundObjective::Kind::kFeasibility) return CertifyOutcome::kUndecided;
  if (b.solve_status == SolveStatus::kBackendError || b.solve_status == SolveStatus::kIterationLimit)
    return CertifyOutcome::kSolverFailed;
  return CertifyOutcome::kNotVerified;
}

const char* to_string(CertifyOutcome outcome) {
  switch (outcome) {
    case CertifyOutcome::kVerified: return "verified";
    case CertifyOutcome::kInvalidated: return "invalidated";
    case CertifyOutcome::kUndecided: return "undecided";
    case CertifyOutcome::kSolverFailed: return "solver_failed";
    case CertifyOutcome::kNotVerified: return "not_verified";
  }
  return "?";
}

std::string solve_status_text(const CertifiedBounds& b) {
  if (!b.closed_form.empty()) return "no solve: " + b.closed_form;
  return b.solve_status ? to_string(*b.solve_status) : "given taps (no solve)";
}

void add_stage_seconds(CertifiedBounds& into, const CertifiedBounds& from) {
  into.signals_seconds += from.signals_seconds;
  into.solve_seconds += from.solve_seconds;
  into.upper_build_seconds += from.upper_build_seconds;
  into.verify_seconds += from.verify_seconds;
  into.total_seconds += from.total_seconds;
}

double relative_gap(const CertifiedBounds& b) {
  if (!b.verified() || !b.lower.verified()) return NAN;
  if (b.upper == 0) return 0.0;
  return nearest_double((b.upper - b.lower.value) / b.upper);
}

}  // namespace lpvid
