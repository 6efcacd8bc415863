// Long work talks: invalidate prints its stages on stderr (solve, upper end,
// lower end, each with the elapsed time) unless --quiet; stdout carries the
// report either way and no progress line.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct Progress : CliRunner {
  std::string invalidate(const std::string& extra) {
    const std::string data = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/noise_free_n40.csv";
    const std::string model = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/initial_model.json";
    const std::string cmd = exe + " invalidate --data " + data + " --model " + model + " --delta 1 --certificate " +
                            file("c.json") + " " + extra + " >" + file("out.txt") + " 2>" + file("err.txt");
    EXPECT_EQ(std::system(cmd.c_str()), 0) << output();
    std::ifstream in(file("err.txt"));
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
};

TEST_F(Progress, InvalidateNamesItsStagesOnStderrUnlessQuiet) {
  const std::string err = invalidate("");
  EXPECT_NE(err.find("[invalidate"), std::string::npos) << err;
  EXPECT_NE(err.find("solving Theorem 2.1"), std::string::npos) << err;
  EXPECT_NE(err.find("upper end"), std::string::npos) << err;
  EXPECT_NE(err.find(" s] "), std::string::npos) << err;  // elapsed seconds
  const std::string report = output();
  EXPECT_EQ(report.find("[invalidate"), std::string::npos) << report;  // not on stdout
  EXPECT_NE(report.find("verified"), std::string::npos) << report;
  EXPECT_EQ(invalidate("--quiet"), "");
  EXPECT_NE(output().find("verified"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
