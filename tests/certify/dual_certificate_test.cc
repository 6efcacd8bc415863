// Dual certificates (toeplitz/delta_form_dual.h): "invalidated" and
// "lower_bound" claims are checked exactly by the verifier, and the answers
// are known by construction:
//  - the data come from a known truth (Δ with ‖T_Δ‖ < δ, noise with RMS
//    0.9·d_max), so the model is consistent at (δ, d_max): an "invalidated"
//    claim there is FALSE and a lower bound on d_max² at δ cannot exceed d_max²;
//  - by the triangle inequality ‖d‖ ≥ ‖r‖ − ‖T_Δ‖·‖z‖ ≥ ‖r‖ − δ‖z‖, so with
//    δ = ‖r‖/(4‖z‖) and √(n·ny)·d_max = ‖r‖/2 the model is invalidated.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "examples/paper_example1.h"
#include "certify/certify.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "core/input_error.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

using namespace gen;

/// Writes the (tampered) certificate next to the original and checks it.
CertificateVerdict check_tampered(const ScratchDir& dir, const std::string& name, const Certificate& c) {
  const std::string path = dir.file(name);
  write_certificate(path, c);
  try {
    return check_certificate_file(path);
  } catch (const InputError& e) {  // refused when read: the claim is not accepted either
    CertificateVerdict refused;
    refused.holds = false;
    refused.reason = e.what();
    return refused;
  }
}

RC_GTEST_PROP(DualCertificateProperty, InvalidatedAndConsistentByConstructionNeverBoth, ()) {
  IdentCaseOptions o;
  o.min_n = 6;
  o.max_n = 14;
  const IdentCase ic = *ident_case(o);
  ScratchDir dir("dual_feas");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");

  // Consistent by construction.
  const CertifiedBounds yes =
      written(certify_fixed_model(ic.model, ic.exp, certify_options(feasibility_objective(ic.delta, ic.dmax), data), *solver), dir.file("yes.json"));
  RC_ASSERT(!yes.invalidated());
  if (yes.verified()) RC_ASSERT(check_certificate_file(dir.file("yes.json")).holds);

  // Invalidated by construction (triangle inequality).
  const FixedSignals s = fixed_signals(ic.model, ic.exp);
  const double nr = s.r.norm(), nz = s.z.norm();
  RC_PRE(nr > 1e-6 && nz > 1e-9);
  const double delta = nr / (4 * nz), dmax = nr / (2 * std::sqrt(static_cast<double>(s.r.size())));
  const std::string path = dir.file("no.json");
  CertifyOptions no_options = certify_options(feasibility_objective(delta, dmax), data);
  no_options.dense_dual = *rc::gen::arbitrary<bool>();  // both forms of the dual certificate
  const CertifiedBounds no = written(certify_fixed_model(ic.model, ic.exp, no_options, *solver), path);
  RC_ASSERT(!no.verified());
  RC_ASSERT(no.invalidated());
  RC_ASSERT(no.outcome == CertifyOutcome::kInvalidated);
  const CertificateVerdict v = check_certificate_file(path);
  RC_ASSERT(v.holds);
  RC_ASSERT(v.claim_text == "invalidated");

  // Tampering: each variant must be rejected.
  const Certificate c = read_certificate(path);
  {  // the claim moved to bounds where the model is consistent by construction: false, must fail
    Certificate t = c;
    t.delta2 = rational_from_text(double_to_text(ic.delta)) * rational_from_text(double_to_text(ic.delta));
    t.dmax2 = rational_from_text(double_to_text(ic.dmax)) * rational_from_text(double_to_text(ic.dmax));
    RC_ASSERT(!check_tampered(dir, "t1.json", t).holds);
  }
  if (c.form == CertificateForm::kDualDelta) {
    {  // one entry of W changed: the dual equality fails
      Certificate t = c;
      const Eigen::Index off = t.dual.horizon * ic.model.ny;
      t.dual.Y1(0, off) += Rational(1, 1000000000);
      t.dual.Y1(off, 0) = t.dual.Y1(0, off);
      const CertificateVerdict tv = check_tampered(dir, "t2.json", t);
      RC_ASSERT(!tv.holds);
      RC_ASSERT(tv.reason.find("dual equality") != std::string::npos);
    }
    {  // a negative diagonal: Y1 is not PSD
      Certificate t = c;
      t.dual.Y1(0, 0) = Rational(-1);
      RC_ASSERT(!check_tampered(dir, "t3.json", t).holds);
    }
  } else {
    RC_ASSERT(c.form == CertificateForm::kDualDeltaPath);
    RC_ASSERT(no_options.dense_dual == false);
    {  // x ≤ 0: the rebuilt point is not PSD; the file is refused
      Certificate t = c;
      t.dual.path.x = Rational(0);
      RC_ASSERT(!check_tampered(dir, "t2.json", t).holds);
    }
    {  // one tap fewer than the horizon
      Certificate t = c;
      t.dual.path.taps = t.dual.path.taps.topRows(t.dual.path.taps.rows() - 1).eval();
      RC_ASSERT(!check_tampered(dir, "t3.json", t).holds);
    }
  }
  {  // g changed: the dual equality (or the margin) fails
    Certificate t = c;
    t.dual.g(t.dual.g.rows() - 1, 0) += Rational(1);
    RC_ASSERT(!check_tampered(dir, "t4.json", t).holds);
  }
  {  // σ ≤ 0
    Certificate t = c;
    t.dual.sigma = Rational(0);
    RC_ASSERT(!check_tampered(dir, "t5.json", t).holds);
  }
}

