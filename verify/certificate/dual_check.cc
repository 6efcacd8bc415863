#include "verify/certificate/dual_check.h"

#include <sstream>

#include "core/number_text.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/fir.h"
#include "verify/psd/exact_psd.h"
#include "verify/certificate/path_dual.h"
#include "verify/certificate/verdict_text.h"
#include "verify/psd/check_progress.h"
#include "verify/psd/work_limits.h"

namespace lpvid {
namespace {

/// Step 7: the exact bound against the claim; appends to `d`. Empty when it holds.
std::string bound_problem(const Certificate& c, const Rational& bound, std::ostringstream& d) {
  if (c.claim == CertificateClaim::kInvalidated) {
    if (!(bound > 0))
      return "the dual point does not prove infeasibility: beta - delta2*tr(U) - N*dmax2*sigma = " + approx_text(bound, 8) +
             " is not > 0";
    d << "; beta - delta2*tr(U) - N*dmax2*sigma = " << approx_text(bound, 8) << " > 0";
  } else {
    if (bound < c.lower_bound)
      return "the dual point gives the lower bound " + approx_text(bound, 8) + ", below the claimed " + approx_text(c.lower_bound, 8);
    d << "; certified lower bound " << approx_text(bound, 8) << " >= claimed " << approx_text(c.lower_bound, 8);
  }
  return "";
}

/// Steps 6–8 for the compact form (verify/certificate/path_dual.h): the point is rebuilt
/// from its recipe, then checked on that grid matrix.
CertificateVerdict check_path_dual(const Certificate& c, const Simulation<Rational>& sim, const Mat<Rational>& r,
                                   Eigen::Index L, std::string details, const RecordLengths& records) {
  const PathDualRecipe& p = c.dual.path;
  if (p.taps.rows() != L) return invalid_verdict("dual.taps has " + std::to_string(p.taps.rows()) + " rows, not the horizon", details);
  require_dual_order(static_cast<long>(L * c.model.ny));  // before the O((L·ny)³) floating rebuild
  check_progress(dual_step_work(L * c.model.ny), "the compact dual: U of order " + std::to_string(L * c.model.ny) +
                                                      " rebuilt in floating point from its recipe");
  const PathDualGrid grid = path_dual_grid(p, c.model.ny, c.model.nz());
  if (!grid.problem.empty()) return invalid_verdict("the dual recipe gives no point: " + grid.problem, details);
  return check_path_dual_on_grid(c, sim, r, grid.U, std::move(details), records);
}

}  // namespace

CertificateVerdict check_path_dual_on_grid(const Certificate& c, const Simulation<Rational>& sim, const Mat<Rational>& r,
                                           const Mat<double>& U_grid, std::string details, const RecordLengths& records) {
  const Eigen::Index ny = c.model.ny, nz = c.model.nz(), L = c.dual.path.taps.rows();
  const PathDualRecipe& p = c.dual.path;
  const double step = dual_step_work(U_grid.rows());
  check_progress(step, "the compact dual: the exact sums of U and the correction E of the dual equality");
  const PathDualSums sums = path_dual_sums(p, U_grid, ny, nz);
  if (!sums.problem.empty()) return invalid_verdict("the dual recipe gives no point: " + sums.problem, details);
  const PathDualValue v = path_dual_value(p, sums, fir_adjoint_records(c.dual.g, sim.z, L, records), c.dual.g, c.dual.sigma, r, ny, nz);
  std::ostringstream d;
  d << details << ", compact dual of horizon " << L << " rebuilt from " << L * ny * nz
    << " taps; dual equality made exact by the correction E";
  const Rational allowance = p.x * p.floor;
  if (v.E_norm2 > allowance)
    return invalid_verdict("the correction E of the dual equality is too large for the floor: ||E||_F^2 = " +
                               approx_text(v.E_norm2, 8) + " > x*u_floor = " + approx_text(allowance, 8),
                           d.str());
  d << "; ||E||_F^2 = " << approx_text(v.E_norm2, 3) << " <= x*u_floor";
  const Rational bound = dual_bound(v.terms, c.objective, c.delta2, c.dmax2, c.lambda);
  if (std::string why = bound_problem(c, bound, d); !why.empty()) return invalid_verdict(why, d.str());
  check_progress(step, "the compact dual: U - u_floor*I of order " + std::to_string(U_grid.rows()) + ", its PSD proof");
  const PsdResult psd = path_dual_psd(p, U_grid, true);
  if (psd.verdict == PsdVerdict::kNotPsd)
    return invalid_verdict("U - u_floor*I is not PSD (" + psd.reason + "), so Y1 is not shown PSD", d.str());
  d << "; U - u_floor*I (size " << U_grid.rows() << ") is " << verdict_word(psd.verdict) << " ("
    << (psd.decided_by_filter ? "floating filter with rigorous bound" : "exact elimination") << "), so Y1 is PSD";
  return CertificateVerdict::holding(d.str());
}

CertificateVerdict check_dual_claim(const Certificate& c, const Experiment<Rational>& exp, const Simulation<Rational>& sim,
                                    std::string details) {
  if (c.mode != ToeplitzMode::kSignal)
    return invalid_verdict("a dual certificate is only defined for toeplitz_mode \"signal\" (the Delta form)", details);
  const Eigen::Index n = exp.n(), ny = c.model.ny, nz = c.model.nz();
  // 4. The horizon covers exactly the taps that act on the data: the longest
  // record's samples from its first non-zero z (one record: n − m).
  const Eigen::Index L = nz == 0 ? 0 : records_horizon(sim.z, exp.records);
  if (L == 0) return invalid_verdict("z is identically zero: the Delta form has no horizon", details);
  if (c.dual.horizon != L)
    return invalid_verdict("dual.horizon is " + std::to_string(c.dual.horizon) + " but the exact z has " +
                               (several_records(exp.records) ? "its longest record's first non-zero sample "
                                                             : std::to_string(n - L) + " leading zero samples of " + std::to_string(n)) +
                               ", so the horizon must be " + std::to_string(L),
                           details);
  if (c.dual.g.rows() != n)
    return invalid_verdict("dual.g has " + std::to_string(c.dual.g.rows()) + " rows for " + std::to_string(n) + " samples", details);
  // 5. σ > 0.
  if (!(c.dual.sigma > 0)) return invalid_verdict("dual.sigma must be > 0", details);
  const Mat<Rational> r = exp.y - sim.output;
  if (c.form == CertificateForm::kDualDeltaPath) return check_path_dual(c, sim, r, L, std::move(details), exp.records);
  // 6. Dual equality, exactly.
  const Mat<Rational> omega = block_diagonal_sums(c.dual.Y1, L, ny, nz);
  const Mat<Rational> adj = fir_adjoint_records(c.dual.g, sim.z, L, exp.records);
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index q = 0; q < ny * nz; ++q)
      if (omega(l, q) != adj(l, q))
        return invalid_verdict("dual equality fails at tap " + std::to_string(l) + ", entry (" + std::to_string(q / nz) + ", " +
                           std::to_string(q % nz) + "): Omega_l(W) = " + approx_text(omega(l, q), 8) +
                           " but C_l(g) = " + approx_text(adj(l, q), 8) + " (exact comparison)",
                       details);
  // 7. The bound.
  const DualTerms<Rational> terms = dual_terms(c.dual.Y1, c.dual.g, c.dual.sigma, r, L);
  const Rational bound = dual_bound(terms, c.objective, c.delta2, c.dmax2, c.lambda);
  std::ostringstream d;
  d << details << ", dual horizon " << L << "; dual equality holds exactly for " << L << " taps";
  if (std::string why = bound_problem(c, bound, d); !why.empty()) return invalid_verdict(why, d.str());
  // 8. Y1 ⪰ 0, exactly.
  const PsdResult psd = decide_psd(c.dual.Y1);
  if (psd.verdict == PsdVerdict::kNotPsd)
    return invalid_verdict("the dual matrix Y1 is not PSD (" + psd.reason + ")", d.str());
  d << "; Y1 (size " << c.dual.Y1.rows() << ") is " << verdict_word(psd.verdict) << " ("
    << (psd.decided_by_filter ? "floating filter with rigorous bound" : "exact elimination") << ")";
  return CertificateVerdict::holding(d.str());
}

}  // namespace lpvid
