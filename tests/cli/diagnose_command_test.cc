// `lpvid diagnose` end to end (the real binary): on generated data with an
// undeclared output offset it must name `output_offset`, lower the
// validation RMS, report verified bounds whose certificates the independent
// verifier accepts, write the report fields of docs/design.md §11.4 and the plots; bad input
// ends with exit code 2 and a message naming the problem, before any work.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "data/csv_writer.h"
#include "examples/effect_cases.h"
#include "core/number_text.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

struct DiagnoseCommandTest : gen::CliRunner {
  std::string est, val, model;
  void SetUp() override {
    CliRunner::SetUp();
    if (IsSkipped()) return;
    const EffectCase c = make_effect_case("output_offset", 200, 5, 0.02);
    est = file("est.csv");
    val = file("val.csv");
    model = file("declared.json");
    for (const auto& [path, e] : {std::pair{est, &c.estimation}, std::pair{val, &c.validation}})
      write_csv(path, {{"u1", column_text(e->u, 0)}, {"y1", column_text(e->y, 0)}, {"rho1", column_text(e->rho, 0)}});
    write_model_file(model, c.declared);
  }
  nlohmann::json report(const std::string& name) {
    std::ifstream in(file(name));
    return nlohmann::json::parse(in);
  }
};

TEST_F(DiagnoseCommandTest, FindsTheOffsetWithVerifiedBoundsAndPlots) {
  ASSERT_EQ(run("diagnose", "--data " + est + " --model " + model + " --validation " + val + " --window 0:80 --max-taps 16" +
                                " --report " + file("r.json") + " --plots " + file("plots") + " --model-out " +
                                file("after.json")),
            0)
      << output();
  const nlohmann::json r = report("r.json");
  ASSERT_FALSE(r["effects"].empty());
  EXPECT_EQ(r["effects"][0]["kind"], "output_offset");
  EXPECT_NEAR(r["effects"][0]["parameters"]["phi"][0][0].get<double>(), 0.5, 0.02);  // the generating offset
  EXPECT_LT(r["after"]["rms_validation"].get<double>(), 0.7 * r["before"]["rms_validation"].get<double>());
  for (const char* side : {"before", "after"}) {
    EXPECT_TRUE(r[side]["verified"].get<bool>()) << side;
    EXPECT_TRUE(r[side]["delta"].is_number() && r[side]["dmax"].is_number()) << side;
    const std::string cert = r[side]["windows"][0]["certificate"];
    EXPECT_EQ(run_program(verify_exe, "certificate " + cert), 0) << side << ": " << output();
  }
  // the validation rows' three plots and the estimation record; an offset is no static map, so no map plot
  std::vector<std::string> plots;
  for (const auto& p : r["plots"]) plots.push_back(std::filesystem::path(p["csv"].get<std::string>()).stem().string());
  EXPECT_EQ(plots, (std::vector<std::string>{"residual", "autocorrelation", "output", "record"}));
  // the model written is the certified after-model, readable again
  EXPECT_NO_THROW(read_model_file<Rational>(file("after.json")));
}

TEST_F(DiagnoseCommandTest, ControlCaseAnswersNone) {
  const EffectCase c = make_effect_case("none", 200, 5, 0.02);
  write_csv(est, {{"u1", column_text(c.estimation.u, 0)}, {"y1", column_text(c.estimation.y, 0)},
                  {"rho1", column_text(c.estimation.rho, 0)}});
  write_csv(val, {{"u1", column_text(c.validation.u, 0)}, {"y1", column_text(c.validation.y, 0)},
                  {"rho1", column_text(c.validation.rho, 0)}});
  ASSERT_EQ(run("diagnose", "--data " + est + " --model " + model + " --validation " + val + " --window 0:60 --max-taps 8" +
                                " --report " + file("r.json")),
            0)
      << output();
  const nlohmann::json r = report("r.json");
  ASSERT_EQ(r["effects"].size(), 1u);
  EXPECT_EQ(r["effects"][0]["kind"], "none");
}

