// Outputs are checked before any work, and an interrupted run leaves none of
// its files behind (core/file_io.h), through the real binary.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;
namespace fs = std::filesystem;

struct Outputs : CliRunner {
  /// Generated SISO data and its declared model (an undeclared output polynomial).
  void generate() {
    ASSERT_EQ(run("generate", "effect-case --effect output_polynomial --n 300 --seed 3 --out " + file("est.csv") +
                                  " --validation-out " + file("val.csv") + " --model-out " + file("m.json")),
              0)
        << output();
  }
  int certificates() const {
    int k = 0;
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(".cert") != std::string::npos) ++k;
    return k;
  }
};

TEST_F(Outputs, AReportInAMissingDirectoryFailsBeforeAnyWork) {
  generate();
  const auto t0 = std::chrono::steady_clock::now();
  const int code = run("diagnose", "--data " + file("est.csv") + " --model " + file("m.json") + " --report " +
                                       file("missing/dir/r.json"));
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(code, 6) << output();
  EXPECT_NE(output().find("does not exist"), std::string::npos) << output();
  EXPECT_LT(secs, 5.0) << "the check must come before the work (diagnose itself takes tens of seconds here)";
  EXPECT_EQ(certificates(), 0);
}

TEST_F(Outputs, AModelOutThatIsADirectoryIsRefusedAtOnce) {
  generate();
  fs::create_directories(dir / "adir");
  EXPECT_EQ(run("diagnose", "--data " + file("est.csv") + " --model " + file("m.json") + " --model-out " + file("adir")), 6)
      << output();
  EXPECT_NE(output().find("is a directory"), std::string::npos) << output();
}

TEST_F(Outputs, CtrlCRemovesTheCertificatesAlreadyWritten) {
  generate();
  // diagnose without effects goes straight to the window bounds and writes
  // one certificate per window; interrupt it once the first is there
  const std::string cmd = exe + " diagnose --data " + file("est.csv") + " --model " + file("m.json") +
                          " --max-effects 0 --report " + file("r.json") + " >" + file("out.txt") + " 2>&1 & echo $! > " +
                          file("pid");
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  bool seen = false;
  for (int i = 0; i < 1200 && !seen; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    seen = certificates() > 0;
  }
  ASSERT_TRUE(seen) << "no certificate appeared within 120 s:\n" << output();
  const int rc = std::system(("pid=$(cat " + file("pid") + "); kill -INT $pid; while kill -0 $pid 2>/dev/null; do sleep 0.1; done").c_str());
  ASSERT_EQ(rc, 0);
  EXPECT_NE(output().find("interrupted"), std::string::npos) << output();
  EXPECT_EQ(certificates(), 0) << output();
  EXPECT_FALSE(fs::exists(dir / "r.json"));
}

}  // namespace
}  // namespace lpvid
