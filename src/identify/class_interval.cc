#include "identify/class_interval.h"

#include "core/deadline.h"
#include "core/number_text.h"
#include "toeplitz/record_segments.h"

namespace lpvid {

ClassInterval class_interval(const IdentifiedModel& id, const Problem& problem, const CertifyOptions& certify,
                             ClassBoundOptions options, SdpSolver& solver) {
  const auto& [model_q, model_d, exp_q, exp_d] = problem;
  ClassInterval out;
  options.upper = nearest_double(id.bounds.upper);
  try {
    out.bound = class_lower_bound(problem, id.fixed.value, certify, options);
  } catch (const RunStopped&) {
    throw;  // the user's --timeout or a requested stop ends the command
  } catch (const std::exception& e) {
    // the found θ and its bounds stand; only the class's lower end is missing
    out.bound.outcome = ClassBoundOutcome::kNotCertified;
    out.bound.reason = std::string("the class bound failed: ") + e.what();
    return out;
  }
  if (!out.bound.certified()) return out;
  if (out.bound.whole_class && out.bound.best_p.size() == id.fixed.value.size() &&
      out.bound.best_objective < options.upper) {
    FixedParameters optimum = fix_parameters(model_q, id.fit.layout, out.bound.best_p, certify.digits, exp_q.record_x0);
    const Experiment<Rational> exp = with_fixed_initial_states(exp_q, optimum);
    CertifiedBounds b = out.bound.best_solution
                            ? certify_fixed_model_from(optimum.model, exp, certify, solver, *out.bound.best_solution)
                            : certify_identified(optimum.model, exp, Mat<double>(), certify, solver);
    if (b.verified() && b.upper < id.bounds.upper) out.better = ClassOptimum{std::move(optimum), std::move(b)};
  }
  const double U = nearest_double(out.better ? out.better->bounds.upper : id.bounds.upper);
  const double L = nearest_double(out.bound.lower);
  out.relative_gap = U > 0 ? (U - L) / U : 0.0;
  return out;
}

void adopt_class_optimum(IdentifiedModel& id, ClassInterval& interval) {
  if (!interval.better) return;
  id.fixed = std::move(interval.better->fixed);
  id.bounds = std::move(interval.better->bounds);
  interval.better.reset();
  interval.adopted = true;
}

}  // namespace lpvid