RC_GTEST_PROP(DualCertificateProperty, LowerEndIsBelowUpperEndAndBelowTheTruth, ()) {
  IdentCaseOptions o;
  o.min_n = 6;
  o.max_n = 14;
  const IdentCase ic = *ident_case(o);
  ScratchDir dir("dual_lower");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  const auto which = *rc::gen::inRange(0, 3);
  const BoundObjective obj = which == 0 ? weighted_objective(0.5)
                             : which == 1 ? min_dmax_objective(ic.delta)
                                          : min_delta_objective(ic.dmax);
  const std::string path = dir.file("c.json");
  const CertifiedBounds b = written(certify_fixed_model(ic.model, ic.exp, certify_options(obj, data), *solver), path);
  RC_ASSERT(b.verified());
  RC_ASSERT(b.lower.verified());
  RC_ASSERT(b.lower.value <= b.upper);
  const Rational truth_delta2 = rational_from_text(double_to_text(ic.delta)) * rational_from_text(double_to_text(ic.delta));
  const Rational truth_dmax2 = rational_from_text(double_to_text(ic.dmax)) * rational_from_text(double_to_text(ic.dmax));
  // The truth is a feasible point: no certified lower end may exceed its objective.
  if (which == 1) RC_ASSERT(b.lower.value <= truth_dmax2);
  if (which == 2) RC_ASSERT(b.lower.value <= truth_delta2);
  if (which == 0) RC_ASSERT(b.lower.value <= (truth_delta2 + truth_dmax2) / 2);
  const CertificateVerdict v = check_certificate_file(lower_certificate_path(path));
  RC_ASSERT(v.holds);
  RC_ASSERT(v.claim_text.rfind("lower_bound", 0) == 0);
  // A claimed lower end above the primal certificate's value is false: rejected.
  Certificate t = read_certificate(lower_certificate_path(path));
  t.lower_bound = b.upper * Rational(11, 10) + Rational(1) / Rational(1000000000000.0);
  RC_ASSERT(!check_tampered(dir, "t.json", t).holds);
}

// A Δ the default restriction cannot hold: the true Δ is a 70-sample delay
// on n = 100 samples, which no 64-tap Δ can represent. With the default
// options (64 taps first) the model must still be certified consistent: a
// restricted program's infeasibility is not a verdict, the full horizon decides.
TEST(DualCertificate, DelayedDeltaIsConsistentWithDefaultOptions) {
  IdentCaseOptions o;
  o.min_n = 100;
  o.max_n = 100;
  o.model.max_nx = 2;
  o.model.max_nu = 1;
  o.model.max_ny = 1;
  o.model.max_rho = 0;
  o.zero_delta = true;
  IdentCase ic = sample(ident_case(o), 8);
  ic.delta = 0.5;
  ic.dmax = 1e-4;
  Mat<double> taps = Mat<double>::Zero(71, 1);
  taps(70, 0) = 1.0;  // w_k = c·z_{k−70}, scaled to ‖T_Δ‖ = 0.5/(1 + 1e-6)
  Mat<double> noise = Mat<double>::Ones(100, 1);
  generate_output(ic, taps, noise);
  ScratchDir dir("delay");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  CertifyOptions co = certify_options(feasibility_objective(0.5, 1e-4), data);
  co.max_taps = CertifyOptions{}.max_taps;  // the library default (64)
  ASSERT_EQ(co.max_taps, 64);
  const CertifiedBounds b = written(certify_fixed_model(ic.model, ic.exp, co, *solver), dir.file("c.json"));
  EXPECT_TRUE(b.verified()) << b.reason;
  EXPECT_FALSE(b.invalidated());
  EXPECT_TRUE(check_certificate_file(dir.file("c.json")).holds);
  // The 64-tap restriction alone cannot: its program is infeasible.
  CertifyOptions restricted = co;
  restricted.lower_end = false;
  restricted.structured = false;  // the SISO full-horizon solver would not restrict
  const CertifiedBounds r = certify_fixed_model(ic.model, ic.exp, restricted, *solver);
  EXPECT_FALSE(r.verified());
  EXPECT_FALSE(r.invalidated());
}

// The KYP restriction (‖Δ‖∞ by the KYP lemma, 2×2, 16 taps)
// certifies the 2×2 Example 1 at n = 60 (it used to end in a solver failure),
// and its interval's ends are ordered; the lower end is the full horizon's dual.
TEST(DualCertificate, KypWorksOnMimoExample1) {
  Example1Options eo;
  eo.n = 60;
  eo.noise_variance = 0.01;
  const LpvModel<Rational> model = example1_initial_model();
  const Experiment<Rational> exp = example1_experiment(eo);
  ScratchDir dir("kyp_ex1");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, model, exp);
  auto solver = make_solver("csdp");
  CertifyOptions co = certify_options(weighted_objective(0.5), data);
  co.delta_norm = DeltaNorm::kKyp;
  co.max_taps = 16;
  const CertifiedBounds b = written(certify_fixed_model(model, exp, co, *solver), dir.file("c.json"));
  ASSERT_TRUE(b.verified()) << b.reason;
  EXPECT_TRUE(check_certificate_file(dir.file("c.json")).holds);
  ASSERT_TRUE(b.lower.verified()) << b.lower.reason;
  EXPECT_LE(b.lower.value, b.upper);
}

}  // namespace
}  // namespace lpvid