// The benchmark protocol: the test role is scored once, at the end, and never
// influences the choice. Known answers by construction: with the test data
// equal to the selection data, the test RMS is the selection RMS of the same
// model; with another test file the chosen effects and the written model are
// byte-identical; without --test the report says so (test = null).
TEST_F(DiagnoseCommandTest, TestRoleIsScoredOnceAndNeverChooses) {
  const std::string common = "--data " + est + " --model " + model + " --validation " + val + " --window 0:60";
  ASSERT_EQ(run("diagnose", common + " --test " + val + " --report " + file("t1.json") + " --model-out " + file("m1.json")), 0)
      << output();
  const nlohmann::json r1 = report("t1.json");
  ASSERT_TRUE(r1["test"].is_object());
  EXPECT_EQ(r1["test"]["samples"].get<long>(), r1["validation"]["samples"].get<long>());
  // the same rows in both roles, x0 from the same first 5 samples: the test RMS leaves
  // those 5 out (the warm-up), so (n - 5)·test² <= n·validation², with equality
  // only if the warm-up samples had no error
  const double nv = r1["validation"]["samples"].get<double>();
  EXPECT_EQ(r1["test"]["warmup_samples"].get<long>(), 5);
  for (const char* side : {"after", "before"}) {
    const double t = r1["test"][std::string("rms_") + side].get<double>();
    const double v = r1[side]["rms_validation"].get<double>();
    EXPECT_LE((nv - 5) * t * t, nv * v * v * (1 + 1e-9)) << side;
    EXPECT_GT(t, 0.5 * v) << side;
  }
  EXPECT_TRUE(r1["test"]["fit_percent_after"].is_number());

  ASSERT_EQ(run("diagnose", common + " --test " + est + " --report " + file("t2.json") + " --model-out " + file("m2.json")), 0)
      << output();
  const nlohmann::json r2 = report("t2.json");
  EXPECT_EQ(r1["effects"], r2["effects"]);
  std::ifstream m1(file("m1.json")), m2(file("m2.json"));
  const std::string t1((std::istreambuf_iterator<char>(m1)), std::istreambuf_iterator<char>());
  const std::string t2((std::istreambuf_iterator<char>(m2)), std::istreambuf_iterator<char>());
  EXPECT_EQ(t1, t2);
  EXPECT_NE(r2["test"]["rms_after"].get<double>(), r1["test"]["rms_after"].get<double>());
  // the estimation record itself as the test record: every signal inside its own range, the ranges equal
  ASSERT_GE(r2["test"]["range"].size(), 3u);  // u1, y1 and the scheduling columns
  for (const nlohmann::json& s : r2["test"]["range"]) {
    EXPECT_EQ(s["samples_below"].get<long>() + s["samples_above"].get<long>(), 0) << s;
    EXPECT_EQ(s["test_range"], s["estimation_range"]) << s;
  }
  EXPECT_EQ(r2["test"]["after_worse"].get<bool>(),
            r2["test"]["rms_after"].get<double>() > r2["test"]["rms_before"].get<double>());

  ASSERT_EQ(run("diagnose", common + " --report " + file("t3.json")), 0) << output();
  EXPECT_TRUE(report("t3.json")["test"].is_null());
}

// A sensor |·| the declared model lacks, and a test record whose input is 1.6
// times the validation record's, so that it leaves the estimation range.
// Known answers by construction: the true system, simulated here, makes the
// test output (plus white noise of 0.02); diagnose must name |·|, score the
// model after below the model before on the test record (near the noise), and
// state that the input leaves the estimation range.
TEST_F(DiagnoseCommandTest, SensorAbsIsFoundAndHoldsOnATestRecordBeyondTheEstimationRange) {
  const EffectCase c = make_effect_case("abs_value", 400, 3, 0.02);
  Experiment<Rational> t = c.validation;
  for (Eigen::Index k = 0; k < t.u.rows(); ++k) t.u(k, 0) = t.u(k, 0) * Rational(8) / Rational(5);
  Mat<double> y = nearest_double(simulate(c.truth, t).output);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (Eigen::Index k = 0; k < y.rows(); ++k) y(k, 0) += noise(rng);
  const std::string e = file("abs_est.csv"), test = file("abs_test.csv"), m = file("abs_declared.json");
  write_csv(e, {{"u1", column_text(c.estimation.u, 0)}, {"y1", column_text(c.estimation.y, 0)},
                {"rho1", column_text(c.estimation.rho, 0)}});
  write_csv(test, {{"u1", column_text(t.u, 0)}, {"y1", column_text(y, 0)}, {"rho1", column_text(t.rho, 0)}});
  write_model_file(m, c.declared);
  ASSERT_EQ(run("diagnose", "--data " + e + " --model " + m + " --test " + test +
                                " --warmup 10 --max-effects 2 --max-windows 1 --report " + file("abs.json")),
            0)
      << output();
  const nlohmann::json r = report("abs.json");
  ASSERT_FALSE(r["effects"].empty());
  EXPECT_EQ(r["effects"][0]["kind"], reported_effect_kind("abs_value"));
  const double before = r["test"]["rms_before"].get<double>(), after = r["test"]["rms_after"].get<double>();
  EXPECT_LT(after, before);
  EXPECT_LT(after, 0.1) << "the noise is 0.02";
  EXPECT_FALSE(r["test"]["after_worse"].get<bool>());
  const nlohmann::json& u1 = r["test"]["range"][0];
  EXPECT_EQ(u1["signal"], "u1");
  EXPECT_GT(u1["samples_below"].get<long>(), 0) << u1;
  EXPECT_GT(u1["samples_above"].get<long>(), 0) << u1;
  EXPECT_NE(output().find("OUTSIDE the estimation range: u1"), std::string::npos) << output();
}

