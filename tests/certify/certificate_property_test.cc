// Certificates (docs/design.md §10): every certificate the pipeline writes verifies,
// and a perturbation beyond its stated margin is rejected with the failing
// constraint named; the signal (Δ form) and paper (w form) Toeplitz modes
// agree for LTI models (docs/design.md §6.3).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/file_io.h"
#include "core/sha256.h"
#include "data/csv_reader.h"
#include "certify/certify.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "toeplitz/fir.h"
#include "toeplitz/signal_toeplitz.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

using namespace gen;
namespace fs = std::filesystem;

bool mentions(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

/// Writes `c` with a copy of the data (the bytes given) into its own
/// sub-folder of `root` and checks it from the file. With `rehash` the
/// certificate's sha256 is updated to the new bytes.
CertificateVerdict check_variant(const ScratchDir& root, const std::string& name, Certificate c,
                                 const LpvModel<Rational>& model, const Experiment<Rational>& exp, bool rehash = false) {
  const fs::path dir = root.path() / name;
  fs::create_directories(dir);
  const std::string data = (dir / "data.csv").string();
  write_experiment_csv(data, model, exp);
  c.records.front().data.file = "data.csv";
  if (rehash) c.records.front().data.sha256 = sha256_hex(read_text_file(data));
  const std::string path = (dir / "certificate.json").string();
  write_certificate(path, c);
  return check_certificate_file(path);
}

double max_abs(const Mat<Rational>& m) {
  double a = 0;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) a = std::max(a, std::abs(nearest_double(m(i, j))));
  return a;
}

// Δ form. Certificate of the weighted optimum (λ = 1/2, so δ² > 0 and
// d_max² > 0 generically: at δ = 0 moving a little residual into w lowers
// d_max² linearly and raises δ² quadratically, and vice versa); then
//  (a) δ² lowered by 10·margin + 1e-8 relative: (C1) fails. δ² is
//      ‖T_Δ̂‖²·(1 + margin) rounded up to 12 digits, and ‖T_Δ̂‖² is the
//      exact norm up to ~1e-14, so the lowered δ² is below it;
//  (b) d_max² lowered by 1e-6 relative: (C2) fails (it is ‖d‖²/(n·ny)
//      rounded UP to 15 digits, i.e. by less than 1e-14 relative);
//  (c) one y value changed by 1e-12, sha256 kept: the data hash fails;
//  (c') one y value changed by a lot, sha256 updated: (C2) fails;
//  (d) one tap changed by 1000·max|tap| + 1: (C2) fails, or (C1) — both
//      must, since ‖T_Δ‖ ≤ K·√(ny·nz)·max|tap| < 999·max|tap| here;
// and the control: the same certificate rewritten unchanged, and with both
// bounds doubled, is consistent.
RC_GTEST_PROP(CertificateProperty, DeltaFormPerturbationsBeyondTheMarginAreRejected, ()) {
  IdentCaseOptions o;
  o.model.allow_general = true;
  o.min_n = 6;
  o.max_n = 16;
  const IdentCase ic = *ident_case(o);
  ScratchDir dir("perturb");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  const CertifiedBounds b =
      written(certify_fixed_model(ic.model, ic.exp, certify_options(weighted_objective(0.5), data), *solver), dir.file("c.json"));
  RC_LOG() << "certify: " << b.verified() << " " << b.reason << " delta2 " << nearest_double(b.delta2) << " dmax2 "
           << nearest_double(b.dmax2) << " margin " << b.margin << "\n";
  RC_ASSERT(b.verified());
  RC_ASSERT(check_certificate_file(dir.file("c.json")).holds);
  const Certificate cert = read_certificate(dir.file("c.json"));
  RC_ASSERT(cert.delta2 == b.delta2);
  RC_ASSERT(cert.dmax2 == b.dmax2);
  RC_ASSERT(cert.delta2 > 0);
  RC_ASSERT(cert.dmax2 > 0);
  RC_ASSERT(cert.form == CertificateForm::kDelta);

  {  // controls
    RC_ASSERT(check_variant(dir, "same", cert, ic.model, ic.exp).holds);
    Certificate c2 = cert;
    c2.delta2 *= 2;
    c2.dmax2 *= 2;
    RC_ASSERT(check_variant(dir, "looser", c2, ic.model, ic.exp).holds);
  }
  {  // (a)
    Certificate c2 = cert;
    c2.delta2 *= Rational(1) - exact_rational_of_double(10 * b.margin + 1e-8);
    const CertificateVerdict v = check_variant(dir, "a", c2, ic.model, ic.exp);
    RC_LOG() << "(a) " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "(C1) fails"));
  }
  {  // (b)
    Certificate c2 = cert;
    c2.dmax2 *= Rational(1) - Rational(1) / Rational(1000000);
    const CertificateVerdict v = check_variant(dir, "b", c2, ic.model, ic.exp);
    RC_LOG() << "(b) " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "(C2) fails"));
  }
  const int k = *uniform_int(0, static_cast<int>(ic.exp.n()) - 1);
  const int i = *uniform_int(0, ic.model.ny - 1);
  {  // (c)
    Experiment<Rational> e2 = ic.exp;
    e2.y(k, i) += Rational(1) / Rational(1000000000000LL);
    const CertificateVerdict v = check_variant(dir, "c", cert, ic.model, e2);
    RC_LOG() << "(c) " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "sha256"));
  }
  {  // (c')
    Experiment<Rational> e2 = ic.exp;
    e2.y(k, i) += Rational(1000) * (Rational(1) + decimal_round(max_abs(ic.exp.y), 3));
    const CertificateVerdict v = check_variant(dir, "c2", cert, ic.model, e2, /*rehash=*/true);
    RC_LOG() << "(c') " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "(C2) fails"));
  }
  {  // (d)
    Certificate c2 = cert;
    const int l = *uniform_int(0, static_cast<int>(cert.taps.rows()) - 1);
    c2.taps(l, 0) += Rational(1000) * decimal_round(max_abs(cert.taps), 3) + Rational(1);
    const CertificateVerdict v = check_variant(dir, "d", c2, ic.model, ic.exp);
    RC_LOG() << "(d) tap " << l << ": " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "(C2) fails") || mentions(v.reason, "(C1) fails"));
  }
}

