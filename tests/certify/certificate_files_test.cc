// The file edge of certification (certify/certificate_files.h): certify.h
// returns its certificates in memory, checked by the verifier's core on the
// exact experiment; the front end writes them. What is checked in memory is
// what the file layer accepts from the written files, and the two layers
// agree on a false claim.
#include <gtest/gtest.h>

#include <filesystem>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "core/input_error.h"
#include "examples/paper_example1.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

struct Case {
  LpvModel<Rational> model = example1_initial_model();
  Experiment<Rational> exp;
  Case() {
    Example1Options eo;
    eo.n = 40;
    eo.noise_variance = 0.01;
    exp = example1_experiment(eo);
  }
};

/// The case's data written in `dir` and certified for `objective`.
CertifiedBounds certified(const Case& k, const gen::ScratchDir& dir, const BoundObjective& objective) {
  const std::string data = dir.file("data.csv");
  gen::write_experiment_csv(data, k.model, k.exp);
  auto solver = make_solver("csdp");
  return certify_fixed_model(k.model, k.exp, gen::certify_options(objective, data), *solver);
}

// A verified optimum carries both certificates in memory; written into a
// sub-folder, they name the data relative to that folder and pass the file
// layer (sha256, rows) as they passed the core.
TEST(CertificateFiles, WrittenCertificatesPassTheFileLayer) {
  const Case k;
  gen::ScratchDir dir("certificate_files");
  const CertifiedBounds b = certified(k, dir, gen::weighted_objective(0.5));
  ASSERT_TRUE(b.verified()) << b.reason;
  EXPECT_EQ(b.outcome, CertifyOutcome::kVerified);
  ASSERT_TRUE(b.certificate.has_value());
  ASSERT_TRUE(b.lower.verified()) << b.lower.reason;
  ASSERT_TRUE(b.lower.certificate.has_value());
  EXPECT_TRUE(check_certificate(*b.certificate, k.exp).holds);
  EXPECT_TRUE(check_certificate(*b.lower.certificate, k.exp).holds);

  fs::create_directories(dir.path() / "sub");
  const std::string path = (dir.path() / "sub" / "c.json").string();
  const CertificateFiles files = write_certificates(b, path);
  EXPECT_EQ(files.certificate, path);
  EXPECT_EQ(files.lower, (dir.path() / "sub" / "c.lower.json").string());
  EXPECT_EQ(read_certificate(path).records.front().data.file, "../data.csv");
  const CertificateVerdict upper = check_certificate_file(files.certificate);
  const CertificateVerdict lower = check_certificate_file(files.lower);
  EXPECT_TRUE(upper.holds) << upper.reason;
  EXPECT_TRUE(lower.holds) << lower.reason;
  EXPECT_EQ(lower.claim_text.rfind("lower_bound", 0), 0u);
}

// A false claim (δ² a quarter of the certified one, so ‖T_Δ‖ ≤ δ fails) is
// refused by the core and by the file layer alike; a certificate of data
// made in memory (no file, no sha256) cannot be written.
TEST(CertificateFiles, CoreAndFileLayerAgreeOnAFalseClaim) {
  const Case k;
  gen::ScratchDir dir("certificate_files_false");
  const CertifiedBounds b = certified(k, dir, gen::min_delta_objective(0.2));
  ASSERT_TRUE(b.verified()) << b.reason;
  ASSERT_GT(b.delta2, Rational(0));
  Certificate c = *b.certificate;
  c.delta2 = c.delta2 / 4;
  const CertificateVerdict core = check_certificate(c, k.exp);
  EXPECT_FALSE(core.holds);
  write_certificate_at(c, dir.file("false.json"));
  const CertificateVerdict file = check_certificate_file(dir.file("false.json"));
  EXPECT_FALSE(file.holds);
  EXPECT_EQ(core.reason, file.reason);

  Certificate no_file = *b.certificate;
  no_file.records.front().data.sha256.clear();
  EXPECT_THROW(write_certificate_at(no_file, dir.file("none.json")), InputError);
  EXPECT_FALSE(fs::exists(dir.file("none.json")));
}

// A bound without a certificate writes no file and names none (a report
// then shows the reason, never a file name).
TEST(CertificateFiles, NoCertificateNoFile) {
  gen::ScratchDir dir("certificate_files_none");
  CertifiedBounds b;
  b.reason = "the solver stopped";
  EXPECT_EQ(b.outcome, CertifyOutcome::kUndecided);  // nothing decided yet: never "verified" by default
  EXPECT_FALSE(b.verified());
  EXPECT_FALSE(b.invalidated());
  const CertificateFiles files = write_certificates(b, dir.file("c.json"));
  EXPECT_TRUE(files.certificate.empty());
  EXPECT_TRUE(files.lower.empty());
  EXPECT_FALSE(fs::exists(dir.file("c.json")));
  EXPECT_FALSE(fs::exists(dir.file("c.lower.json")));
}

}  // namespace
}  // namespace lpvid
