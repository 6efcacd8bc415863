#include "certify/certify.h"

#include <cmath>

#include "core/decimal_rounding.h"
#include "core/finite_check.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "core/stopwatch.h"
#include "lmi/delta_form_barrier.h"
#include "lmi/delta_form_lmi.h"
#include "lmi/delta_form_solve.h"
#include "lmi/relaxed_bmi_lmi.h"
#include "certify/bound_scaling.h"
#include "certify/closed_form.h"
#include "certify/dual_certify.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "model/simulate.h"
#include "toeplitz/displacement_cholesky.h"
#include "toeplitz/fir.h"
#include "toeplitz/tap_toeplitz.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/closed_form_check.h"

namespace lpvid {

namespace {

/// K taps on L blocks: h_K … h_{L−1} = 0.
Mat<double> padded_taps(const Mat<double>& taps, Eigen::Index horizon) {
  Mat<double> padded = Mat<double>::Zero(horizon, taps.cols());
  padded.topRows(std::min(taps.rows(), horizon)) = taps.topRows(std::min(taps.rows(), horizon));
  return padded;
}

/// SISO horizons from this length on use the displacement Cholesky
/// (toeplitz/displacement_cholesky.h, O(L²) time, O(L) memory) for the norm
/// and the shrink test below instead of dense O(L³) factorisations (at
/// L = 10 000 an eigenvalue solve of TᵀT takes minutes and 1.6 GB); shorter
/// ones keep the dense tests, so their certificates stay as they were.
constexpr Eigen::Index kDisplacementHorizon = 4096;

bool displacement_applies(const Mat<double>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz) {
  return ny == 1 && nz == 1 && horizon >= kDisplacementHorizon && taps.cols() == 1;
}

/// Largest singular value² of the block Toeplitz T_Δ (L blocks, K taps).
double toeplitz_norm2(const Mat<double>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz) {
  if (displacement_applies(taps, horizon, ny, nz)) return lower_toeplitz_norm2(padded_taps(taps, horizon).col(0));
  const Mat<double> T = tap_toeplitz_dense(padded_taps(taps, horizon), ny, nz);
  Eigen::SelfAdjointEigenSolver<Mat<double>> es(T.transpose() * T, Eigen::EigenvaluesOnly);
  return std::max(0.0, es.eigenvalues().maxCoeff());
}

/// Whether ‖T_Δ‖₂ ≤ cap as far as the Cholesky factorisation of
/// cap²·I − T_Δ T_Δᵀ in doubles can tell (T_Δ T_Δᵀ in O(L²) from the taps):
/// the usual answer before the shrink of certify_taps, without
/// toeplitz_norm2's O(L³) product and eigenvalues (measured at SISO
/// n = 3200: 10 of the upper end's 11 s). Only a shortcut: the exact check
/// decides.
bool toeplitz_norm_at_most(const Mat<double>& taps, Eigen::Index horizon, Eigen::Index ny, Eigen::Index nz, double cap) {
  double log_det = 0;
  if (displacement_applies(taps, horizon, ny, nz))
    return displacement_log_det(padded_taps(taps, horizon).col(0), cap * cap, &log_det);
  Mat<double> F = -tap_gram(padded_taps(taps, horizon), ny, nz);
  F.diagonal().array() += cap * cap;
  return Eigen::LLT<Mat<double>>(F).info() == Eigen::Success;
}

/// Steps 5–6, shared by both forms: δ² with the smallest margin whose
/// certificate passes the exact check after its JSON round trip (each δ²
/// tried is checked exactly once). `build` started with step 3.
template <typename Norm2>
void finish_certificate(Certificate& c, const Experiment<Rational>& exp, Norm2 norm2_fn, const CertifyOptions& o,
                        const std::string& solver_name, const Stopwatch& build, CertifiedBounds& out) {
  name_certificate_data(c, o, exp);
  c.info["tool"] = "lpvid";
  c.info["objective"] = o.objective.describe();
  c.info["solver"] = solver_name;
  c.info["solver_status"] = solve_status_text(out);
  const double norm2 = o.objective.delta_fixed() ? 0.0 : norm2_fn();
  CertificateVerdict v;
  double checking = 0;
  // The smallest margin is 1e-9. For large (C1) matrices the exact fallback
  // of the PSD decision is slow (minutes at size 800), so start where the
  // rigorous floating filter can decide: its shift is about (N+1)·u·tr(M)
  // (Rump 2006), and the margin must exceed it.
  double margin = 1e-9;
  const double N = c.form == CertificateForm::kDelta
                       ? static_cast<double>(c.horizon * (c.model.ny + c.model.nz()))
                       : static_cast<double>(c.w.rows() * (1 + c.model.ny));
  // The verifier balances the Δ-form matrix to unit diagonal blocks
  // (certificate_check.cc), so tr ≈ N and λ_min ≈ margin/2 there.
  if (N > 300) margin = std::max(margin, 16.0 * (N + 1) * N * 0x1.0p-53);
  for (int attempt = 0; attempt < 5; ++attempt, margin *= 100) {
    if (o.objective.delta_fixed()) {
      c.delta2 = o.objective.delta.exact * o.objective.delta.exact;
    } else {
      c.delta2 = round_up_to_digits(exact_rational_of_double(norm2 * (1.0 + margin) + 1e-300), 12);
    }
    c.info["delta2_margin"] = margin;
    const Stopwatch check;
    v = check_round_trip(c, exp, "the certificate (in memory)");  // step 6: as a file would carry it
    checking += check.seconds();
    if (v.holds || o.objective.delta_fixed()) break;
  }
  out.verify_seconds += checking;
  out.upper_build_seconds += build.seconds() - checking;
  out.margin = margin;
  if (!v.holds) {
    out.reason = "exact check failed: " + v.reason;
    return;
  }
  out.outcome = CertifyOutcome::kVerified;
  out.reason.clear();
  out.verifier_details = v.details;
  out.delta2 = c.delta2;
  out.dmax2 = c.dmax2;
  out.delta = sqrt_up(c.delta2);
  out.dmax = sqrt_up(c.dmax2);
  out.certificate = c;
}

/// d_max² of the certificate: the fixed one (which must hold exactly) or
/// ‖d‖²/(n·ny) rounded up. Returns false (with out.reason) if a fixed d_max fails.
bool set_dmax2(Certificate& c, const Rational& dd, const Rational& N, const CertifyOptions& o, CertifiedBounds& out) {
  if (o.objective.dmax_fixed()) {
    c.dmax2 = o.objective.dmax.exact * o.objective.dmax.exact;
    if (dd > N * c.dmax2) {
      out.reason = "after rounding, ||d||^2/(n*ny) = " + double_to_text(nearest_double(dd / N)) +
                   " exceeds the fixed dmax^2";
      return false;
    }
  } else {
    c.dmax2 = round_up_to_digits(dd / N, 15);
  }
  return true;
}

/// Steps 3–6 for floating taps (K × ny·nz) on the given horizon.
void certify_taps(const LpvModel<Rational>& model, const Experiment<Rational>& exp, const Simulation<Rational>& sim, const Mat<Rational>& r,
                  const Mat<double>& taps, Eigen::Index horizon, const CertifyOptions& o,
                  const std::string& solver_name, CertifiedBounds& out) {
  const Stopwatch build;
  const Eigen::Index n = r.rows(), ny = model.ny, nz = model.nz();
  // 3. Rounded taps.
  Certificate c;
  c.model = model;
  c.mode = ToeplitzMode::kSignal;
  c.form = CertificateForm::kDelta;
  c.horizon = horizon;
  c.taps = Mat<Rational>(taps.rows(), taps.cols());
  Mat<double> taps_d(taps.rows(), taps.cols());
  // A fixed δ must hold exactly, but the solver meets ‖T_Δ‖ ≤ δ only up to its
  // feasibility tolerance, which is absolute in its scaled units: for a tiny or
  // zero δ the taps can exceed δ by orders of magnitude. Shrink them onto
  // δ·(1 − 1e-8) (to zero for δ = 0) before rounding. On the displacement
  // horizons the verifier proves (C1) on a complement formed in doubles,
  // whose proof needs λ_min ≳ 2·L²·u (Rump's shift plus the proved radius,
  // verify/certificate/tap_gram_filter.h): there the margin is 4·L²·u
  // (4.4e-8 at L = 10 000) when that is larger.
  double shrink = 1.0;
  if (o.objective.delta_fixed()) {
    const double L = static_cast<double>(horizon);
    const double margin = displacement_applies(taps, horizon, ny, nz) ? std::max(1e-8, 4.0 * L * L * 0x1.0p-53) : 1e-8;
    const double cap = o.objective.delta.approx * (1.0 - margin);
    if (!toeplitz_norm_at_most(taps, horizon, ny, nz, cap)) {
      const double norm = std::sqrt(toeplitz_norm2(taps, horizon, ny, nz));
      if (norm > cap) shrink = cap / norm;
    }
  }
  for (Eigen::Index i = 0; i < taps.rows(); ++i)
    for (Eigen::Index j = 0; j < taps.cols(); ++j) {
      c.taps(i, j) = round_to_digits(shrink * taps(i, j), o.digits);
      taps_d(i, j) = nearest_double(c.taps(i, j));
    }

  // 4. (C2) exactly.
  const Mat<Rational> w = apply_fir_records(c.taps, sim.z, ny, c.horizon, exp.records);
  if (!set_dmax2(c, residual_energy(r - w), Rational(static_cast<long>(n * ny)), o, out)) return;

  finish_certificate(c, exp, [&] { return toeplitz_norm2(taps_d, c.horizon, ny, nz); }, o, solver_name, build, out);
}

/// The exact signals every certification starts from: the data with the
/// state-scheduling columns ("@x<i>"), the model's exact simulation, the
/// residual r = y − ŷ (eq. 5) and the horizon L after the leading z = 0 rows.
struct ExactSignals {
  Experiment<Rational> exp;
  Simulation<Rational> sim;
  Mat<Rational> r;
  Eigen::Index n = 0, horizon = 0;
};

ExactSignals exact_signals(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in) {
  ExactSignals s;
  s.exp = with_state_scheduling(model, exp_in);
  s.sim = simulate(model, s.exp);
  s.r = s.exp.y - s.sim.output;
  s.n = s.exp.n();
  s.horizon = records_horizon(s.sim.z, s.exp.records);  // one record: n − (leading zero samples of z)
  return s;
}

}  // namespace

namespace {

std::string status_reason(const DeltaFormSolution& sol, const char* what) {
  return std::string("the ") + what + " solve of Theorem 2.1 ended with status " + to_string(sol.solve.status) +
         (sol.solve.message.empty() ? "" : ": " + sol.solve.message);
}

}  // namespace

CertifyOptions in_original_units(const CertifyOptions& options, const LpvModel<Rational>& model,
                                 const Simulation<Rational>& sim, const Experiment<Rational>& exp, SignalScales* scales) {
  CertifyOptions o = options;
  if (!o.scale_signals) return o;
  const SignalScales s = signal_scales(nearest_double(sim.z), nearest_double(exp.y), o.objective,
                                       model.uncertainty.structure == UncertaintyStructure::kMultiplicative);
  o.objective = objective_in_original_units(o.objective, s);
  o.scale_signals = false;  // done: the objective is in original units now
  if (scales) *scales = s;
  return o;
}

CertifiedBounds certify_fixed(const LpvModel<Rational>& model, const Experiment<Rational>& exp, ToeplitzMode mode,
                              const CertifyOptions& options, SdpSolver& solver) {
  return mode == ToeplitzMode::kSignal ? certify_fixed_model(model, exp, options, solver)
                                       : certify_fixed_model_paper(model, exp, options, solver);
}

namespace {

/// What the stages of certify_fixed_model share: the exact signals (and
/// their doubles, converted once), the options in original units, and the
/// solve plan (K taps or the full horizon; Δ form or KYP).
struct CertifyRun {
  const LpvModel<Rational>& model;
  const ExactSignals& exact;
  DeltaFormSignals signals;
  CertifyOptions o;
  BoundObjective objective;  ///< solver_objective(o.objective)
  SdpSolver& solver;
  bool kyp = false, feasibility = false;
  long K = 0;  ///< taps of the first solve; 0: the full horizon
  const DeltaFormSolution* given = nullptr;  ///< the first solve, done by the caller (certify_fixed_model_from)

