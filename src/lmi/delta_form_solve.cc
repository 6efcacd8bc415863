#include "lmi/delta_form_solve.h"

#include <stdexcept>

#include "lmi/delta_form_barrier.h"
#include "lmi/delta_kyp_lmi.h"
#include "toeplitz/fir.h"

namespace lpvid {
namespace {

/// (KYP): the taps of ‖Δ‖_∞ ≤ δ as a DeltaFormSolution (no dual matrices).
DeltaFormSolution solve_kyp(const DeltaFormSignals& s, const BoundObjective& objective, const DeltaFormRequest& q,
                            SdpSolver& solver) {
  const DeltaKypSolution k = solve_delta_kyp(s.z, s.r, objective, solver, q.solver, q.taps);
  DeltaFormSolution sol;
  sol.solve = k.solve;
  sol.leading_zeros = leading_zero_samples(s.z);
  sol.horizon = s.z.rows() - sol.leading_zeros;
  sol.taps = k.taps.topRows(std::min<Eigen::Index>(k.taps.rows(), sol.horizon));
  sol.delta2 = k.delta2;
  sol.dmax2 = k.dmax2;
  return sol;
}

}  // namespace

DeltaFormSolution solve_delta_form(const DeltaFormSignals& s, const BoundObjective& objective,
                                   const DeltaFormRequest& q, SdpSolver& solver) {
  const auto tell = [&q](const std::string& line) {
    if (q.progress) q.progress(line);
  };
  const Eigen::Index L = records_horizon(s.z, s.records);
  const bool kyp = q.method == DeltaFormMethod::kKyp;
  if (kyp && q.free_regressors.cols() > 0)
    throw std::invalid_argument("delta form: free regressors are not available with the KYP program");
  if (kyp && several_records(s.records))
    throw std::invalid_argument("delta form: several records are not available with the KYP program (its state "
                                "would run across the records); use the Delta form on the full horizon or K taps");
  if (q.method == DeltaFormMethod::kStructured && q.taps == 0 && barrier_applies(s.z, s.r, objective)) {
    tell("solving Theorem 2.1 on the full horizon (" + std::to_string(L) + " taps) with the structured barrier");
    DeltaFormSolution fast = solve_delta_form_barrier(s.z, s.r, objective, {}, q.free_regressors, s.records);
    fast.solver_used = kStructuredBarrierName;
    if (fast.solve.status != SolveStatus::kBackendError) return fast;
    tell(fast.solve.message + "; solving again with " + solver.name());
    DeltaFormSolution slow = solve_delta_form(s.z, s.r, objective, solver, q.solver, q.taps, q.free_regressors, s.records);
    slow.solve.message += (slow.solve.message.empty() ? "" : "; ") + fast.solve.message + " (fell back to " + solver.name() + ")";
    slow.solve.seconds += fast.solve.seconds;
    slow.fallback = fast.solve.message;
    slow.solver_used = solver.name();
    return slow;
  }
  tell("solving Theorem 2.1 with " + solver.name() + " (" + (q.taps == 0 ? std::to_string(L) : std::to_string(q.taps)) +
       " taps" + (kyp ? ", KYP" : "") + ")");
  DeltaFormSolution out = kyp ? solve_kyp(s, objective, q, solver)
                              : solve_delta_form(s.z, s.r, objective, solver, q.solver, q.taps, q.free_regressors, s.records);
  out.solver_used = solver.name();
  return out;
}

}  // namespace lpvid
