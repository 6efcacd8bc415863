#include "certify/dual_certify.h"

#include "certify/path_dual_build.h"

#include <cmath>
#include <optional>
#include <utility>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "toeplitz/delta_form_dual.h"
#include "toeplitz/fir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"
#include "verify/certificate/path_dual.h"
#include "verify/psd/psd_filter.h"

namespace lpvid {
namespace {


/// `done(reason)`: sets the outcome's reason and the seconds since this call, returns it.
auto outcome_closer(DualOutcome& out) {
  const Stopwatch t0;
  return [&out, t0](std::string reason) {
    out.reason = std::move(reason);
    out.seconds = t0.seconds();
    return out;
  };
}

/// The certificate around a dual point (form and dual filled by the caller).
Certificate dual_certificate(const LpvModel<Rational>& model, DualClaim claim, const FixedValues& f, const Rational& bound,
                             int bound_digits) {
  Certificate c;
  c.model = model;
  c.mode = ToeplitzMode::kSignal;
  c.claim = claim == DualClaim::kInvalidated ? CertificateClaim::kInvalidated : CertificateClaim::kLowerBound;
  c.objective = claim;
  c.delta2 = f.delta2;
  c.dmax2 = f.dmax2;
  c.lambda = f.lambda;
  c.lower_bound = claim == DualClaim::kInvalidated ? Rational(0) : round_down_to_digits(bound, bound_digits);
  return c;
}

/// Names the data in c, checks it once after its JSON round trip (certify.h
/// step 6) on the exact experiment, fills `out` (the certificate only when it
/// holds; the check's time in out.check_seconds).
void check_and_keep(Certificate& c, const Experiment<Rational>& exp, const CertifyOptions& o, const Rational& bound,
                    DualOutcome& out) {
  name_certificate_data(c, o, exp);
  c.info["tool"] = "lpvid";
  c.info["objective"] = o.objective.describe();
  const Stopwatch check;
  const CertificateVerdict v = check_round_trip(c, exp, "the dual certificate (in memory)");
  out.check_seconds += check.seconds();
  out.status = v.holds ? DualOutcome::Status::kHolds : DualOutcome::Status::kFails;
  out.verifier_details = v.details;
  out.bound = c.claim == CertificateClaim::kInvalidated ? bound : c.lower_bound;
  if (!v.holds) {
    out.reason = "the dual certificate failed the exact check: " + v.reason;
    return;
  }
  out.certificate = std::move(c);
}


/// Y1 (normalised, symmetrised) on the 10⁻¹⁴ grid.
Mat<Rational> grid_matrix(const Mat<double>& Y1d) {
  const double unit_d = 1e-14;
  const Rational unit = power_of_ten(-14);
  const Eigen::Index P = Y1d.rows();
  Mat<Rational> Y1(P, P);
  for (Eigen::Index i = 0; i < P; ++i)
    for (Eigen::Index j = i; j < P; ++j) {
      Y1(i, j) = on_grid(0.5 * (Y1d(i, j) + Y1d(j, i)), unit_d, unit);
      Y1(j, i) = Y1(i, j);
    }
  return Y1;
}

/// Step 3: Y1 projected onto Ω_l(W) = C_l(g) exactly (the dual equality of
/// toeplitz/delta_form_dual.h), the error spread along each block diagonal.
void project_onto_dual_equality(Mat<Rational>& Y1, const Mat<Rational>& g, const Mat<Rational>& z, Eigen::Index L,
                                Eigen::Index ny, Eigen::Index nz, const RecordLengths& records) {
  const Mat<Rational> target = fir_adjoint_records(g, z, L, records);
  const Mat<Rational> have = block_diagonal_sums(Y1, L, ny, nz);
  const Eigen::Index off = L * ny;
  for (Eigen::Index l = 0; l < L; ++l)
    for (Eigen::Index i = 0; i < ny; ++i)
      for (Eigen::Index j = 0; j < nz; ++j) {
        const Rational E = target(l, i * nz + j) - have(l, i * nz + j);
        if (E == 0) continue;
        const Rational share = E / Rational(static_cast<long>(L - l));
        for (Eigen::Index b = 0; b + l < L; ++b) {
          Y1((b + l) * ny + i, off + b * nz + j) += share;
          Y1(off + b * nz + j, (b + l) * ny + i) = Y1((b + l) * ny + i, off + b * nz + j);
        }
      }
}

/// Step 4: Y1 + ε·I with ε from the floating λ_min, grown until the rigorous
/// filter proves it ≻ 0; nullopt when six tries fail (`eps_out`: the last ε).
/// The certificate's exact check decides Y1 ⪰ 0 again on the same matrix:
/// this filter only chooses ε (cheap beside the check's exact work), the
/// check is what the certificate is judged by.
std::optional<Mat<Rational>> with_psd_margin(const Mat<Rational>& Y1, Rational& eps_q, double& eps_out) {
  const Eigen::Index P = Y1.rows();
  const Mat<double> Y1f = nearest_double(Y1);
  Eigen::SelfAdjointEigenSolver<Mat<double>> es(Y1f, Eigen::EigenvaluesOnly);
  const double lmin = es.eigenvalues().minCoeff();
  double eps = std::max(0.0, -lmin) * 1.5 + 8.0 * static_cast<double>(P + 2) * 0x1.0p-53 * std::max(Y1f.trace(), 1e-300) + 1e-300;
  for (int attempt = 0; attempt < 6; ++attempt, eps *= 10) {
    eps_q = round_up_to_digits(exact_rational_of_double(eps), 2);
    Mat<Rational> Y1m = Y1;
    for (Eigen::Index i = 0; i < P; ++i) Y1m(i, i) += eps_q;
    if (run_psd_filter(Y1m).proved_pd) return Y1m;
  }
  eps_out = eps / 10;
  return std::nullopt;
}

DualOutcome certify_dual_dense(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                               const Simulation<Rational>& sim, const Mat<double>& Y1_in, const Mat<double>& Y2_in,
                               const CertifyOptions& o) {
  DualOutcome out;
  const auto done = outcome_closer(out);
  const Eigen::Index n = exp.n(), ny = model.ny, nz = model.nz();
  const Eigen::Index L = records_horizon(sim.z, exp.records);
  const Eigen::Index P = L * (ny + nz), N = n * ny;
  if (L == 0 || nz == 0) return done("z is identically zero: no Delta form");
  if (Y1_in.rows() != P || Y1_in.cols() != P || Y2_in.rows() != N + 1 || Y2_in.cols() != N + 1)
    return done("the solver returned no dual matrices of the expected sizes");
  if (!Y1_in.allFinite() || !Y2_in.allFinite()) return done("the solver's dual matrices are not finite");
  const Mat<Rational> r = exp.y - sim.output;
  const DualClaim claim = claim_of(o.objective);
  const FixedValues fixed = fixed_values(o, claim);

  // 2. Normalise (the dual is homogeneous) and round to a decimal grid; 3. project exactly.
  const double scale = std::max(Y1_in.cwiseAbs().maxCoeff(), Y2_in.col(0).cwiseAbs().maxCoeff());
  if (!(scale > 0)) return done("the solver's dual matrices are zero");
  GridSignal gs = grid_signal(Y2_in.col(0).tail(N), scale, n, ny);
  Mat<Rational> Y1 = grid_matrix(Y1_in / scale);
  project_onto_dual_equality(Y1, gs.g, sim.z, L, ny, nz, exp.records);
  // 4. PSD margin.
  Rational eps_q;
  double eps_failed = 0;
  std::optional<Mat<Rational>> Y1m = with_psd_margin(Y1, eps_q, eps_failed);
  if (!Y1m) return done("the rounded dual matrix Y1 is not positive definite even with a margin of " + double_to_text(eps_failed));

  // 5. σ.
  double trU = 0, trV = 0;
  for (Eigen::Index i = 0; i < P; ++i) (i < L * ny ? trU : trV) += nearest_double((*Y1m)(i, i));
  const Rational sigma = chosen_sigma(trU, trV, g_norms(gs.g_d, r), N, claim, fixed, Y2_in(0, 0) / scale);
  if (!(sigma > 0)) return done("no positive sigma");

  // 6. The bound, exactly; the certificate; the check after its JSON round trip.
  const Rational bound = dual_bound(dual_terms(*Y1m, gs.g, sigma, r, L), claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  if (claim == DualClaim::kInvalidated && !(bound > 0))
    return done("after rounding and the PSD margin (" + double_to_text(nearest_double(eps_q)) +
                ") the dual point no longer proves infeasibility (margin " + double_to_text(nearest_double(bound)) + ")");
  Certificate c = dual_certificate(model, claim, fixed, bound, 12);
  c.form = CertificateForm::kDualDelta;
  c.dual.horizon = L;
  c.dual.Y1 = std::move(*Y1m);
  c.dual.g = std::move(gs.g);
  c.dual.sigma = sigma;
  c.info["psd_margin"] = nearest_double(eps_q);
  c.info["dual_scale"] = scale;
  check_and_keep(c, exp, o, bound, out);
  return done(out.reason);
}

/// The compact form (verify/certificate/path_dual.h) from a barrier's central-path point:
/// the recipe is the point itself (taps, t, μ) with x = μ; g from Y2's first
/// column on a decimal grid; the floor γ and x as in prove_floor.
DualOutcome certify_dual_path(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                              const Simulation<Rational>& sim, const DeltaFormSolution& s, const CertifyOptions& o) {
  DualOutcome out;
  const auto done = outcome_closer(out);
  const Eigen::Index ny = model.ny, L = records_horizon(sim.z, exp.records);
  const DualClaim claim = claim_of(o.objective);
  const FixedValues fixed = fixed_values(o, claim);
  const Mat<Rational> r = exp.y - sim.output;
  PathDualBuild b = build_path_dual(sim.z, r, L, s, claim, fixed, {}, {}, exp.records);
  if (!b.problem.empty()) return done(b.problem);
  const Rational bound = dual_bound(b.value.terms, claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  // What a verifier built elsewhere, with U in other last bits, still reaches.
  const Rational portable = portable_bound(b, L * ny, [&](const DualTerms<Rational>& terms) {
    return dual_bound(terms, claim, fixed.delta2, fixed.dmax2, fixed.lambda);
  });
  if (claim == DualClaim::kInvalidated && !(portable > 0))
    return done("the compact dual point does not prove infeasibility (margin " + double_to_text(nearest_double(bound)) +
                ", " + double_to_text(nearest_double(portable)) + " for a rebuild of U within the stated tolerance)");
  // The claimed lower end: that, and 10⁻⁹ (relative) below the bound.
  const Rational slack = bound > 0 ? bound * power_of_ten(-9) : Rational(0);
  Certificate c = dual_certificate(model, claim, fixed, std::min(portable, bound - slack), 12);
  c.form = CertificateForm::kDualDeltaPath;
  c.info["dual_scale"] = b.scale;
  c.info["x_over_mu"] = nearest_double(b.point.path.x / b.point.path.mu);
  c.info["u_floor_over_mu"] = nearest_double(b.point.path.floor / b.point.path.mu);
  c.info["rebuild_tolerance"] = kPathDualRebuildTolerance;
  c.dual = std::move(b.point);
  check_and_keep(c, exp, o, bound, out);
  return done(out.reason);
}

}  // namespace

DualOutcome certify_dual(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                         const Simulation<Rational>& sim, const DeltaFormSolution& s, const CertifyOptions& o) {
  if (s.path_mu > 0 && !o.dense_dual) {
    DualOutcome compact = certify_dual_path(model, exp, sim, s, o);
    if (compact.verified()) return compact;
    DualOutcome dense = certify_dual_dense(model, exp, sim, s.dual_c1, s.dual_c2, o);
    dense.note = "compact dual form not used: " + compact.reason;
    if (!dense.verified()) dense.reason = "compact form: " + compact.reason + "; dense form: " + dense.reason;
    dense.seconds += compact.seconds;
    dense.check_seconds += compact.check_seconds;
    return dense;
  }
  return certify_dual_dense(model, exp, sim, s.dual_c1, s.dual_c2, o);
}

}  // namespace lpvid
