// Portable acceptance of compact dual certificates (docs/dual_certificates.md,
// "Portable acceptance"): a verifier compiled elsewhere rebuilds the floating
// U = μ(t·I − TTᵀ)⁻¹ with other last bits. The builder promises acceptance
// for every rebuild U' with ‖U' − U‖_F ≤ ε·‖U‖_F, ε = kPathDualRebuildTolerance.
// Known answers by construction:
//  - U' = U ± (k/√P)·I, U' = U + (k/P)·S (S a symmetric sign matrix),
//    U' = U + (k/P)·ssᵀ (s a sign vector) and U' = U + c·vvᵀ (v the top
//    eigenvector of U, the direction in which a floating inverse of the
//    nearly singular t·I − TTᵀ errs most), each of Frobenius norm at most k,
//    k the largest whole number of grid units within ε‖U‖_F, lie in that
//    class: the certificate must still hold on them;
//  - t moved by up to ±kPathDualTMoveUlps ulps (the builder rebuilt U from
//    those and covers them) and μ by ±1, ±3 ulps (U scaled by 1 ± k·u, inside
//    the class): the certificate must hold on each rebuild too;
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

/// ‖U‖_F of the exact grid matrix Ũ·2^e, from below (the class is then only smaller).
double frobenius_norm_below(const Mat<double>& U_grid, long e) {
  return std::ldexp(U_grid.norm(), static_cast<int>(e)) * (1 - 1e-6);
}

/// The rebuilds of the class, in whole grid units, each of Frobenius norm at most k.
std::vector<Mat<double>> rebuilds_within_tolerance(const Mat<double>& U_grid, long e) {
  const Eigen::Index P = U_grid.rows();
  const double k = std::floor(std::ldexp(kPathDualRebuildTolerance * frobenius_norm_below(U_grid, e), static_cast<int>(-e)));
  const double Pd = static_cast<double>(P);
  const Mat<double> I = Mat<double>::Identity(P, P);
  const double diagonal = std::floor(k / std::sqrt(Pd));  // ‖diagonal·I‖_F = diagonal·√P ≤ k
  const double per_entry = std::floor(k / Pd);            // ‖per_entry·S‖_F = P·per_entry ≤ k
  Mat<double> S(P, P);
  Vec<double> sign(P);
  for (Eigen::Index i = 0; i < P; ++i) {
    sign(i) = *rc::gen::arbitrary<bool>() ? 1 : -1;
    for (Eigen::Index j = i; j < P; ++j) S(i, j) = S(j, i) = per_entry * (*rc::gen::arbitrary<bool>() ? 1 : -1);
  }
  std::vector<Mat<double>> out{U_grid + diagonal * I, U_grid - diagonal * I, U_grid + S,
                               U_grid + per_entry * sign * sign.transpose()};
  // c·vvᵀ rounded to whole units: the rounding adds at most P/2 in Frobenius norm.
  if (const double c = k - Pd; c > 0) {
    Eigen::SelfAdjointEigenSolver<Mat<double>> es(U_grid);
    const Vec<double> v = es.eigenvectors().col(P - 1);
    for (double side : {1.0, -1.0}) out.push_back(U_grid + (side * c * v * v.transpose()).array().round().matrix());
  }
  return out;
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
  // t moved by up to kPathDualTMoveUlps ulps: the builder rebuilt U from ±4 and covers
  // them (and, E being nearly linear in t, the moves between); μ moved by a few
  // ulps scales U by 1 ± k·u, inside the Frobenius class. Each rebuild is U' on the
  // certificate's own grid, as a verifier computes it from the moved recipe.
  for (int ulps : {-kPathDualTMoveUlps, -3, -1, 1, 3, kPathDualTMoveUlps})
    for (bool move_t : {true, false}) {
      if (!move_t && std::abs(ulps) == kPathDualTMoveUlps) continue;
      Checked m = genuine;
      (move_t ? m.c.dual.path.t : m.c.dual.path.mu) = moved(move_t ? p.t : p.mu, ulps);
      const PathDualGrid moved_grid = path_dual_grid(m.c.dual.path, m.c.model.ny, m.c.model.nz());
      if (!moved_grid.problem.empty()) continue;  // t·I − TTᵀ not definite after the move: no rebuild to check
      RC_ASSERT(holds_on(genuine, moved_grid.U));
      RC_ASSERT(!holds_on(forged, moved_grid.U));
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
