// `lpvid identify --method alternating` through the real binary (when built
// in the same tree): Example 1 fixture, noise-free, full basis → exit 0, a
// report with verified: true and both bounds ≤ 1e-4, a certificate that the
// verifier accepts; bad option combinations → exit 2 (src/core/exit_codes.h).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/fixtures.h"
#include "support/gen_identify.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

int run_lpvid(const std::string& args) {
  const std::string exe = std::string(LPVID_BINARY_DIR) + "/lpvid";
  const int s = std::system(("OPENBLAS_NUM_THREADS=1 " + exe + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

TEST(AlternatingCli, Example1IsIdentifiedAndCertified) {
  if (!std::filesystem::exists(std::string(LPVID_BINARY_DIR) + "/lpvid")) GTEST_SKIP() << "lpvid not built";
  gen::ScratchDir dir("alt-cli");
  const std::string common = "identify --data " + gen::kExample1Fixtures + "noise_free_n40.csv --model " + gen::kExample1Fixtures +
                             "initial_model.json --method alternating --certificate " + dir.file("c.json") +
                             " --report " + dir.file("r.json");
  ASSERT_EQ(run_lpvid(common), 0);
  std::ifstream in(dir.file("r.json"));
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report.at("verified"), true);
  EXPECT_EQ(report.at("method"), "alternating");
  EXPECT_LE(report.at("delta").get<double>(), 1e-4);
  EXPECT_LE(report.at("dmax").get<double>(), 1e-4);
  EXPECT_TRUE(check_certificate_file(dir.file("c.json")).holds);

  EXPECT_EQ(run_lpvid(common + " --iterate"), 2);              // --iterate belongs to the relaxation
  EXPECT_EQ(run_lpvid(common + " --method newton"), 2);        // unknown method
  EXPECT_EQ(run_lpvid(common + " --alt-taps 0"), 2);           // K ≥ 1
  EXPECT_EQ(run_lpvid(common + " --delta-norm spectral"), 2);  // unknown norm form
}

}  // namespace
}  // namespace lpvid