IdentCaseOptions lti_options() {
  IdentCaseOptions o;
  o.model.lti = true;
  o.model.allow_general = true;
  o.min_n = 6;
  o.max_n = 14;
  return o;
}

/// d_max for kMinDelta that is feasible and tight: w must vanish where z
/// does (k < m), so d_k = r_k there; on the rest w can match r (SISO: T_z is
/// invertible there) and must remove 3/4 of its energy, so δ is clearly > 0:
/// n·ny·d_max² = ‖r_{<m}‖² + ‖r_{≥m}‖²/4.
double fixed_dmax_for(const FixedSignals& s) {
  const Eigen::Index m = leading_zero_samples(s.z);
  const double head = s.r.topRows(m).squaredNorm(), tail = s.r.bottomRows(s.r.rows() - m).squaredNorm();
  return std::sqrt((head + 0.25 * tail) / static_cast<double>(s.r.size()));
}

/// Paper-mode T_z = T_G12·T_u (exact) and the number of its trailing zero
/// columns (samples where w is forced to zero).
struct PaperTz {
  Mat<Rational> Tz;
  Eigen::Index m = 0;
};
PaperTz paper_tz(const LpvModel<Rational>& model, const Experiment<Rational>& exp) {
  PaperTz p{T_z_paper(model, exp), 0};
  const Eigen::Index n = p.Tz.cols();
  auto zero_col = [&](Eigen::Index j) {
    for (Eigen::Index i = 0; i < p.Tz.rows(); ++i)
      if (p.Tz(i, j) != 0) return false;
    return true;
  };
  while (p.m < n && zero_col(n - 1 - p.m)) ++p.m;
  return p;
}

/// The w form meets (C1) only up to the solver's feasibility tolerance
/// (1e-8, scaled units); in directions where T_zᵀT_z is smaller than that,
/// no inflation of δ² repairs it. So paper-mode certification is only
/// expected to pass when cond(T_z)² ≪ 1e8. Observed: passes at cond 1e3,
/// needs margin 1e-1 at cond 6.5e4, fails at cond 3.7e5 (n = 10–14), but
/// also passed once at cond 5.6e8 with margin 1e-3.
constexpr double kWellConditioned = 1e3;

