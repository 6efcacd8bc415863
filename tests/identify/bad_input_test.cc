// Bad inputs (docs/design.md §7, §12): data that says nothing about the uncertainty
// (z ≡ 0) is an InputError naming the problem; bounds the data contradicts
// give "not verified" with a reason and never a bound or a certificate.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <string>

#include "core/input_error.h"
#include "toeplitz/affine_residual.h"
#include "certify/certify.h"
#include "identify/identify.h"
#include "lmi/delta_form_lmi.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

using namespace gen;

/// Runs f and returns the InputError's message ("" if none was thrown).
template <typename F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// u ≡ 0 with x0 = 0: every state, ŷ and z are 0 for every θ, so δ is
// undetermined. identify() (both methods), solve_delta_form(),
// certify_fixed_model() and certify_with_taps() must say so (InputError
// mentioning "ill-posed"), for every structure.
RC_GTEST_PROP(IdentifyBadInput, ZeroInputIsIllPosed, ()) {
  IdentCaseOptions o;
  o.model.allow_general = true;
  o.model.max_correction = 2;
  o.min_n = 4;
  o.max_n = 10;
  IdentCase c = *ident_case(o);
  c.exp.u.setZero();  // y keeps the generated values (noise, say)
  ScratchDir dir("zero-u");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, c.model, c.exp);
  auto solver = make_solver("csdp");

  const FixedSignals s = fixed_signals(c.model, c.exp);
  RC_ASSERT(s.z.isZero(0.0));
  const std::string e1 = input_error_of(
      [&] { solve_delta_form(s.z, s.r, weighted_objective(0.5), *solver, SolverOptions{}, 0); });
  RC_LOG() << "solve_delta_form: " << e1 << "\n";
  RC_ASSERT(e1.find("ill-posed") != std::string::npos);

  const std::string e2 = input_error_of([&] {
    written(certify_fixed_model(c.model, c.exp, certify_options(weighted_objective(0.5), data), *solver), dir.file("c.json"));
  });
  RC_LOG() << "certify_fixed_model: " << e2 << "\n";
  RC_ASSERT(e2.find("ill-posed") != std::string::npos);
  RC_ASSERT(!std::filesystem::exists(dir.file("c.json")));

  if (!c.model.correction.basis.empty()) {
    const Experiment<double> exp = read_experiment(data, convert_model<double>(c.model));
    for (int variant : {0, 1, 2}) {  // single relaxation step, iterated, alternating
      IdentifyOptions io;
      io.iterate = variant == 1;
      if (variant == 2) io.method = IdentifyMethod::kAlternating;
      const std::string e3 = input_error_of([&] { identify(convert_model<double>(c.model), exp, io, *solver); });
      RC_LOG() << "identify (variant " << variant << "): " << e3 << "\n";
      RC_ASSERT(e3.find("ill-posed") != std::string::npos);
    }
    const std::string e4 = input_error_of([&] {
      written(certify_with_taps(c.model, c.exp, Mat<double>::Ones(2, c.model.ny * c.model.nz()),
                        certify_options(weighted_objective(0.5), data), "csdp"), dir.file("c.json"));
    });
    RC_LOG() << "certify_with_taps: " << e4 << "\n";
    RC_ASSERT(e4.find("ill-posed") != std::string::npos);
    RC_ASSERT(!std::filesystem::exists(dir.file("c.json")));
  }
}

