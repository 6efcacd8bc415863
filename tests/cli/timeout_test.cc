// The user's --timeout (core/deadline.h) is the one wall-clock limit: a run
// that passes it ends "timed out" with exit code 124, leaves none of its
// outputs behind, and a run within it gives the same answer as without it.
// (Failed before: --timeout was an unknown option, exit 2.)
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "core/exit_codes.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct Timeout : CliRunner {
  /// A generated diagnose case (scripts/demo.sh's, smaller): minutes of
  /// ranking and bounds, far more than the timeouts below.
  std::string diagnose_args() {
    EXPECT_EQ(run("generate", "effect-case --effect output_polynomial --n 400 --seed 3 --out " + file("est.csv") +
                                  " --validation-out " + file("test.csv") + " --model-out " + file("declared.json")),
              0)
        << output();
    return "--data " + file("est.csv") + " --model " + file("declared.json") + " --test " + file("test.csv") +
           " --warmup 10 --threads 1 --report " + file("r.report.json") + " --model-out " + file("after.json");
  }
};

TEST_F(Timeout, PassedDeadlineIsTimedOutWithItsOwnCodeAndNoOutputs) {
  const std::string args = diagnose_args();
  const auto t0 = std::chrono::steady_clock::now();
  const int code = run("diagnose", "--timeout 2 " + args);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(code, kExitTimedOut) << output();
  EXPECT_NE(output().find("timed out after 2 s (--timeout 2)"), std::string::npos) << output();
  EXPECT_LT(wall, 30.0) << output();
  EXPECT_FALSE(std::filesystem::exists(file("r.report.json")));
  EXPECT_FALSE(std::filesystem::exists(file("after.json")));
}

// Given before the subcommand too (like the input limits); a generous
// timeout changes nothing: the certificate is the one of a run without it.
TEST_F(Timeout, GenerousTimeoutChangesNothing) {
  const std::string data = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/noise_free_n40.csv";
  const std::string model = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/initial_model.json";
  const std::string args = "--data " + data + " --model " + model + " --delta 1 --quiet --certificate ";
  ASSERT_EQ(run("invalidate", args + file("a.json")), kExitOk) << output();
  ASSERT_EQ(run_program(exe, "--timeout 600 invalidate " + args + file("b.json")), kExitOk) << output();
  EXPECT_EQ(read_text(file("a.json")), read_text(file("b.json")));
  EXPECT_EQ(run("invalidate", args + file("c.json") + " --timeout 0"), kExitBadInput) << output();  // must be > 0
}

}  // namespace
}  // namespace lpvid