  /// One solve: K taps (0: full horizon), KYP or not, with dual matrices when wanted.
  DeltaFormSolution solve(long taps, bool kyp_form, bool want_dual) const {
    DeltaFormRequest q;
    q.method = kyp_form ? DeltaFormMethod::kKyp : o.structured ? DeltaFormMethod::kStructured : DeltaFormMethod::kSdp;
    q.taps = taps;
    q.solver = o.solver;
    q.solver.want_dual = want_dual;
    q.progress = o.progress;
    return solve_delta_form(signals, objective, q, solver);
  }
};

/// Seconds to one decimal, for progress lines.
std::string tenths_text(double seconds) { return double_to_text(std::round(seconds * 10) / 10); }

/// The progress line after a certificate's stage: what, whether it passed, where the time went.
std::string stage_done(const std::string& what, bool certified, double build_seconds, double check_seconds) {
  return what + (certified ? " certified" : " not certified") + ": built in " + tenths_text(build_seconds) +
         " s, checked exactly in " + tenths_text(check_seconds) + " s";
}

/// Steps 3–6 on a solve: the primal certificate (the upper end) in `b`.
void certify_upper_end(const CertifyRun& run, const DeltaFormSolution& sol, CertifiedBounds& b) {
  b.solve_status = sol.solve.status;
  b.solve_seconds += sol.solve.seconds;
  if (!sol.fallback.empty()) b.fallback += (b.fallback.empty() ? "" : "; ") + sol.fallback + " (fell back to " + run.solver.name() + ")";
  b.taps = sol.taps.rows();
  b.horizon = sol.horizon;
  if (!has_solution(sol.solve.status)) {
    b.reason = status_reason(sol, sol.taps.rows() < sol.horizon && sol.taps.rows() > 0 ? "restricted (K-tap)" : "Delta-form");
    return;
  }
  b.delta2_solver = sol.delta2;
  if (run.o.progress) run.o.progress("solved in " + tenths_text(sol.solve.seconds) + " s; checking the upper end exactly");
  const double built = b.upper_build_seconds, checked = b.verify_seconds;
  b.solver_used = sol.solver_used.empty() ? run.solver.name() : sol.solver_used;
  certify_taps(run.model, run.exact.exp, run.exact.sim, run.exact.r, sol.taps, sol.horizon, run.o, b.solver_used, b);
  if (b.verified()) b.upper = objective_at(run.o.objective, b.delta2, b.dmax2);
  if (run.o.progress)
    run.o.progress(stage_done("upper end", b.verified(), b.upper_build_seconds - built, b.verify_seconds - checked));
}


/// The lower end from the dual of a solve (lifted to the full horizon when K < L); keeps the best.
void certify_lower_end(const CertifyRun& run, const DeltaFormSolution& s, CertifiedBounds& out) {
  if (s.dual_c1.size() == 0) return;
  if (run.o.progress) run.o.progress("building and checking the lower end's dual certificate");
  DualOutcome d = certify_dual(run.model, run.exact.exp, run.exact.sim, s, run.o);
  if (d.verified() && (!out.lower.verified() || d.bound > out.lower.value)) {
    out.lower.outcome = LowerEndOutcome::kCertified;
    out.lower.value = d.bound;
    out.lower.certificate = std::move(d.certificate);
    out.lower.verifier_details = d.verifier_details + (d.note.empty() ? "" : " (" + d.note + ")");
    out.lower.reason.clear();
  } else if (!out.lower.verified()) {
    out.lower.outcome = LowerEndOutcome::kNotCertified;
    out.lower.reason = d.reason;
  }
  out.lower.seconds += d.seconds;
  out.lower.check_seconds += d.check_seconds;
  if (run.o.progress) run.o.progress(stage_done("lower end", d.verified(), d.seconds - d.check_seconds, d.check_seconds));
}

/// Fixed bounds without a primal certificate: a restricted program's
/// infeasibility decides nothing, so only a primal or an exactly checked
/// dual of the FULL-horizon problem may ("invalidated", at the certificate path).
void decide_fixed_bounds(const CertifyRun& run, const DeltaFormSolution& first, CertifiedBounds& out) {
  if (out.verified() || !run.o.lower_end || run.kyp) return;
  DeltaFormSolution full = first;
  if (run.K != 0) {
    full = run.solve(0, false, true);
    CertifiedBounds again;
    certify_upper_end(run, full, again);
    add_stage_seconds(again, out);
    if (again.verified() || !has_solution(full.solve.status)) {
      const std::string restricted = out.reason;
      out = again;
      out.full_horizon = true;
      if (!again.verified() && !restricted.empty())
        out.reason = again.reason + " (first, with " + std::to_string(run.K) + " taps: " + restricted + ")";
    }
  } else if (full.dual_c1.size() == 0) {
    full = run.solve(0, false, true);
  }
  if (out.verified() || full.solve.status != SolveStatus::kPrimalInfeasible || full.dual_c1.size() == 0) return;
  if (run.o.progress) run.o.progress("infeasible: building and checking the dual certificate of invalidation");
  DualOutcome d = certify_dual(run.model, run.exact.exp, run.exact.sim, full, run.o);
  if (d.verified()) out.outcome = CertifyOutcome::kInvalidated;
  out.lower.seconds = d.seconds;
  out.lower.check_seconds = d.check_seconds;
  if (run.o.progress) run.o.progress(stage_done("invalidation", d.verified(), d.seconds - d.check_seconds, d.check_seconds));
  out.lower.verifier_details = d.verifier_details;
  if (d.verified()) out.certificate = std::move(d.certificate);
  if (!d.verified()) out.reason += "; no exact invalidation certificate: " + d.reason;
}

/// An optimised bound: the lower end from the first solve's dual (KYP has
/// none: its Δ-form twin is solved for it); when the gap stays above
/// gap_target after a K-tap solve and L is small enough, the full horizon
/// too (its primal may lower the upper end, its dual raises the lower end).
void bracket_optimum(const CertifyRun& run, const DeltaFormSolution& first, CertifiedBounds& out) {
  if (run.kyp) {
    const DeltaFormSolution twin = run.solve(run.K, false, true);
    out.solve_seconds += twin.solve.seconds;
    certify_lower_end(run, twin, out);
  } else {
    certify_lower_end(run, first, out);
  }
  const double gap = relative_gap(out);
  if (run.K == 0 || run.exact.horizon > run.o.full_horizon_limit || gap <= run.o.gap_target) return;
  const DeltaFormSolution full = run.solve(0, false, true);
  CertifiedBounds better;
  certify_upper_end(run, full, better);
  if (better.verified() && (!out.verified() || better.upper < out.upper)) {
    add_stage_seconds(better, out);
    better.lower = out.lower;
    out = better;
  } else {
    add_stage_seconds(out, better);
  }
  out.full_horizon = true;
  certify_lower_end(run, full, out);
}

/// Steps 2–6 by solving: the first solve and its primal certificate (the
/// upper end), then the lower end, or the verdict at fixed bounds.
CertifiedBounds certify_by_solving(const CertifyRun& run) {
  CertifiedBounds out;
  const DeltaFormSolution first =
      run.given ? *run.given : run.solve(run.K, run.kyp, run.o.lower_end && !run.kyp && !run.feasibility);
  certify_upper_end(run, first, out);
  out.full_horizon = run.K == 0;
  if (run.feasibility) decide_fixed_bounds(run, first, out);
  else if (run.o.lower_end) bracket_optimum(run, first, out);
  else out.lower.reason = "not requested";
  if (run.kyp && run.feasibility && !out.verified()) out.reason += " (KYP restriction: not a verdict; run without --delta-norm kyp)";
  return out;
}

}  // namespace

namespace {

/// certify_fixed_model, with the first solve `given` when it fits the run (else solved).
CertifiedBounds certify_fixed_model_run(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in,
                                        const CertifyOptions& options, SdpSolver& solver, const DeltaFormSolution* given) {
  const Stopwatch total;
  // 1. Exact signals, and their doubles once.
  const ExactSignals es = exact_signals(model, exp_in);
  const double signals_seconds = total.seconds();
  if (es.horizon == 0 || model.nz() == 0) check_uncertainty_excited(nearest_double(es.sim.z));  // throws the usual InputError
  DeltaFormSignals doubles{nearest_double(es.sim.z), nearest_double(es.r), es.exp.records};
  check_finite_signal(doubles.z, "certification (Theorem 2.1)", "the model's uncertainty channel z, in double precision");
  check_finite_signal(doubles.r, "certification (Theorem 2.1)", "the residual r = y - yhat, in double precision");
  // A weighted objective stated on signals scaled to unit size (certify/
  // bound_scaling.h): the same program in original units with λ_orig.
  SignalScales scales;
  CertifyRun run{model, es, std::move(doubles), in_original_units(options, model, es.sim, es.exp, &scales),
                 BoundObjective{}, solver};
  run.objective = solver_objective(run.o.objective);
  run.kyp = run.o.delta_norm == DeltaNorm::kKyp;
  run.feasibility = run.o.objective.kind == BoundObjective::Kind::kFeasibility;
  if (run.kyp && run.o.max_taps <= 0) throw InputError("certify: the KYP Delta form needs a finite number of taps (--max-taps > 0)");
  // The structured full-horizon solve is cheaper than a K-tap SDP and exact for the horizon.
  const bool structured = run.o.structured && !run.kyp && barrier_applies(Mat<double>::Ones(1, 1), Mat<double>::Ones(1, 1), run.objective);
  run.K = !structured && run.o.max_taps > 0 && run.o.max_taps < es.horizon ? run.o.max_taps : 0;
  if (given && !options.scale_signals && structured && run.K == 0 && !run.feasibility && run.o.lower_end && given->horizon == es.horizon &&
      given->taps.cols() == model.ny * model.nz())
    run.given = given;

  // δ = 0 and the other degenerate objectives: exact, at once, no solve (certify/closed_form.h); else 2–6.
  std::optional<CertifiedBounds> closed = certify_closed_form({model, es.exp, es.r, es.horizon, ToeplitzMode::kSignal}, run.o);
  CertifiedBounds out = closed ? std::move(*closed) : certify_by_solving(run);
  out.scales = scales;
  out.signals_seconds = signals_seconds;
  out.total_seconds = total.seconds();
  out.outcome = outcome_of(out, options.objective);
  return out;
}

}  // namespace

CertifiedBounds certify_fixed_model(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in,
                                    const CertifyOptions& options, SdpSolver& solver) {
  return certify_fixed_model_run(model, exp_in, options, solver, nullptr);
}

CertifiedBounds certify_fixed_model_from(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                         const CertifyOptions& options, SdpSolver& solver,
                                         const DeltaFormSolution& solution) {
  CertifiedBounds b = certify_fixed_model_run(model, exp, options, solver, &solution);
  if (b.verified() && b.lower.verified()) return b;
  CertifiedBounds solved = certify_fixed_model(model, exp, options, solver);
  add_stage_seconds(solved, b);  // the first attempt's checks took time too
  return solved;
}

CertifiedBounds certify_with_taps(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in,
                                  const Mat<double>& taps, const CertifyOptions& o, const std::string& solver_name) {
  const Stopwatch total;
  CertifiedBounds out;
  const ExactSignals es = exact_signals(model, exp_in);
  out.signals_seconds = total.seconds();
  const Simulation<Rational>& sim = es.sim;
  const Mat<Rational>& r = es.r;
  const Eigen::Index horizon = es.horizon;
  if (horizon == 0 || model.nz() == 0) check_uncertainty_excited(nearest_double(sim.z));  // throws the usual InputError
  if (taps.cols() != model.ny * model.nz())
    throw std::invalid_argument("certify_with_taps: taps have " + std::to_string(taps.cols()) + " columns, expected ny*nz");
  // Taps beyond the horizon never act on the data (w_k only sees h_0 … h_{L−1}).
  const Mat<double> used = taps.topRows(std::min<Eigen::Index>(taps.rows(), horizon));
  out.taps = used.rows();
  out.horizon = horizon;
  out.delta2_solver = toeplitz_norm2(used, horizon, model.ny, model.nz());
  certify_taps(model, es.exp, sim, r, used, horizon, o, solver_name, out);
  if (out.verified()) out.upper = objective_at(o.objective, out.delta2, out.dmax2);
  out.total_seconds = total.seconds();
  out.outcome = outcome_of(out, o.objective);
  return out;
}
}  // namespace lpvid

