// No output file the user did not name: `invalidate`, `tradeoff` and `diagnose` run in
// an empty folder without --certificate, --report, --csv or --plots leave it
// empty (they used to write ./lpvid.cert.json, ./lpvid.cert.lower.json,
// ./tradeoff.csv and ./tradeoff.png); with --report R the certificate is
// R's stem + .cert.json and its path is printed.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;
namespace fs = std::filesystem;

struct UnnamedOutputs : CliRunner {
  fs::path empty;
  void generate() {
    ASSERT_EQ(run("generate", "effect-case --effect output_polynomial --n 150 --seed 3 --out " + file("est.csv") +
                                  " --validation-out " + file("val.csv") + " --model-out " + file("m.json")),
              0)
        << output();
    empty = dir / "run";
    fs::create_directories(empty);
  }
  /// `lpvid <subcommand> args` with the empty folder as working directory.
  int run_in_empty(const std::string& subcommand, const std::string& args) {
    return run_program("cd '" + empty.string() + "' && " + exe, subcommand + " --quiet " + args);
  }
  std::set<std::string> files_left() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(empty)) names.insert(e.path().filename().string());
    return names;
  }
};

TEST_F(UnnamedOutputs, InvalidateNamingNoFileWritesNone) {
  generate();
  const int code = run_in_empty("invalidate", "--data " + file("est.csv") + " --model " + file("m.json"));
  EXPECT_TRUE(code == 0 || code == 1 || code == 4) << code << "\n" << output();
  EXPECT_EQ(files_left(), std::set<std::string>{}) << output();
  EXPECT_NE(output().find("no certificate file written (name one with --certificate FILE)"), std::string::npos)
      << output();
}

TEST_F(UnnamedOutputs, InvalidateWithAReportWritesTheCertificateBesideItAndSaysWhere) {
  generate();
  const int code = run_in_empty("invalidate", "--data " + file("est.csv") + " --model " + file("m.json") + " --report R.json");
  ASSERT_EQ(code, 0) << output();
  const std::set<std::string> left = files_left();
  EXPECT_TRUE(left.count("R.json")) << output();
  EXPECT_TRUE(left.count("R.cert.json")) << output();
  for (const std::string& f : left) EXPECT_EQ(f.rfind("R.", 0), 0u) << f << " is not derived from the report's name";
  EXPECT_NE(output().find("R.cert.json"), std::string::npos) << output();
}

TEST_F(UnnamedOutputs, TradeoffNamingNoFileWritesNone) {
  generate();
  const int code = run_in_empty("tradeoff", "--data " + file("est.csv") + " --model " + file("m.json") + " --lambdas 0.5");
  EXPECT_TRUE(code == 0 || code == 4) << code << "\n" << output();
  EXPECT_EQ(files_left(), std::set<std::string>{}) << output();
}

TEST_F(UnnamedOutputs, TradeoffWritesTheCertificatesUnderTheReportsStemAndTheCsvWhenNamed) {
  generate();
  const int code = run_in_empty("tradeoff", "--data " + file("est.csv") + " --model " + file("m.json") +
                                                " --lambdas 0.5 --report T.json --csv c.csv");
  ASSERT_EQ(code, 0) << output();
  const std::set<std::string> left = files_left();
  EXPECT_TRUE(left.count("T.json")) << output();
  EXPECT_TRUE(left.count("c.csv")) << output();
  EXPECT_TRUE(left.count("T.lambda1.cert.json")) << output();
  EXPECT_FALSE(left.count("c.png")) << "no figure without --plots";
}

TEST_F(UnnamedOutputs, DiagnoseNamingNoFileWritesNone) {
  generate();
  const int code = run_in_empty("diagnose", "--data " + file("est.csv") + " --model " + file("m.json") +
                                                " --max-effects 1 --folds 2 --max-windows 1");
  EXPECT_TRUE(code == 0 || code == 4) << code << "\n" << output();
  EXPECT_EQ(files_left(), std::set<std::string>{}) << output();  // it used to write ./lpvid.cert.*.json
  EXPECT_NE(output().find("certificates: no file written"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