// Without --window the bounds cover the whole estimation
// record (windows of 200 rows; a last one of 70 >= 50 rows stays its own),
// each window states its rows, every certificate passes the verifier, and
// certifying the windows on two threads reports exactly what one thread does.
TEST_F(DiagnoseCommandTest, WindowsCoverTheRecordAndThreadsDoNotChangeTheBounds) {
  const EffectCase c = make_effect_case("none", 270, 7, 0.02);
  write_csv(est, {{"u1", column_text(c.estimation.u, 0)}, {"y1", column_text(c.estimation.y, 0)},
                  {"rho1", column_text(c.estimation.rho, 0)}});
  const std::string common = "--data " + est + " --model " + model + " --validation " + val + " --max-effects 1";
  ASSERT_EQ(run("diagnose", common + " --threads 1 --report " + file("seq.json")), 0) << output();
  ASSERT_EQ(run("diagnose", common + " --threads 2 --report " + file("par.json")), 0) << output();
  EXPECT_NE(output().find("estimation rows 200:270"), std::string::npos) << output();
  EXPECT_NE(output().find("first window only"), std::string::npos) << output();
  const nlohmann::json seq = report("seq.json"), par = report("par.json");
  for (const char* side : {"before", "after"}) {
    const nlohmann::json& ws = seq[side]["windows"];
    ASSERT_EQ(ws.size(), 2u) << side;
    EXPECT_EQ(ws[0]["estimation_rows"], nlohmann::json::array({0, 200}));
    EXPECT_EQ(ws[1]["estimation_rows"], nlohmann::json::array({200, 270}));
    ASSERT_EQ(par[side]["windows"].size(), 2u) << side;
    for (size_t i = 0; i < 2; ++i) {
      const nlohmann::json& a = ws[i];
      const nlohmann::json& b = par[side]["windows"][i];
      for (const char* key : {"estimation_rows", "file_rows", "delta", "dmax", "verified", "informative", "rms_output"})
        EXPECT_EQ(a[key], b[key]) << side << " window " << i << " " << key;
      EXPECT_TRUE(b["informative"].is_boolean());
      // every certificate the report names exists (a verified bound has one)
      ASSERT_TRUE(b["certificate"].is_string()) << side << " window " << i;
      EXPECT_TRUE(std::filesystem::is_regular_file(b["certificate"].get<std::string>())) << b["certificate"];
      EXPECT_EQ(run_program(verify_exe, "certificate " + b["certificate"].get<std::string>()), 0) << output();
    }
  }
}

