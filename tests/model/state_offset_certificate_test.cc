// A certificate of a model with state functions and a state offset E(ρ)
// (docs/design.md §10): the certify path writes it, the exact verifier
// rebuilds x, z, ŷ with the rounded √ in rational arithmetic and accepts it;
// the same certificate with E or the √ shift moved by 10^-6 is rejected.
//
// Why a mutation must fail: d_max² is ‖d‖²/n rounded UP to 15 digits, so
// the certificate has no room beyond ~1e-15·‖d‖². Moving e by ±ε changes d
// by ±ε·g + O(ε²) (g ≠ 0: e enters every later state), so ‖d‖² changes by
// ±2ε⟨d, g⟩ + ε²‖g‖²; for at least one sign that is ≥ ε²‖g‖² ~ 1e-12·n,
// far above the slack. Hence: at least one of the two signs fails (C2).
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "core/number_text.h"
#include "data/csv_writer.h"
#include "examples/model_literals.h"
#include "toeplitz/affine_residual.h"
#include "certify/certify.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "toeplitz/uncertainty_toeplitz.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

using namespace literals;

/// The 2-vector of two decimal texts.
Vec<Rational> cert_vec(const char* a, const char* b) {
  Vec<Rational> v(2);
  v << dec(a), dec(b);
  return v;
}

/// x1+ = 0.7 x1 + 0.5 u − 0.2·√|x1 + 1/4| + 0.1, x2+ = 0.4 x1 + 0.5 x2 −
/// 0.3·max(x2 − 0.6, 0) + 0.02·|x1 − 0.3|, y = x2 (scheduling s, h, a).
LpvModel<Rational> certified_tank_model() {
  LpvModel<Rational> m;
  m.nx = 2;
  m.nu = m.ny = 1;
  m.scheduling = {"s", "h", "a"};
  m.columns = {{"u1"}, {"y1"}, {"@sqrt(x1+1/4)", "@hinge(x2-0.6)", "@abs(x1-0.3)"}};
  const Monomial one{{0, 0, 0}}, s{{1, 0, 0}}, h{{0, 1, 0}}, a{{0, 0, 1}};
  m.A = ParamMatrix<Rational>(2, 2);
  m.A.add(one, literals::mat(2, 2, {"0.7", "0", "0.4", "0.5"}));
  m.B = ParamMatrix<Rational>(2, 1);
  m.B.add(one, cert_vec("0.5", "0"));
  m.C = ParamMatrix<Rational>(1, 2);
  m.C.add(one, literals::mat(1, 2, {"0", "1"}));
  m.D = ParamMatrix<Rational>(1, 1);
  m.state_offset.basis = {s, h, a, one};
  m.state_offset.values = {cert_vec("-0.2", "0"), cert_vec("0", "-0.3"), cert_vec("0", "0.02"),
                           cert_vec("0.1", "0")};
  m.x0 = Vec<Rational>::Zero(2);
  return m;
}

/// u: a dyadic pseudo-random input in [0, 2); y: the model's exact output
/// plus a pseudo-random disturbance of up to ±0.01, rounded to 6 decimals.
void write_tank_data(const std::string& path, const LpvModel<Rational>& m, int n) {
  Experiment<Rational> e;
  e.u.resize(n, 1);
  e.rho = Mat<Rational>::Zero(n, m.n_rho());
  unsigned s = 12345u;
  auto next = [&] {
    s = s * 1103515245u + 12345u;
    return static_cast<int>((s >> 8) % 1024);
  };
  for (int k = 0; k < n; ++k) e.u(k, 0) = Rational(next()) / Rational(512);
  const Simulation<Rational> sim = simulate(m, e);
  Mat<Rational> y(n, 1);
  for (int k = 0; k < n; ++k) {
    const double v = nearest_double(sim.output(k, 0)) + (next() - 512) / 51200.0;
    y(k, 0) = Rational(static_cast<long>(std::llround(v * 1e6))) / Rational(1000000);
  }
  write_csv(path, {{"u1", column_text(e.u, 0)}, {"y1", column_text(y, 0)}});
}

bool says(const CertificateVerdict& v, const std::string& what) { return v.reason.find(what) != std::string::npos; }

