// `lpvid oracle` against toy outside implementations (tests/oracle/toy_impls.py,
// which answer by asking lpvid itself, then err on purpose): the correct one
// is never refuted; each wrong one is refuted, and every refutation names a
// certificate that the separate program `lpvid-verify certificate` accepts.
// The cases come from the property tests' generator (examples/random_case.h)
// with small records so that the run stays short.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "cli/random_cases.h"
#include "oracle/random_task.h"
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

/// `count` identify cases (the oracle's random tasks, seeds from 1) whose
/// model has (or lacks) the additive structure, as case folders under `root`.
void write_identify_cases(const std::string& root, bool additive, int count) {
  RandomTaskOptions o;
  o.kinds = {TaskKind::kIdentify};
  o.cases.min_n = 10;
  o.cases.max_n = 24;
  o.cases.model.max_nu = o.cases.model.max_ny = 1;
  int written = 0;
  for (uint64_t seed = 1; seed < 200 && written < count; ++seed) {
    const GeneratedCase g = random_oracle_case(seed, o);
    if ((g.random.model.uncertainty.structure == UncertaintyStructure::kAdditive) != additive) continue;
    cli::write_case_folder(root + "/case-" + std::to_string(seed), g);
    ++written;
  }
  ASSERT_EQ(written, count);
}

TEST_F(Oracle, IdentifyClaimsBelowTheClassLowerEndAreRefutedByTheClassCertificate) {
  // additive structure: z does not depend on θ, Theorem 3.1 is convex and
  // lpvid's class lower end holds for every θ of the basis
  write_identify_cases(file("additive"), true, 3);
  const std::string cases = " --cases-dir " + file("additive");
  nlohmann::json report;
  EXPECT_EQ(oracle("correct", cases, report), 0) << output();
  EXPECT_EQ(verdicts(report)["confirmed"], 3) << report.dump(1);
  for (const auto& c : report["cases"]) {
    EXPECT_TRUE(c["class_lower_end"]["verified"].get<bool>()) << c.dump();
    EXPECT_EQ(c["class_lower_end"]["region"], "whole_class") << c.dump();
  }
  // too good by 5 % in d_max (the class interval is at the solver's tolerance), and with θ = 0
  for (const std::string mode : {"scaled", "zero_theta"}) {
    EXPECT_EQ(oracle(mode, cases, report), 1) << output();
    EXPECT_EQ(verdicts(report)["refuted"], 3) << report.dump(1);
    for (const auto& c : report["cases"]) {
      const std::string cert = c["certificate"];
      EXPECT_EQ(cert, c["class_lower_end"]["certificate"]) << c.dump();
      EXPECT_NE(c["certificate_check"].get<std::string>().find("class_lower_bound"), std::string::npos) << c.dump();
    }
    expect_refutations_verified(report);
  }
}

TEST_F(Oracle, WithoutTheClassBoundAClaimIsJudgedOnItsOwnThetaOnly) {
  // --no-class-bound: no class interval, no lpvid.class.json; a claim too good
  // by 5 % in d_max with lpvid's own θ is still refuted, by that fixed model's
  // lower end (a dual certificate, not a class one)
  write_identify_cases(file("additive_no_class"), true, 2);
  const std::string cases = " --cases-dir " + file("additive_no_class") + " --no-class-bound";
  nlohmann::json report;
  EXPECT_EQ(oracle("scaled", cases, report), 1) << output();
  EXPECT_EQ(verdicts(report)["refuted"], 2) << report.dump(1);
  for (const auto& c : report["cases"]) {
    EXPECT_FALSE(c["class_lower_end"]["verified"].get<bool>()) << c.dump();
    EXPECT_NE(c["class_lower_end"]["reason"].get<std::string>().find("--no-class-bound"), std::string::npos) << c.dump();
    EXPECT_EQ(c["certificate_check"].get<std::string>().find("class_lower_bound"), std::string::npos) << c.dump();
  }
  for (const auto& entry : std::filesystem::recursive_directory_iterator(file("scaled")))
    EXPECT_NE(entry.path().filename(), "lpvid.class.json") << entry.path();
  expect_refutations_verified(report);
}

TEST_F(Oracle, ABoxClassCertificateDoesNotRefuteAThetaOutsideItsBox) {
  // multiplicative: the class lower end holds on a box around lpvid's θ; θ = 0
  // lies outside it, so only the fixed θ's own lower end can refute the claim
  write_identify_cases(file("multiplicative"), false, 2);
  nlohmann::json report;
  EXPECT_EQ(oracle("zero_theta", " --cases-dir " + file("multiplicative"), report), 1) << output();
  for (const auto& c : report["cases"]) {
    if (c["verdict"] != "refuted") continue;
    EXPECT_NE(c["certificate"], c["class_lower_end"].value("certificate", "")) << c.dump();
    const nlohmann::json& k = c["class_lower_end"];
    const bool below = k["verified"].get<bool>() &&
                       std::stod(c["claimed_objective"].get<std::string>()) < 0.999 * k["lower_dmax2"].get<double>();
    if (below && k["region"] == "box") {
      EXPECT_NE(c["reason"].get<std::string>().find("not refutable by the class certificate: theta outside the certified box"),
                std::string::npos)
          << c.dump();
    }
  }
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