// δ = 0 and d_max far below the noise: the model is invalidated at those
// bounds. certify_fixed_model must return verified = false with a reason,
// no bound (δ², d_max² left at 0) and, as its only file, an exactly checked
// "invalidated" certificate; a model identify() may report at the same fixed
// bounds is never certified, and is invalidated exactly too.
RC_GTEST_PROP(IdentifyBadInput, InfeasibleFixedBoundsGiveNoBound, ()) {
  IdentCaseOptions o;
  o.model.allow_general = true;
  o.model.min_correction = 1;
  o.model.max_correction = 1;
  o.min_n = 12;  // n·ny ≥ 12 residual samples
  o.max_n = 16;
  const IdentCase c = *ident_case(o);
  ScratchDir dir("infeasible");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, c.model, c.exp);
  auto solver = make_solver("csdp");
  // The residual of the model is r = Δ∗z + d (+ rounding), with ‖d‖ =
  // 0.9·d_max·√(n·ny): with δ = 0 (w = 0) the noise bound must hold for r,
  // far above d_max' = 1e-3·d_max.
  const double tiny = 1e-3 * c.dmax;
  const CertifiedBounds b = written(certify_fixed_model(
      c.model, c.exp, certify_options(feasibility_objective(0.0, tiny), data), *solver), dir.file("c.json"));
  RC_LOG() << "certify: verified " << b.verified() << ", reason: " << b.reason << ", status " << solve_status_text(b) << "\n";
  const FixedSignals s = fixed_signals(c.model, c.exp);
  RC_LOG() << "RMS(r) = " << rms(s.r) << ", fixed dmax = " << tiny << ", generating delta = " << c.delta << "\n";
  RC_ASSERT(rms(s.r) > 10 * tiny);  // by construction: the data contradicts (δ, d_max) = (0, tiny)
  RC_ASSERT(!b.verified());
  RC_ASSERT(!b.reason.empty());
  RC_ASSERT(b.delta2 == Rational(0));
  RC_ASSERT(b.dmax2 == Rational(0));
  RC_ASSERT(b.delta == 0.0);
  RC_ASSERT(b.dmax == 0.0);
  // No consistency certificate: the only file allowed there is an exactly
  // checked "invalidated" certificate, which this case must get.
  RC_ASSERT(b.invalidated());
  const CertificateVerdict v = check_certificate_file(dir.file("c.json"));
  RC_ASSERT(v.holds);
  RC_ASSERT(v.claim_text == "invalidated");

  // Identification at the same bounds. With δ = 0, (C1) forces T_w = 0, so
  // d = r(θ) and no θ does better than the least-squares floor of r(θ) =
  // r0 − Jr·θ; with ≤ ny·(nx+nu) output parameters against n·ny ≥ 12 samples
  // of random noise that floor is far above d_max'. identify() may still
  // report a "solution" — the δ = 0 program has no interior, and CSDP meets
  // [Lin, T_wᵀ; T_w, 0] ⪰ 0 up to 1e-7 absolute by making θ, hence Lin,
  // huge (λ_max ~ 1e9) so that T_w ~ √(1e9·1e-7) ≠ 0 passes — but then the
  // certificate must refuse: never a certified model at (0, d_max').
  const LpvModel<double> model_d = convert_model<double>(c.model);
  const Experiment<double> exp = read_experiment(data, model_d);
  const AffineResidual<double> a = build_affine_residual(model_d, exp, Unknowns{});
  const Vec<double> theta = a.Jr.colPivHouseholderQr().solve(a.r0);
  const double floor = std::sqrt((a.r0 - a.Jr * theta).squaredNorm() / static_cast<double>(a.r0.size()));
  RC_LOG() << "least-squares floor of RMS(r) = " << floor << "\n";
  RC_ASSERT(floor > 10 * tiny);
  IdentifyOptions io;
  io.objective = feasibility_objective(0.0, tiny);
  const IdentifyResult r = identify(model_d, exp, io, *solver);
  RC_LOG() << "identify: " << to_string(r.status) << " " << r.message << "\n";
  RC_CLASSIFY(has_solution(r.status), "identify claims a model at (0, tiny)");
  if (has_solution(r.status)) {
    const LpvModel<Rational> fixed = fold_rounded(c.model, r.layout, r.p);
    const CertifiedBounds bf = written(certify_fixed_model(
        fixed, c.exp, certify_options(feasibility_objective(0.0, tiny), data), *solver), dir.file("f.json"));
    RC_LOG() << "certify the identified model: " << bf.verified() << " " << bf.reason << "\n";
    RC_ASSERT(!bf.verified());
    RC_ASSERT(!bf.reason.empty());
    // At δ = 0 the decision is exact (certify/closed_form.h: d = r(θ), whose RMS is above the
    // least-squares floor > 10·tiny): the only file is an "invalidated" certificate that holds.
    RC_ASSERT(bf.invalidated());
    const CertificateVerdict vf = check_certificate_file(dir.file("f.json"));
    RC_ASSERT(vf.holds);
    RC_ASSERT(vf.claim_text == "invalidated");
  }
}

}  // namespace
}  // namespace lpvid

namespace lpvid {
namespace {

// A model whose free run diverges along the data (A = 1000·I: the state
// grows like 1000^k and leaves double precision after about 103 samples):
// the double signals are not finite. No solver may see them: certification
// and identification stop with an InputError naming their stage (no
// "cost -nan" from inside a solver), and no certificate is written.
RC_GTEST_PROP(IdentifyBadInput, DivergingFreeRunStopsBeforeTheSolver, ()) {
  IdentCaseOptions o;
  o.model.allow_general = true;
  o.model.max_correction = 2;
  o.min_n = 120;
  o.max_n = 130;
  IdentCase c = *ident_case(o);
  RC_PRE(c.model.nx > 0);
  c.model.A = ParamMatrix<Rational>(c.model.nx, c.model.nx);
  c.model.A.add(constant_monomial(c.model.scheduling.size()),
                Mat<Rational>(Mat<Rational>::Identity(c.model.nx, c.model.nx) * Rational(1000)));
  ScratchDir dir("diverging");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, c.model, c.exp);
  auto solver = make_solver("csdp");
  const std::string e1 = input_error_of([&] {
    written(certify_fixed_model(c.model, c.exp, certify_options(weighted_objective(0.5), data), *solver), dir.file("c.json"));
  });
  RC_LOG() << "certify_fixed_model: " << e1 << "\n";
  RC_ASSERT(e1.find("certification (Theorem 2.1)") != std::string::npos);
  RC_ASSERT(e1.find("no solver was called") != std::string::npos);
  RC_ASSERT(!std::filesystem::exists(dir.file("c.json")));
  if (!c.model.correction.basis.empty()) {
    const Experiment<double> exp = read_experiment(data, convert_model<double>(c.model));
    for (IdentifyMethod method : {IdentifyMethod::kRelaxation, IdentifyMethod::kAlternating}) {
      IdentifyOptions io;
      io.method = method;
      const std::string e2 = input_error_of([&] { identify(convert_model<double>(c.model), exp, io, *solver); });
      RC_LOG() << "identify: " << e2 << "\n";
      RC_ASSERT(e2.find("Theorem 3.1") != std::string::npos);
      RC_ASSERT(e2.find("no solver was called") != std::string::npos);
    }
  }
}

}  // namespace
}  // namespace lpvid