// Several test sets: each scored once and reported separately ("tests"); the
// same file twice gives the same figures twice, and "test" is the first.
TEST_F(DiagnoseCommandTest, SeveralTestSetsAreScoredSeparately) {
  const std::string scaled = file("scaled.csv");
  const EffectCase c = make_effect_case("output_offset", 200, 5, 0.02);
  Mat<double> y10 = nearest_double(c.validation.y) * 10.0;
  write_csv(scaled, {{"u1", column_text(c.validation.u, 0)}, {"y1", column_text(y10, 0)}, {"rho1", column_text(c.validation.rho, 0)}});
  ASSERT_EQ(run("diagnose", "--data " + est + " --model " + model + " --validation " + val + " --window 0:80 --max-taps 16" +
                                " --max-effects 1 --test " + val + " --test " + scaled + " --test " + val + " --report " +
                                file("t.json")),
            0)
      << output();
  const nlohmann::json r = report("t.json");
  ASSERT_EQ(r["tests"].size(), 3u);
  EXPECT_EQ(r["test"], r["tests"][0]);
  EXPECT_EQ(r["tests"][0]["rms_after"], r["tests"][2]["rms_after"]);
  EXPECT_GT(r["tests"][1]["rms_after"].get<double>(), 2 * r["tests"][0]["rms_after"].get<double>());
  EXPECT_NE(r["tests"][1]["source"].get<std::string>().find("scaled.csv"), std::string::npos);
  // y times 10 leaves the estimation range of y (the inputs are the validation record's own)
  const nlohmann::json& y1 = r["tests"][1]["range"][1];
  EXPECT_EQ(y1["role"], "output");
  EXPECT_GT(y1["samples_below"].get<long>() + y1["samples_above"].get<long>(), 0) << y1;
  EXPECT_GT(y1["beyond_width"].get<double>(), 1.0) << y1;
  EXPECT_NE(output().find("OUTSIDE the estimation range: y1"), std::string::npos) << output();
  for (const nlohmann::json& t : r["tests"])
    EXPECT_EQ(t["after_worse"].get<bool>(), t["rms_after"].get<double>() > t["rms_before"].get<double>());
  EXPECT_NE(output().find("test 3 of 3"), std::string::npos) << output();
  // one file, two column sets (here the same columns twice): two test sets
  ASSERT_EQ(run("diagnose", "--data " + est + " --model " + model + " --validation " + val + " --window 0:80 --max-taps 16" +
                                " --max-effects 1 --test " + val + " --test-columns u1,y1 --test-columns u1,y1 --report " +
                                file("c.json")),
            0)
      << output();
  const nlohmann::json rc = report("c.json");
  ASSERT_EQ(rc["tests"].size(), 2u);
  EXPECT_EQ(rc["tests"][0]["rms_after"], r["tests"][0]["rms_after"]);
  EXPECT_NE(rc["tests"][1]["source"].get<std::string>().find("columns u1,y1"), std::string::npos) << rc["tests"][1];
  // several files AND several column sets: refused before any work
  EXPECT_EQ(run_program(exe, "diagnose --data " + est + " --model " + model + " --test " + val + " --test " + scaled +
                                 " --test-columns u1,y1 --test-columns u1,y1"),
            2);
  EXPECT_NE(output().find("--test-columns"), std::string::npos) << output();
}

// --max-windows caps the certified windows; without --lower-ends no dual
// certificate is written; the cost estimate is said before any work.
TEST_F(DiagnoseCommandTest, WindowCapAndNoDualCertificatesByDefault) {
  const EffectCase c = make_effect_case("none", 270, 7, 0.02);
  write_csv(est, {{"u1", column_text(c.estimation.u, 0)}, {"y1", column_text(c.estimation.y, 0)},
                  {"rho1", column_text(c.estimation.rho, 0)}});
  ASSERT_EQ(run("diagnose", "--data " + est + " --model " + model + " --validation " + val +
                                " --max-effects 1 --max-windows 1 --report " + file("cap.json")),
            0)
      << output();
  const nlohmann::json r = report("cap.json");
  ASSERT_EQ(r["before"]["windows"].size(), 1u);
  EXPECT_EQ(r["before"]["windows"][0]["estimation_rows"], nlohmann::json::array({0, 200}));
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(file("cap.json")).parent_path()))
    EXPECT_EQ(e.path().string().find(".lower.json"), std::string::npos) << e.path();
  EXPECT_NE(output().find("expected roughly"), std::string::npos) << output();
}

TEST_F(DiagnoseCommandTest, BadInputIsRejectedWithTheReason) {
  const std::string base = "diagnose --data " + est + " --model " + model + " ";
  EXPECT_EQ(run_program(exe, base + "--validation-columns a,b,c"), 2);
  EXPECT_NE(output().find("--validation-columns"), std::string::npos) << output();
  EXPECT_EQ(run_program(exe, base + "--validation " + file("missing.csv")), 2);
  EXPECT_NE(output().find("missing.csv"), std::string::npos) << output();
  EXPECT_EQ(run_program(exe, base + "--window 0:5000"), 2);
  EXPECT_NE(output().find("window"), std::string::npos) << output();
  EXPECT_EQ(run_program(exe, base + "--holdout 1.5"), 2);
  EXPECT_EQ(run_program(exe, base + "--threads 0"), 2);
  std::ofstream(file("nan.csv")) << "u1,y1,rho1\n1,2,0\nnan,1,0\n";
  EXPECT_EQ(run_program(exe, "diagnose --data " + file("nan.csv") + " --model " + model), 2);
  EXPECT_NE(output().find("nan.csv:3"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
