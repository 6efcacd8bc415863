// Class claims over a free x0 whose residual is not affine in the unknowns
// (fixtures/false_class_claims/README.md): certificates that an earlier lpvid
// wrote and its verifier accepted, though a member of the class explains the
// data exactly. The verifier must refuse each, naming the broken premise, and
// the member that made the data must be certified consistent at a d_max below
// every claimed lower end (so the claims are false, not only unproven).
#include <gtest/gtest.h>

#include <string>

#include "model/model_file.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

const std::string kDir = std::string(LPVID_SOURCE_DIR) + "/fixtures/false_class_claims/";

TEST(VerifierFalseClassClaims, NonAffineClassClaimsOverX0AreRefused) {
  for (const char* c : {"output_correction_x0", "state_scheduling_x0"})
    for (const char* f : {"identify.class.json", "select_basis.class.json"}) {
      const std::string path = kDir + c + "/" + f;
      const Certificate cert = read_certificate(path);
      ASSERT_TRUE(is_class_claim(cert.claim)) << path;
      ASSERT_TRUE(cert.region.unknowns.x0) << path;
      const CertificateVerdict v = check_certificate_file(path);
      EXPECT_FALSE(v.holds) << path << ": accepted a false class claim (" << v.details << ")";
      EXPECT_NE(v.reason.find("not affine"), std::string::npos) << path << ": " << v.reason;
    }
}

}  // namespace
}  // namespace lpvid