/// cond(T_z) on its non-zero columns (double SVD).
double paper_condition(const PaperTz& p) {
  const Mat<double> T = nearest_matrix(Mat<Rational>(p.Tz.leftCols(p.Tz.cols() - p.m)));
  Eigen::JacobiSVD<Mat<double>> svd(T);
  const auto& s = svd.singularValues();
  return s(0) / s(s.size() - 1);
}

/// An exact lower bound q on the smallest δ² that (C1) of the w form allows
/// for this w: q = vᵀT_wᵀT_w v / vᵀT_zᵀT_z v for v the top generalized
/// eigenvector (computed in double, then evaluated exactly). With δ² < q,
/// [v; −T_w v/δ²] is a negative direction of [T_zᵀT_z, T_wᵀ; T_w, δ²I].
Rational rayleigh_lower_bound(const PaperTz& p, const Mat<Rational>& w) {
  const Mat<Rational> G = p.Tz.transpose() * p.Tz;
  const Mat<Rational> Tw = signal_toeplitz(w);
  const Mat<Rational> H = Tw.transpose() * Tw;
  const Eigen::Index L = G.rows() - p.m;
  const Mat<double> GL = nearest_matrix(Mat<Rational>(G.topLeftCorner(L, L)));
  const Mat<double> HL = nearest_matrix(Mat<Rational>(H.topLeftCorner(L, L)));
  Eigen::GeneralizedSelfAdjointEigenSolver<Mat<double>> ges(HL, GL);
  Vec<Rational> v = Vec<Rational>::Zero(G.rows());
  for (Eigen::Index i = 0; i < L; ++i) v(i) = exact_rational_of_double(ges.eigenvectors()(i, L - 1));
  const Rational den = (v.transpose() * G * v)(0, 0);
  return den > 0 ? Rational((v.transpose() * H * v)(0, 0) / den) : Rational(0);
}

// w form (paper mode, LTI model so that paper = signal): the certificate
// verifies; a large change of one w entry, or δ² just below an exact lower
// bound of the minimal δ² for the certificate's w, is rejected, naming the
// constraint.
// The w form squares the conditioning of T_z (certify.h): for cond(T_z)
// above kWellConditioned the margin ladder may not reach a passing δ². Then
// it must still never claim a bound.
RC_GTEST_PROP(CertificateProperty, WFormPerturbationsAreRejected, ()) {
  const IdentCase ic = *ident_case(lti_options());
  ScratchDir dir("wform");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  const FixedSignals s = fixed_signals(ic.model, ic.exp);
  const PaperTz ptz = paper_tz(ic.model, ic.exp);
  const double cond = paper_condition(ptz);
  const CertifiedBounds b = written(certify_fixed_model_paper(
      ic.model, ic.exp, certify_options(min_delta_objective(fixed_dmax_for(s)), data), *solver), dir.file("c.json"));
  RC_LOG() << "cond(T_z) = " << cond << ", certify (paper): " << b.verified() << " " << b.reason << " delta2 "
           << nearest_double(b.delta2) << " margin " << b.margin << "\n";
  RC_CLASSIFY(cond > kWellConditioned, "cond(T_z) > 1e3");
  if (!b.verified()) {
    RC_ASSERT(cond > kWellConditioned);
    RC_ASSERT(!b.reason.empty());
    RC_ASSERT(b.delta2 == Rational(0));
    RC_ASSERT(b.dmax2 == Rational(0));
    RC_ASSERT(!fs::exists(dir.file("c.json")));
    return;
  }
  const Certificate cert = read_certificate(dir.file("c.json"));
  RC_ASSERT(cert.form == CertificateForm::kW);
  RC_ASSERT(cert.mode == ToeplitzMode::kPaper);
  RC_ASSERT(cert.delta2 > 0);
  // the upper end of min δ² is the certified δ² (paper mode once reported 0 here)
  RC_ASSERT(b.upper == b.delta2);
  RC_ASSERT(b.upper == cert.delta2);
  RC_ASSERT(check_variant(dir, "same", cert, ic.model, ic.exp).holds);
  {  // (e) one w entry changed by a lot (where w may be non-zero: before the trailing zero columns)
    Certificate c2 = cert;
    const int k = *uniform_int(0, static_cast<int>(ic.exp.n() - ptz.m) - 1);
    const int i = *uniform_int(0, ic.model.ny - 1);
    c2.w(k, i) += Rational(1000) * (Rational(1) + decimal_round(max_abs(cert.w), 3));
    const CertificateVerdict v = check_variant(dir, "e", c2, ic.model, ic.exp);
    RC_LOG() << "(e) w(" << k << "," << i << "): " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "(C2) fails") || mentions(v.reason, "(C1) fails"));
  }
  {  // (e') δ² below the exact lower bound q of the minimal δ² for this w
    const Rational q = rayleigh_lower_bound(ptz, cert.w);
    RC_LOG() << "(e') delta2 / q = " << nearest_double(cert.delta2 / q) << "\n";
    RC_ASSERT(q > 0);
    RC_ASSERT(q <= cert.delta2);  // the certificate passed, so δ² ≥ its minimum ≥ q
    if (cond <= kWellConditioned) RC_ASSERT(nearest_double(cert.delta2 / q) <= 1 + 10 * b.margin + 1e-6);  // and tight
    Certificate c2 = cert;
    c2.delta2 = q * (Rational(1) - Rational(1) / Rational(1000000000000LL));
    const CertificateVerdict v = check_variant(dir, "e2", c2, ic.model, ic.exp);
    RC_LOG() << "(e') " << v.reason << "\n";
    RC_ASSERT(!v.holds);
    RC_ASSERT(mentions(v.reason, "(C1) fails"));
  }
}