TEST(StateOffsetCertificate, VerifiesExactlyAndMutationsAreRejected) {
  const LpvModel<Rational> model = certified_tank_model();
  gen::ScratchDir dir("state-offset-cert");
  const std::string data = dir.file("data.csv");
  write_tank_data(data, model, 48);
  const Experiment<Rational> exp = gen::read_experiment<Rational>(data, model);
  auto solver = make_solver("csdp");
  const std::string path = dir.file("c.json");
  const CertifiedBounds b =
      gen::written(certify_fixed_model(model, exp, gen::certify_options(gen::weighted_objective(0.5), data), *solver), path);
  ASSERT_TRUE(b.verified()) << b.reason;
  std::cout << "certified delta = " << b.delta << ", dmax = " << b.dmax << ", margin " << b.margin << "\n";
  const CertificateVerdict ok = check_certificate_file(path);
  ASSERT_TRUE(ok.holds) << ok.reason;
  const Certificate cert = read_certificate(path);
  EXPECT_EQ(cert.model.columns.rho, model.columns.rho);
  ASSERT_EQ(cert.model.state_offset.values.size(), 4u);
  for (size_t j = 0; j < 4; ++j) EXPECT_EQ(cert.model.state_offset.values[j], model.state_offset.values[j]);

  // the verifier reads what it is given: rewritten unchanged, still consistent
  auto verdict = [&](const Certificate& c, const std::string& name) {
    const std::string p = dir.file(name);
    write_certificate(p, c);
    return check_certificate_file(p);
  };
  EXPECT_TRUE(verdict(cert, "same.json").holds);

  // E moved by ±10^-6 (the √ term of x1, and the constant): one sign at least fails (C2)
  for (size_t j : {size_t{0}, size_t{3}}) {
    int rejected = 0;
    for (int sign : {1, -1}) {
      Certificate c = cert;
      c.model.state_offset.values[j](0) += Rational(sign) / Rational(1000000);
      const CertificateVerdict v = verdict(c, "e" + std::to_string(j) + (sign > 0 ? "p" : "m") + ".json");
      std::cout << "E[" << j << "] " << (sign > 0 ? "+" : "-") << "1e-6: " << v.reason << "\n";
      if (!v.holds) {
        ++rejected;
        EXPECT_TRUE(says(v, "(C2) fails")) << v.reason;
      }
    }
    EXPECT_GE(rejected, 1) << "state_offset value " << j;
  }
  // the √ column's shift moved by ±10^-6 in its text
  {
    int rejected = 0;
    for (const char* text : {"@sqrt(x1+0.250001)", "@sqrt(x1+0.249999)"}) {
      Certificate c = cert;
      c.model.columns.rho[0] = text;
      const CertificateVerdict v = verdict(c, std::string("shift") + std::to_string(rejected) + text[14] + ".json");
      std::cout << text << ": " << v.reason << "\n";
      if (!v.holds) ++rejected;
    }
    EXPECT_GE(rejected, 1);
  }
  // paper mode cannot hold E(ρ): refused with the reason
  {
    Certificate c = cert;
    c.mode = ToeplitzMode::kPaper;
    const CertificateVerdict v = verdict(c, "paper.json");
    EXPECT_FALSE(v.holds);
    EXPECT_TRUE(says(v, "state_offset")) << v.reason;
  }
}

/// x0 as an unknown (toeplitz/affine_residual.h) with a state offset: the x0
/// columns are the secant sim(x0 + e_c) − sim(x0). With a constant E only
/// (no state columns) the state equation is affine in x0, so the secant must
/// equal the zero-input response from e_c of the model without E (exactly).
TEST(StateOffsetCertificate, FreeX0ColumnsWithAStateOffset) {
  LpvModel<Rational> m;
  m.nx = 2;
  m.nu = m.ny = 1;
  m.columns = {{"u1"}, {"y1"}, {}};
  m.A = ParamMatrix<Rational>(2, 2);
  m.A.add(Monomial{}, literals::mat(2, 2, {"0.7", "0.1", "0.4", "0.5"}));
  m.B = ParamMatrix<Rational>(2, 1);
  m.B.add(Monomial{}, cert_vec("0.5", "0"));
  m.C = ParamMatrix<Rational>(1, 2);
  m.C.add(Monomial{}, literals::mat(1, 2, {"0", "1"}));
  m.D = ParamMatrix<Rational>(1, 1);
  m.state_offset.basis = {Monomial{}};
  m.state_offset.values = {cert_vec("0.3", "-0.2")};
  m.x0 = cert_vec("1", "2");
  Experiment<Rational> e;
  e.u = Mat<Rational>::Constant(12, 1, Rational(1, 2));
  e.y = Mat<Rational>::Zero(12, 1);
  e.rho = Mat<Rational>(12, 0);
  Unknowns u;
  u.correction = false;
  u.offset = false;
  u.x0 = true;
  const AffineResidual<Rational> a = build_affine_residual(m, e, u);
  ASSERT_EQ(a.Jr.cols(), 2);
  LpvModel<Rational> free = m;
  free.state_offset = {};
  Experiment<Rational> zero = e;
  zero.u.setZero();
  for (int c = 0; c < 2; ++c) {
    free.x0 = Vec<Rational>::Zero(2);
    free.x0(c) = 1;
    const Simulation<Rational> s = simulate(free, zero);
    for (Eigen::Index k = 0; k < e.n(); ++k) EXPECT_EQ(a.Jr(k, c), s.yhat(k, 0)) << c << " " << k;
  }
}

}  // namespace
}  // namespace lpvid
