// `lpvid oracle` against toy outside implementations (tests/oracle/toy_impls.py,
// which answer by asking lpvid itself, then err on purpose): the correct one
// is never refuted; each wrong one is refuted, and every refutation names a
// certificate that the separate program `lpvid-verify certificate` accepts.
// The cases come from the property tests' generator (examples/random_case.h)
// with small records so that the run stays short.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "support/cli_runner.h"

namespace lpvid {
namespace {

struct Oracle : gen::CliRunner {
  void SetUp() override {
    gen::CliRunner::SetUp();
    if (IsSkipped()) return;
    if (std::system("python3 -c 'import json' >/dev/null 2>&1") != 0) GTEST_SKIP() << "python3 not found";
  }
  /// Runs the oracle with toy MODE; returns the exit code and fills `report`.
  int oracle(const std::string& mode, const std::string& flags, nlohmann::json& report) {
    const std::string toy = std::string(LPVID_SOURCE_DIR) + "/tests/oracle/toy_impls.py";
    const std::string command = "python3 " + toy + " " + mode + " " + exe + " {data} {model} {task} {out}";
    const int code = run("oracle", "--quiet --command \"" + command + "\" --work " + file(mode) + " --report " +
                                       file(mode + ".json") + " --junit " + file(mode + ".xml") + " " + flags);
    report = read_json(file(mode + ".json"));
    return code;
  }
  std::map<std::string, int> verdicts(const nlohmann::json& report) {
    std::map<std::string, int> v;
    for (const auto& c : report["cases"]) ++v[c["verdict"].get<std::string>()];
    return v;
  }
  /// Every refuted case names a certificate that lpvid-verify accepts (exit 0).
  void expect_refutations_verified(const nlohmann::json& report) {
    for (const auto& c : report["cases"]) {
      if (c["verdict"] != "refuted") continue;
      const std::string cert = c["certificate"].get<std::string>();
      EXPECT_EQ(run_program(verify_exe, "certificate " + cert), 0) << c.dump() << "\n" << output();
    }
  }
};

TEST_F(Oracle, TheCorrectImplementationIsNeverRefuted) {
  nlohmann::json report;
  const int code = oracle("correct", "--cases 50 --seed 1 --min-n 8 --max-n 40", report);
  const auto v = verdicts(report);
  EXPECT_EQ(code, 0) << output();
  EXPECT_EQ(v.count("refuted"), 0u) << report.dump(1);
  EXPECT_EQ(v.count("error"), 0u) << report.dump(1);
  EXPECT_GE(v.at("confirmed"), 45) << report.dump(1);
  EXPECT_EQ(report["cases"].size(), 50u);
  // the table and the JUnit file list every case
  EXPECT_NE(output().find("case-0050"), std::string::npos) << output();
  const std::string junit = read_text(file("correct.xml"));
  EXPECT_NE(junit.find("tests=\"50\""), std::string::npos) << junit.substr(0, 400);
  EXPECT_NE(junit.find("failures=\"0\""), std::string::npos) << junit.substr(0, 400);
}

TEST_F(Oracle, ABoundScaledBy095IsRefutedByTheLowerEnd) {
  nlohmann::json report;
  const int code = oracle("scaled", "--cases 10 --seed 101 --min-n 8 --max-n 40 --kinds min_dmax,min_delta,weighted", report);
  const auto v = verdicts(report);
  EXPECT_EQ(code, 1) << output();
  // a zero optimum scaled by 0.95 is still right; every other case is caught
  int positive = 0;
  for (const auto& c : report["cases"])
    if (c["verdict"] == "refuted") {
      ++positive;
      EXPECT_NE(c["reason"].get<std::string>().find("below lpvid's certified lower end"), std::string::npos) << c.dump();
    }
  EXPECT_GE(positive, 8) << report.dump(1);
  expect_refutations_verified(report);
  const std::string junit = read_text(file("scaled.xml"));
  EXPECT_NE(junit.find("<failure type=\"refuted\""), std::string::npos);
}

TEST_F(Oracle, AFlippedVerdictOnInvalidatedCasesIsRefuted) {
  nlohmann::json report;
  const int code = oracle("flipped", "--cases 16 --seed 201 --min-n 8 --max-n 40 --kinds decide", report);
  EXPECT_EQ(code, 1) << output();
  int refuted = 0;
  for (const auto& c : report["cases"])
    if (c["verdict"] == "refuted") {
      ++refuted;
      EXPECT_NE(c["reason"].get<std::string>().find("lpvid certifies invalidated"), std::string::npos) << c.dump();
      EXPECT_EQ(c["certificate_check"], "invalidated") << c.dump();
    }
  EXPECT_GE(refuted, 1) << report.dump(1);
  expect_refutations_verified(report);
}

TEST_F(Oracle, ARightClaimWithAWitnessWithOneEntryChangedIsABadWitnessNotARefutation) {
  // the claimed bound is lpvid's own (right); only the attached witness is wrong
  nlohmann::json report;
  const int code = oracle("bad_witness", "--cases 8 --seed 301 --min-n 8 --max-n 40 --kinds min_dmax,min_delta,weighted", report);
  EXPECT_EQ(code, 1) << output();
  int bad = 0;
  for (const auto& c : report["cases"])
    if (c["verdict"] == "bad_witness") {
      ++bad;
      EXPECT_EQ(c["certificate_check"], "not_a_witness") << c.dump();
      EXPECT_EQ(run_program(verify_exe, "certificate " + c["certificate"].get<std::string>()), 0) << c.dump() << output();
    }
  EXPECT_EQ(bad, 8) << report.dump(1);
  EXPECT_EQ(report["totals"]["refuted"], 0) << report.dump(1);
  const std::string junit = read_text(file("bad_witness.xml"));
  EXPECT_NE(junit.find("<failure type=\"bad_witness\""), std::string::npos) << junit.substr(0, 600);
}

TEST_F(Oracle, IgnoringTheLeadingZerosOfZIsRefuted) {
  nlohmann::json report;
  const int code =
      oracle("leading_zeros", "--cases 8 --seed 401 --min-n 12 --max-n 40 --kinds min_dmax --leading-zeros 6", report);
  EXPECT_EQ(code, 1) << output();
  EXPECT_GE(verdicts(report)["refuted"], 4) << report.dump(1);
  expect_refutations_verified(report);
}

TEST_F(Oracle, IdentifyClaimsAreJudgedOnTheirTheta) {
  // the correct toy answers with lpvid identify's own certified θ and d_max
  nlohmann::json report;
  EXPECT_EQ(oracle("correct", "--cases 3 --seed 11 --min-n 10 --max-n 30 --kinds identify", report), 0) << output();
  EXPECT_EQ(verdicts(report)["confirmed"], 3) << report.dump(1);
  // the same θ with d_max scaled by 0.95: below the lower end of the model with that θ
  EXPECT_EQ(oracle("scaled", "--cases 3 --seed 11 --min-n 10 --max-n 30 --kinds identify", report), 1) << output();
  EXPECT_GE(verdicts(report)["refuted"], 1) << report.dump(1);
  expect_refutations_verified(report);
}

TEST_F(Oracle, BadCommandsAndAnswersAreErrorsNotRefutations) {
  nlohmann::json report;
  // an unknown placeholder is refused before anything runs
  EXPECT_EQ(run("oracle", "--cases 1 --command \"echo {date}\" --work " + file("w")), 2);
  EXPECT_NE(output().find("unknown placeholder '{date}'"), std::string::npos) << output();
  // a command that writes no answer, one that writes garbage, one that hangs
  for (const auto& [name, cmd] : std::map<std::string, std::string>{
           {"none", "true"}, {"garbage", "echo not-json > {out}"}, {"slow", "sleep 30"}}) {
    const int code = run("oracle", "--quiet --cases 2 --seed 7 --min-n 8 --max-n 12 --case-timeout 1 --command \"" + cmd +
                                       "\" --work " + file(name) + " --report " + file(name + ".json"));
    EXPECT_EQ(code, 3) << name << "\n" << output();
    report = read_json(file(name + ".json"));
    EXPECT_EQ(verdicts(report)["error"], 2) << report.dump(1);
  }
}

}  // namespace
}  // namespace lpvid