// Both Toeplitz modes agree for LTI models (docs/design.md §6.3): the Δ form (signal,
// full horizon) and the w form (paper, T_z = T_G12·T_u) have the same
// minimal δ at a fixed d_max. For SISO T_z is invertible after the leading
// zeros, so the problems are equivalent; for MIMO the Δ form is exact as
// well (Poolla et al.: the time-domain condition T_wᵀT_w ⪯ δ²T_zᵀT_z is the
// tangential Carathéodory–Fejér condition for a causal Δ with ‖Δ‖ ≤ δ).
// Observed: for cond(T_z) ≤ 1e3 the two solver optima agree to ≤ 1e-7
// relative (checked at 1e-4, as asked), SISO and MIMO alike. Beyond, either
// form can fail numerically: the w form (it squares the conditioning)
// differed by up to 4.9e-4 at cond 8.3e4 and its w then failed the exact
// check even with δ² + 10 %, while the Δ form certified with margin 1e-9;
// conversely, when the minimal δ is huge (δ² = 7.9e5 at cond 2.5e5, ny = 2,
// nz = 1, n = 6; δ² = 4.6e5 at cond 6.7e5, SISO, n = 8) CSDP and SDPA both
// call the Δ form infeasible although T_Δ = T_w·T_z⁻¹ exists (a false
// "invalidated"), while the w form certified. Whenever both certify, the CERTIFIED δ² agree to 1e-4 plus the
// margins the two certificates needed (the w form needed up to 1e-1).
RC_GTEST_PROP(CertificateProperty, ToeplitzModesAgreeForLtiModels, ()) {
  const IdentCase ic = *ident_case(lti_options());
  ScratchDir dir("modes");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  const double dmax = fixed_dmax_for(fixed_signals(ic.model, ic.exp));
  const double cond = paper_condition(paper_tz(ic.model, ic.exp));
  const CertifiedBounds sig = written(certify_fixed_model(
      ic.model, ic.exp, certify_options(min_delta_objective(dmax), data, 0), *solver), dir.file("signal.json"));
  const CertifiedBounds pap = written(certify_fixed_model_paper(
      ic.model, ic.exp, certify_options(min_delta_objective(dmax), data), *solver), dir.file("paper.json"));
  const double a = nearest_double(sig.delta2), p = nearest_double(pap.delta2);
  const double as = sig.delta2_solver, ps = pap.delta2_solver;
  RC_LOG() << "ny = " << ic.model.ny << ", nz = " << ic.model.nz() << ", n = " << ic.exp.n() << ", cond(T_z) = " << cond
           << ": solver delta2 signal " << as << " paper " << ps << " (rel " << std::abs(as - ps) / std::max(as, ps)
           << "); certified signal " << sig.verified() << " " << a << " margin " << sig.margin << " (" << sig.reason
           << "), paper " << pap.verified() << " " << p << " margin " << pap.margin << " (" << pap.reason << ")\n";
  RC_CLASSIFY(ic.model.ny > 1 || ic.model.nz() > 1, "MIMO");
  RC_CLASSIFY(cond > kWellConditioned, "cond(T_z) > 1e3");
  RC_CLASSIFY(!sig.verified(), "Delta form not certified");
  RC_CLASSIFY(!pap.verified(), "w form not certified");
  if (cond <= kWellConditioned) {
    RC_ASSERT(sig.solve_status == SolveStatus::kOptimal);
    RC_ASSERT(pap.solve_status == SolveStatus::kOptimal);
    RC_ASSERT(std::abs(as - ps) <= 1e-4 * std::max(as, ps));
    RC_ASSERT(sig.verified());
    RC_ASSERT(pap.verified());
  }
  if (sig.verified() && pap.verified()) RC_ASSERT(std::abs(a - p) <= (1e-4 + sig.margin + pap.margin) * std::max(a, p));
}

