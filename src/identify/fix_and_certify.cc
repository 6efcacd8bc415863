#include "identify/fix_and_certify.h"

#include "core/decimal_rounding.h"

namespace lpvid {

FixedParameters fix_parameters(const LpvModel<Rational>& model, const ParameterLayout& layout, const Vec<double>& p,
                               int digits, const std::vector<Vec<Rational>>& record_x0) {
  FixedParameters f;
  f.exact.resize(p.size());
  f.value.resize(p.size());
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    f.exact(i) = round_to_digits(p(i), digits);
    f.value(i) = CGAL::to_double(f.exact(i));
  }
  f.model = apply_parameters(model, layout, f.exact);
  f.record_x0 = record_initial_states(model, record_x0, layout, f.exact);
  return f;
}

Experiment<Rational> with_fixed_initial_states(const Experiment<Rational>& exp, const FixedParameters& fixed) {
  Experiment<Rational> out = exp;
  out.record_x0 = fixed.record_x0;
  return out;
}

CertifiedBounds certify_identified(const LpvModel<Rational>& fixed, const Experiment<Rational>& exp,
                                   const Mat<double>& taps, const CertifyOptions& options, SdpSolver& solver,
                                   std::string* note) {
  if (taps.size() > 0) {
    CertifiedBounds b = certify_with_taps(fixed, exp, taps, options, solver.name());
    if (b.verified()) {
      if (options.lower_end && options.objective.kind != BoundObjective::Kind::kFeasibility) {
        // The lower end: Theorem 2.1 for the same fixed model, whose dual
        // point is lifted and checked (certify_fixed_model); its own upper
        // certificate is not the one reported (only its lower end is kept).
        const CertifiedBounds twin = certify_fixed_model(fixed, exp, options, solver);
        b.lower = twin.lower;
        add_stage_seconds(b, twin);  // its solve and its unreported upper end took time too
      }
      return b;
    }
    if (note) *note = b.reason;
  }
  return certify_fixed_model(fixed, exp, options, solver);
}

IdentifiedModel identify_and_certify(const Problem& problem, const IdentifyOptions& identify_options,
                                     const CertifyOptions& certify_options, SdpSolver& solver) {
  const auto& [model_q, model_d, exp_q, exp_d] = problem;
  IdentifiedModel out;
  out.fit = identify(model_d, exp_d, identify_options, solver);
  if (!has_solution(out.fit.status)) {
    out.bounds.outcome =
        out.fit.status == SolveStatus::kPrimalInfeasible ? CertifyOutcome::kUndecided : CertifyOutcome::kSolverFailed;
    return out;
  }
  out.fixed = fix_parameters(model_q, out.fit.layout, out.fit.p, certify_options.digits, exp_q.record_x0);
  out.bounds = certify_identified(out.fixed.model, with_fixed_initial_states(exp_q, out.fixed), out.fit.taps,
                                  certify_options, solver, &out.taps_note);
  return out;
}

}  // namespace lpvid
