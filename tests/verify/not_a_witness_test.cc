// The claim "not_a_witness" (verify/certificate/certificate_file.h): a primal point that
// fails Theorem 2.1 exactly. Known answers by hand on a two-sample record:
// the model ŷ = u (A = B = C = 0, D = 1, multiplicative W = 1, so z = u),
// data u = (1, 1), y = (1, 2), hence the residual r = (0, 1). A causal Δ with
// taps (h0, h1) gives w = (h0, h0 + h1), d = r − w, and on the horizon of 2
// samples T_Δ = [h0 0; h1 h0], so ‖T_Δ‖ = |h1| when h0 = 0.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/sha256.h"
#include "core/file_io.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

class NotAWitness : public ::testing::Test {
 protected:
  gen::ScratchDir dir{"not-a-witness"};

  /// A certificate with taps (0, h1) on the full horizon at (δ², d_max²).
  Certificate point(const Rational& h1, const Rational& delta2, const Rational& dmax2, CertificateClaim claim,
                    const std::string& u0 = "1") {
    const std::string data = "u1,y1\n" + u0 + ",1\n1,2\n";
    write_text_file(dir.file("data.csv"), data, "data");
    Certificate c;
    c.records.front().data.file = "data.csv";
    c.records.front().data.sha256 = sha256_hex(data);
    LpvModel<Rational>& m = c.model;
    m.nx = m.nu = m.ny = 1;
    m.columns.u = {"u1"};
    m.columns.y = {"y1"};
    const Mat<Rational> zero = Mat<Rational>::Zero(1, 1), one = Mat<Rational>::Constant(1, 1, Rational(1));
    m.A = ParamMatrix<Rational>(1, 1);
    m.A.add(constant_monomial(0), zero);
    m.B = ParamMatrix<Rational>(1, 1);
    m.B.add(constant_monomial(0), zero);
    m.C = ParamMatrix<Rational>(1, 1);
    m.C.add(constant_monomial(0), zero);
    m.D = ParamMatrix<Rational>(1, 1);
    m.D.add(constant_monomial(0), one);
    c.form = CertificateForm::kDelta;
    c.taps = Mat<Rational>(2, 1);
    c.taps << Rational(0), h1;
    c.horizon = 2;
    c.delta2 = delta2;
    c.dmax2 = dmax2;
    c.claim = claim;
    return c;
  }
  CertificateVerdict check(const Certificate& c) { return check_certificate(c, dir.path().string()); }
};

TEST_F(NotAWitness, AWitnessIsNotRefuted) {
  // taps (0, 1): w = (0, 1) = r, d = 0, ‖T_Δ‖ = 1: a witness at δ² = 1, d_max² = 0.
  EXPECT_TRUE(check(point(Rational(1), Rational(1), Rational(0), CertificateClaim::kConsistent)).holds);
  const CertificateVerdict v = check(point(Rational(1), Rational(1), Rational(0), CertificateClaim::kNotAWitness));
  EXPECT_FALSE(v.holds);
  EXPECT_NE(v.reason.find("it is a witness"), std::string::npos) << v.reason;
}

TEST_F(NotAWitness, NoiseConditionFailingByTheSmallestAmount) {
  // taps (0, 1/2): d = (0, 1/2), ‖d‖² = 1/4; n·ny·d_max² = 2·d_max².
  const Rational h(1, 2);
  // d_max² = 1/8: equality, (C2) holds, so the point is a witness at δ² = 1.
  EXPECT_FALSE(check(point(h, Rational(1), Rational(1, 8), CertificateClaim::kNotAWitness)).holds);
  // one part in 10^9 below: (C2) fails exactly.
  const CertificateVerdict v =
      check(point(h, Rational(1), Rational(1, 8) - Rational(1, 1000000000), CertificateClaim::kNotAWitness));
  EXPECT_TRUE(v.holds) << v.reason;
  EXPECT_NE(v.details.find("(C2) fails"), std::string::npos) << v.details;
  EXPECT_EQ(v.claim_text, "not_a_witness");
  EXPECT_FALSE(check(point(h, Rational(1), Rational(1, 8) - Rational(1, 1000000000), CertificateClaim::kConsistent)).holds);
}

TEST_F(NotAWitness, UncertaintyConditionFailingByTheSmallestAmount) {
  // taps (0, 1): ‖T_Δ‖² = 1; at δ² = 1 the point holds, just below it (C1) fails.
  EXPECT_FALSE(check(point(Rational(1), Rational(1), Rational(0), CertificateClaim::kNotAWitness)).holds);
  const CertificateVerdict v =
      check(point(Rational(1), Rational(1) - Rational(1, 1000000000), Rational(0), CertificateClaim::kNotAWitness));
  EXPECT_TRUE(v.holds) << v.reason;
  EXPECT_NE(v.details.find("(C1) fails"), std::string::npos) << v.details;
}

TEST_F(NotAWitness, AHorizonThatMissesANonZeroZIsAFailure) {
  // horizon 1 leaves z_0 = u_0 = 1 outside the Δ horizon: w = Δ∗z is not what the taps say.
  Certificate c = point(Rational(1), Rational(1), Rational(1), CertificateClaim::kNotAWitness);
  c.taps = Mat<Rational>::Constant(1, 1, Rational(0));
  c.horizon = 1;
  EXPECT_TRUE(check(c).holds);
  // with u_0 = 0 the same horizon is fine: z_0 = 0, w = 0, d = r = y − u = (1, 1), ‖d‖² = 2 = 2·1.
  Certificate ok = point(Rational(1), Rational(1), Rational(1), CertificateClaim::kNotAWitness, "0");
  ok.taps = Mat<Rational>::Constant(1, 1, Rational(0));
  ok.horizon = 1;
  EXPECT_FALSE(check(ok).holds);
}

TEST_F(NotAWitness, AMalformedPointIsNoEvidence) {
  Certificate c = point(Rational(1), Rational(1), Rational(0), CertificateClaim::kNotAWitness);
  c.form = CertificateForm::kW;
  c.w = Mat<Rational>::Zero(3, 1);  // three rows for two samples
  const CertificateVerdict v = check(c);
  EXPECT_FALSE(v.holds);
  EXPECT_NE(v.reason.find("rows"), std::string::npos) << v.reason;
}

TEST_F(NotAWitness, TheFileRoundTripsAndTheProgramSaysTheClaim) {
  const Certificate c = point(Rational(1, 2), Rational(1), Rational(0), CertificateClaim::kNotAWitness);
  write_certificate(dir.file("c.json"), c);
  EXPECT_EQ(read_certificate(dir.file("c.json")).claim, CertificateClaim::kNotAWitness);
  std::ostringstream out, err;
  EXPECT_EQ(run_certificate_command(dir.file("c.json"), out, err), 0) << out.str() << err.str();
  EXPECT_EQ(out.str().rfind("not_a_witness\n", 0), 0u) << out.str();
}

}  // namespace
}  // namespace lpvid
