// Portable acceptance of compact dual certificates (docs/dual_certificates.md,
// "Portable acceptance"): a verifier compiled elsewhere rebuilds the floating
// U = μ(t·I − TTᵀ)⁻¹ with other last bits. The builder promises acceptance
// for every rebuild U' with ‖U' − U‖₂ ≤ ε·‖U‖₂, ε = kPathDualRebuildTolerance.
// Known answers by construction:
//  - U' = U ± k·I and U' = U + (k/P)·S (S a symmetric sign matrix, so
//    ‖(k/P)·S‖₂ ≤ k), k the largest whole number of grid units within ε‖U‖₂,
//    lie in that class: the certificate must still hold on them (k·I moves
//    the correction E by exactly k·‖T‖_F, the worst case of the margin);
//  - t and μ moved by a few ulps give a U' that lies in the class whenever
//    ‖U' − U‖₂ ≤ ε‖U‖₂ (measured here): then it must hold too;
//  - a claim that is false stays rejected on every such U': a lower end
//    above the certified upper end (the truth of the primal certificate), and
//    "invalidated" moved to the data's true (δ, d_max), where the model is
//    consistent by construction.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "certify/certify.h"
#include "certify/dual_certify.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/dual_check.h"
#include "verify/certificate/path_dual.h"

namespace lpvid {
namespace {

using namespace gen;

/// ‖U‖₂ of the exact grid matrix Ũ·2^e (symmetric), from below (the class is then only smaller).
double spectral_norm_below(const Mat<double>& U_grid, long e) {
  Eigen::SelfAdjointEigenSolver<Mat<double>> es(U_grid, Eigen::EigenvaluesOnly);
  return std::ldexp(es.eigenvalues().cwiseAbs().maxCoeff(), static_cast<int>(e)) * (1 - 1e-6);
}

/// The rebuilds of the class: U ± k·I and U + (k/P)·S, in whole grid units.
std::vector<Mat<double>> rebuilds_within_tolerance(const Mat<double>& U_grid, long e) {
  const Eigen::Index P = U_grid.rows();
  const double k = std::floor(std::ldexp(kPathDualRebuildTolerance * spectral_norm_below(U_grid, e), static_cast<int>(-e)));
  const Mat<double> I = Mat<double>::Identity(P, P);
  Mat<double> S(P, P);
  const double per_entry = std::floor(k / static_cast<double>(P));  // ‖per_entry·S‖₂ ≤ P·per_entry ≤ k
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = i; j < P; ++j) S(i, j) = S(j, i) = per_entry * (*rc::gen::arbitrary<bool>() ? 1 : -1);
  return {U_grid + k * I, U_grid - k * I, U_grid + S};
}

struct Checked {
  Certificate c;
  Simulation<Rational> sim;
  Mat<Rational> r;
};

Checked checked(const Certificate& c, const Experiment<Rational>& exp) {
  Checked k{c, simulate(c.model, exp), {}};
  k.r = exp.y - k.sim.output;
  return k;
}

bool holds_on(const Checked& k, const Mat<double>& U_grid) {
  return check_path_dual_on_grid(k.c, k.sim, k.r, U_grid, "").holds;
}

/// t or μ moved by `ulps` units in the last place (their doubles are what the verifier inverts).
Rational moved(const Rational& q, int ulps) {
  double d = nearest_double(q);
  for (int i = 0; i < std::abs(ulps); ++i) d = std::nextafter(d, ulps > 0 ? INFINITY : 0.0);
  return exact_rational_of_double(d);
}

/// Every rebuild in the class accepts the genuine certificate; the false claim `forged` is rejected on each.
void check_portable(const Checked& genuine, const Checked& forged) {
  const PathDualRecipe& p = genuine.c.dual.path;
  const PathDualGrid grid = path_dual_grid(p, genuine.c.model.ny, genuine.c.model.nz());
  RC_ASSERT(grid.problem.empty());
  RC_ASSERT(holds_on(genuine, grid.U));
  RC_ASSERT(!holds_on(forged, grid.U));
  for (const Mat<double>& U : rebuilds_within_tolerance(grid.U, p.u_exponent)) {
    RC_ASSERT(holds_on(genuine, U));
    RC_ASSERT(!holds_on(forged, U));
  }
  const double norm = spectral_norm_below(grid.U, p.u_exponent);
  for (int ulps : {-3, -1, 1, 3})
    for (bool move_t : {true, false}) {
      Checked m = genuine;
      (move_t ? m.c.dual.path.t : m.c.dual.path.mu) = moved(move_t ? p.t : p.mu, ulps);
      const PathDualGrid moved_grid = path_dual_grid(m.c.dual.path, m.c.model.ny, m.c.model.nz());
      RC_ASSERT(moved_grid.problem.empty());
      const Mat<double> D = moved_grid.U - grid.U;
      const double change = std::ldexp(Eigen::SelfAdjointEigenSolver<Mat<double>>(D, Eigen::EigenvaluesOnly)
                                           .eigenvalues().cwiseAbs().maxCoeff(), static_cast<int>(p.u_exponent));
      if (change <= kPathDualRebuildTolerance * norm) RC_ASSERT(holds_on(genuine, moved_grid.U));
    }
}

IdentCase small_case() {
  IdentCaseOptions o;
  o.min_n = 8;
  o.max_n = 30;
  return *ident_case(o);
}

RC_GTEST_PROP(CompactDualPortability, LowerEndHoldsForEveryRebuildWithinTheToleranceAndAFalseOneNever, ()) {
  const IdentCase ic = small_case();
  ScratchDir dir("portable_lower");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  const CertifiedBounds b = certify_fixed_model(ic.model, ic.exp, certify_options(min_dmax_objective(ic.delta), data), *solver);
  RC_PRE(b.verified() && b.lower.verified() && b.lower.certificate.has_value());
  RC_PRE(b.lower.certificate->form == CertificateForm::kDualDeltaPath);
  const Checked genuine = checked(*b.lower.certificate, ic.exp);
  Checked forged = genuine;  // above the certified upper end: false
  forged.c.lower_bound = b.upper * Rational(11, 10) + Rational(1, 1000000);
  check_portable(genuine, forged);
}

RC_GTEST_PROP(CompactDualPortability, InvalidationHoldsForEveryRebuildWithinTheToleranceAndAFalseOneNever, ()) {
  const IdentCase ic = small_case();
  ScratchDir dir("portable_invalid");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  // Invalidated by construction: ‖d‖ ≥ ‖r‖ − δ‖z‖ > √N·d_max.
  const FixedSignals s = fixed_signals(ic.model, ic.exp);
  const double nr = s.r.norm(), nz = s.z.norm();
  RC_PRE(nr > 1e-6 && nz > 1e-9);
  const double delta = nr / (4 * nz), dmax = nr / (2 * std::sqrt(static_cast<double>(s.r.size())));
  auto solver = make_solver("csdp");
  const CertifiedBounds b = certify_fixed_model(ic.model, ic.exp, certify_options(feasibility_objective(delta, dmax), data), *solver);
  RC_ASSERT(b.invalidated());
  RC_PRE(b.certificate.has_value() && b.certificate->form == CertificateForm::kDualDeltaPath);
  const Checked genuine = checked(*b.certificate, ic.exp);
  Checked forged = genuine;  // the truth's (δ, d_max): consistent by construction, so "invalidated" is false
  const Rational d = rational_from_text(double_to_text(ic.delta)), m = rational_from_text(double_to_text(ic.dmax));
  forged.c.delta2 = d * d;
  forged.c.dmax2 = m * m;
  check_portable(genuine, forged);
}

}  // namespace
}  // namespace lpvid