namespace lpvid {
namespace {

/// certify_fixed_model_paper without its outcome (`total` started with the call).
CertifiedBounds certify_w_form(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in, const CertifyOptions& o,
                               SdpSolver& solver, const Stopwatch& total) {
  CertifiedBounds out;
  const ExactSignals es = exact_signals(model, exp_in);
  out.signals_seconds = total.seconds();
  const Experiment<Rational>& exp = es.exp;
  const Simulation<Rational>& sim = es.sim;
  const Mat<Rational>& r = es.r;
  const Eigen::Index n = es.n, ny = model.ny;
  if (std::optional<CertifiedBounds> closed = certify_closed_form({model, exp, r, 0, ToeplitzMode::kPaper}, o)) {
    closed->signals_seconds = out.signals_seconds;
    return *closed;
  }
  const Mat<Rational> Tz = T_z_paper(model, exp);
  AffineSignals sig;
  sig.zb = nearest_double(sim.z);
  sig.rb = nearest_double(r);
  sig.Tz_paper = nearest_double(Tz);
  const BoundObjective obj = solver_objective(o.objective);
  const RelaxedSolution sol = solve_relaxed(sig, Vec<double>(0), obj, solver, o.solver);
  out.solve_status = sol.solve.status;
  out.solve_seconds = sol.solve.seconds;
  if (!has_solution(sol.solve.status)) {
    out.reason = std::string("the w-form solve of Theorem 2.1 ended with status ") + to_string(sol.solve.status);
    return out;
  }
  const Stopwatch build;
  Certificate c;
  c.model = model;
  c.mode = ToeplitzMode::kPaper;
  c.form = CertificateForm::kW;
  c.w = Mat<Rational>::Zero(n, ny);
  // A fixed δ = 0 forces T_w = 0: w = 0 exactly (the solver's w is only as
  // small as its tolerance, which the exact check of δ² = 0 rejects).
  const bool zero_w = o.objective.delta_fixed() && o.objective.delta.approx == 0.0;
  for (Eigen::Index k = zero_w ? n : sol.leading_zeros; k < n; ++k)
    for (Eigen::Index i = 0; i < ny; ++i) c.w(k, i) = round_to_digits(sol.w(k, i), o.digits);
  if (!set_dmax2(c, residual_energy(r - c.w), Rational(static_cast<long>(n * ny)), o, out)) return out;
  out.delta2_solver = sol.delta2;
  finish_certificate(c, exp, [&] { return sol.delta2; }, o, solver.name(), build, out);
  if (out.verified()) out.upper = objective_at(o.objective, out.delta2, out.dmax2);  // as the Δ form's upper end
  return out;
}

}  // namespace

CertifiedBounds certify_fixed_model_paper(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in,
                                          const CertifyOptions& o, SdpSolver& solver) {
  if (exp_in.record_count() > 1)
    throw InputError("--toeplitz paper takes one record: its T_z = T_G12 T_u has no meaning across records (use the signal mode)");
  const Stopwatch total;
  CertifiedBounds out = certify_w_form(model, exp_in, o, solver, total);
  out.total_seconds = total.seconds();
  out.outcome = outcome_of(out, o.objective);
  return out;
}

}  // namespace lpvid
