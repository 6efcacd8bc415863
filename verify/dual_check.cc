#include "verify/dual_check.h"

#include <sstream>

#include "core/number_text.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/fir.h"
#include "verify/exact_psd.h"
#include "verify/verdict_text.h"

namespace lpvid {

CertificateVerdict check_dual_claim(const Certificate& c, const Experiment<Rational>& exp, const Simulation<Rational>& sim,
                                    std::string details) {
  if (c.mode != ToeplitzMode::kSignal)
    return invalid_verdict("a dual certificate is only defined for toeplitz_mode \"signal\" (the Delta form)", details);
  const Eigen::Index n = exp.n(), ny = c.model.ny, nz = c.model.nz();
  const Eigen::Index m = leading_zero_samples(sim.z);
  if (m == n || nz == 0) return invalid_verdict("z is identically zero: the Delta form has no horizon", details);
  const Eigen::Index L = n - m;
  // 4. The horizon covers exactly the taps that act on the data.
  if (c.dual.horizon != L)
    return invalid_verdict("dual.horizon is " + std::to_string(c.dual.horizon) + " but the exact z has " + std::to_string(m) +
                       " leading zero samples of " + std::to_string(n) + ", so the horizon must be " + std::to_string(L),
                   details);
  if (c.dual.g.rows() != n)
    return invalid_verdict("dual.g has " + std::to_string(c.dual.g.rows()) + " rows for " + std::to_string(n) + " samples", details);
  // 5. σ > 0.
  if (!(c.dual.sigma > 0)) return invalid_verdict("dual.sigma must be > 0", details);
  const Mat<Rational> r = exp.y - sim.output;
  // 6. Dual equality, exactly.
  const Mat<Rational> omega = block_diagonal_sums(c.dual.Y1, L, ny, nz);
  const Mat<Rational> adj = fir_adjoint(c.dual.g, sim.z, L);
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
  if (c.claim == CertificateClaim::kInvalidated) {
    if (!(bound > 0))
      return invalid_verdict("the dual point does not prove infeasibility: beta - delta2*tr(U) - N*dmax2*sigma = " + approx_text(bound, 8) +
                         " is not > 0",
                     d.str());
    d << "; beta - delta2*tr(U) - N*dmax2*sigma = " << approx_text(bound, 8) << " > 0";
  } else {
    if (bound < c.lower_bound)
      return invalid_verdict("the dual point gives the lower bound " + approx_text(bound, 8) + ", below the claimed " +
                         approx_text(c.lower_bound, 8),
                     d.str());
    d << "; certified lower bound " << approx_text(bound, 8) << " >= claimed " << approx_text(c.lower_bound, 8);
  }
  // 8. Y1 ⪰ 0, exactly.
  const PsdResult psd = decide_psd(c.dual.Y1);
  if (psd.verdict == PsdVerdict::kNotPsd)
    return invalid_verdict("the dual matrix Y1 is not PSD (" + psd.reason + ")", d.str());
  d << "; Y1 (size " << c.dual.Y1.rows() << ") is " << verdict_word(psd.verdict) << " ("
    << (psd.decided_by_filter ? "floating filter with rigorous bound" : "exact elimination") << ")";
  return {true, "", d.str(), "", ""};
}

}  // namespace lpvid
