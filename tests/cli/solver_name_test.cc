// The report and the certificate name what produced the certified answer:
// the structured full-horizon barrier by default, the SDP backend when it
// solved the program (here the KYP restriction, which only the backend
// solves). Before, both said "csdp" (the --solver option) while the progress
// line said the structured barrier solved it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "support/noise_only_case.h"

namespace lpvid {
namespace {

struct SolverName : gen::CliRunner {
  std::string inputs;
  std::string printed;  ///< what the last invalidate printed (stdout and stderr)

  void SetUp() override {
    gen::CliRunner::SetUp();
    if (IsSkipped()) return;
    const std::vector<Rational> a{Rational(1, 2), Rational(-1, 2)};  // 2 × 2
    write_text(file("model.json"), gen::diagonal_model_json({"1/2", "-1/2"}));
    write_text(file("data.csv"), gen::noise_only_record(a, 30, 3).csv);
    inputs = "--data " + file("data.csv") + " --model " + file("model.json") + " --delta 0.1";
  }

  /// The report's solver and the certificate's info.solver of one run.
  std::pair<std::string, std::string> names(const std::string& flags, const std::string& tag) {
    const std::string cert = file(tag + ".json"), report = file(tag + ".report.json");
    EXPECT_EQ(run("invalidate", inputs + flags + " --certificate " + cert + " --report " + report), 0) << output();
    printed = output();
    EXPECT_EQ(run_program(verify_exe, "certificate " + cert), 0) << output();
    return {read_json(report)["solver"].get<std::string>(), read_json(cert)["info"]["solver"].get<std::string>()};
  }
};

TEST_F(SolverName, TheDefaultAnswerIsTheStructuredBarriers) {
  const auto [report, certificate] = names("", "barrier");
  EXPECT_EQ(report, "structured barrier");
  EXPECT_EQ(certificate, "structured barrier");
  EXPECT_NE(printed.find("with the structured barrier"), std::string::npos) << printed;  // the progress line agrees
}

TEST_F(SolverName, AnAnswerOfTheSdpBackendNamesIt) {
  // fixed δ and d_max with the KYP restriction: its primal point, from CSDP, is the answer
  // (optimising instead would bracket it with the structured barrier's full horizon)
  const auto [report, certificate] = names(" --delta-norm kyp --max-taps 4 --dmax 1", "kyp");
  EXPECT_EQ(report, "csdp");
  EXPECT_EQ(certificate, "csdp");
}

}  // namespace
}  // namespace lpvid
