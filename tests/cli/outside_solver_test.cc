// The round trip of docs/certificates.md with the `csdp` program, through the real binaries:
//   lpvid invalidate … --write-sdpa P.dat-s;  csdp P.dat-s P.sol;
//   lpvid certify … --program P.dat-s --solution P.sol;  lpvid-verify certificate C.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/fixtures.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct OutsideSolver : CliRunner {
  std::string common() const {
    return "--data " + gen::kExample1Fixtures + "noise_free_n40.csv --model " + gen::kExample1Fixtures + "initial_model.json --max-taps 6";
  }
  nlohmann::json report(const std::string& path) const { return nlohmann::json::parse(std::ifstream(path)); }
  bool has(const std::string& needle) const { return output().find(needle) != std::string::npos; }
};

TEST_F(OutsideSolver, CsdpProgramRoundTripGivesAVerifiedCertificate) {
  if (std::system("command -v csdp > /dev/null 2>&1") != 0) GTEST_SKIP() << "the csdp program is not installed";
  const std::string p = file("t21.dat-s"), sol = file("t21.sol"), cert = file("c.json"), rep = file("r.json");
  ASSERT_EQ(run("invalidate", common() + " --write-sdpa " + p + " --certificate " + file("own.json") + " --report " +
                                  file("own.report.json")),
            0)
      << output();
  ASSERT_TRUE(std::filesystem::exists(p) && std::filesystem::exists(p + ".json")) << output();
  const nlohmann::json side = report(p + ".json");
  EXPECT_EQ(side["about"]["kind"], "theorem-2.1-delta-form");
  ASSERT_EQ(run_program("csdp", p + " " + sol), 0) << output();
  ASSERT_EQ(run("certify", common() + " --program " + p + " --solution " + sol + " --certificate " + cert +
                               " --report " + rep),
            0)
      << output();
  const nlohmann::json r = report(rep);
  EXPECT_EQ(r["verified"], true) << r.dump(2);
  EXPECT_EQ(run_program(verify_exe, "certificate " + cert), 0) << output();
  EXPECT_TRUE(has("(C2) holds")) << output();
}

TEST_F(OutsideSolver, SolutionOfAnotherProgramIsRefused) {
  const std::string p = file("t21.dat-s"), sol = file("t21.sol");
  ASSERT_EQ(run("invalidate", common() + " --write-sdpa " + p + " --certificate " + file("own.json")), 0) << output();
  std::ofstream(sol) << "0\n";
  // Another data window: not the program of these inputs.
  EXPECT_EQ(run("certify", common() + " --rows 0:30 --program " + p + " --solution " + sol + " --certificate " +
                               file("c.json")),
            2);
  EXPECT_TRUE(has("not the Theorem 2.1 program")) << output();
  EXPECT_FALSE(std::filesystem::exists(file("c.json")));
  // A solution with the wrong number of variables.
  EXPECT_EQ(run("certify", common() + " --program " + p + " --solution " + sol + " --certificate " + file("c.json")), 2);
  EXPECT_TRUE(has("t21.sol") && has("variables")) << output();
}

}  // namespace
}  // namespace lpvid