// A fixed δ = 0 in paper mode: data = model output + noise (Δ = 0) is
// consistent with δ = 0, so the w form must certify it (w = 0 exactly).
RC_GTEST_PROP(CertificateProperty, PaperModeZeroDeltaIsCertified, ()) {
  IdentCaseOptions o = lti_options();
  o.zero_delta = true;
  const IdentCase ic = *ident_case(o);
  ScratchDir dir("paper0");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, ic.model, ic.exp);
  auto solver = make_solver("csdp");
  const CertifiedBounds b = written(certify_fixed_model_paper(
      ic.model, ic.exp, certify_options(min_dmax_objective(0.0), data), *solver), dir.file("c.json"));
  RC_LOG() << "paper, delta = 0: " << b.verified() << " " << b.reason << "\n";
  RC_ASSERT(b.verified());
  RC_ASSERT(b.delta2 == Rational(0));
  RC_ASSERT(b.upper == b.dmax2);  // min d_max²'s upper end is the certified d_max²
  RC_ASSERT(b.dmax <= 0.9 * ic.dmax * (1 + 1e-3));
}


// KNOWN ISSUE, not fixed (reported): in paper mode a tiny fixed δ (here
// 1e-9 of the generating one; 1e-6 and 1e-3 too when cond(T_z) ≳ 1e8)
// cannot be certified: the solver meets (C1) of the w form only up to its
// absolute tolerance and the fixed δ² leaves no room; unlike the Δ form
// (certify.cc now shrinks the taps onto a fixed δ) the w form has no cheap
// repair (it would need the generalized eigenvalue of T_wᵀT_w against
// T_zᵀT_z). δ = 0 itself is handled (w = 0). Enable once fixed.
TEST(CertificateKnownIssue, DISABLED_PaperModeTinyFixedDeltaIsCertified) {
  IdentCaseOptions o;
  o.model.lti = true;
  o.min_n = 6;
  o.max_n = 14;
  auto solver = make_solver("csdp");
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    const IdentCase ic = sample(ident_case(o), seed);
    ScratchDir dir("paper-tiny");
    const std::string data = dir.file("data.csv");
    write_experiment_csv(data, ic.model, ic.exp);
    const CertifiedBounds b = written(certify_fixed_model_paper(
        ic.model, ic.exp, certify_options(min_dmax_objective(1e-9 * ic.delta), data), *solver), dir.file("c.json"));
    EXPECT_TRUE(b.verified()) << "seed " << seed << ": " << b.reason;
  }
}

}  // namespace
}  // namespace lpvid
