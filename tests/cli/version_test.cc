// `--version` on both programs, and a negative sample count refused: what a
// user can check before anything runs.
#include <gtest/gtest.h>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct Version : CliRunner {};

TEST_F(Version, BothProgramsNameTheirVersion) {
  EXPECT_EQ(run_program(exe, "--version"), 0) << output();
  EXPECT_NE(output().find("lpvid "), std::string::npos) << output();
  EXPECT_NE(output().find("."), std::string::npos) << output();  // major.minor.patch
  EXPECT_EQ(run_program(verify_exe, "--version"), 0) << output();
  EXPECT_NE(output().find("lpvid-verify "), std::string::npos) << output();
}

TEST_F(Version, NegativeInitSamplesAreRefused) {
  EXPECT_EQ(run("fit-linear", "--data x.csv --init-samples -3"), 2) << output();
  EXPECT_NE(output().find("--init-samples"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
