// Options that a command would silently ignore are refused before any work
// (usage error, exit 2, naming the option), and fit-linear takes the
// names the other commands use (--model-out, --validation).
#include <gtest/gtest.h>

#include <fstream>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct IgnoredOptions : CliRunner {};

TEST_F(IgnoredOptions, GenerateRefusesTheOtherDataSetsOptions) {
  EXPECT_EQ(run("generate", "example1 --out " + file("a.csv") + " --validation-out v.csv"), 2) << output();
  EXPECT_NE(output().find("--validation-out"), std::string::npos) << output();
  EXPECT_EQ(run("generate", "effect-case --out " + file("b.csv") + " --noise-variance 0.1"), 2) << output();
  EXPECT_NE(output().find("--noise-variance"), std::string::npos) << output();
}

TEST_F(IgnoredOptions, DiagnoseRefusesOptionsWithoutTheirPartner) {
  const std::string base = "--data x.csv --model m.json ";
  EXPECT_EQ(run("diagnose", base + "--test-rows 0:10"), 2) << output();
  EXPECT_NE(output().find("--test-rows"), std::string::npos) << output();
  EXPECT_EQ(run("diagnose", base + "--validation v.csv --holdout 0.2"), 2) << output();
  EXPECT_NE(output().find("--holdout"), std::string::npos) << output();
  EXPECT_EQ(run("diagnose", base + "--holdout 0.2"), 2) << output();  // default folds: --holdout unused
  EXPECT_NE(output().find("--folds 1"), std::string::npos) << output();
  EXPECT_EQ(run("diagnose", base + "--validation-rows 0:10"), 2) << output();
  EXPECT_NE(output().find("--validation-rows"), std::string::npos) << output();
}


TEST_F(IgnoredOptions, FitLinearAcceptsTheAliasesOfTheOtherCommands) {
  ASSERT_EQ(run("generate", "example1 --n 40 --out " + file("d.csv")), 0) << output();
  EXPECT_EQ(run("fit-linear", "--data " + file("d.csv") + " --u u1,u2 --y y1 --order 1 --model-out " + file("m.json") +
                                  " --validation " + file("d.csv")),
            0)
      << output();
  EXPECT_TRUE(std::ifstream(file("m.json")).good());
}

}  // namespace
}  // namespace lpvid
