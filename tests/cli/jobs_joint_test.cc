// lpvid jobs plan --joint / merge: the windows of one long record as the
// records of ONE claim (one Δ, one noise bound on the RMS over all samples),
// each window from the x0 the plan declares for it. Known answers: data of
// the true Example 1 system, so Δ = 0 with d = y − ŷ_true explains every
// window, and the joint d_max can be no larger than that residual's RMS over
// all rows (simulated here, independently); one Δ for all windows can do no
// better than each window with its own, so the joint d_max² is at least the
// sample-weighted mean of the windows' certified lower ends. A joint
// certificate that names other records than the plan's windows is refused.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/number_text.h"
#include "core/rms.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "examples/paper_example1.h"
#include "model/simulate.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct JobsJoint : CliRunner {
  /// A 600-row record of the true system planned as 3 windows of 200 with --joint.
  void plan_joint(const std::string& extra = "") {
    ASSERT_EQ(run("generate", "example1 --n 600 --noise-std 0.1 --out " + file("d.csv") + " --truth-out " +
                                  file("true.json")),
              0)
        << output();
    ASSERT_EQ(run("jobs", "plan --joint --data " + file("d.csv") + " --model " + file("true.json") +
                              " --delta 0.05 --window-length 200 --dir " + file("J") + extra),
              0)
        << output();
  }
  /// merge with the joint certificate replaced by `c`: the joint entry of merged.json.
  nlohmann::json merge_with(const nlohmann::json& c) {
    write_text(file("J/joint.cert.json"), c.dump(1));
    EXPECT_EQ(run("jobs", "merge --dir " + file("J")), 4) << output();
    return read_json(file("J/merged.json"))["joint"];
  }
};

TEST_F(JobsJoint, PlanListsTheJointJobLastWithEveryWindowAsARecord) {
  plan_joint();
  const std::string jobs = read_text(file("J/jobs.txt"));
  EXPECT_EQ(std::count(jobs.begin(), jobs.end(), '\n'), 4) << jobs;
  const std::string last = jobs.substr(jobs.rfind('\n', jobs.size() - 2) + 1);
  for (const char* rows : {"--rows 0:200 --x0", "--rows 200:400 --x0", "--rows 400:600 --x0"})
    EXPECT_NE(last.find(rows), std::string::npos) << last;
  EXPECT_NE(last.find(file("J/joint.cert.json")), std::string::npos) << last;
  const nlohmann::json plan = read_json(file("J/plan.json"));
  ASSERT_TRUE(plan.contains("joint")) << plan.dump(1);
  EXPECT_EQ(plan["joint"]["certificate"], "joint.cert.json");
  EXPECT_EQ(plan["joint"]["command"].get<std::string>() + "\n", last);
  // one window cannot be a joint claim of several records
  EXPECT_EQ(run("jobs", "plan --joint --data " + file("d.csv") + " --model " + file("true.json") +
                            " --delta 0.05 --window-length 600 --dir " + file("K")),
            2)
      << output();
  EXPECT_NE(output().find("--joint"), std::string::npos) << output();
}

TEST_F(JobsJoint, MergeChecksTheJointClaimAndRefusesOneThatNamesOtherRecords) {
  plan_joint();
  ASSERT_EQ(run_program("bash", file("J/jobs.txt")), 0) << output();
  ASSERT_EQ(run("jobs", "merge --dir " + file("J")), 0) << output();
  EXPECT_NE(output().find("verified 3, invalidated 0, missing 0, refused 0"), std::string::npos) << output();
  const nlohmann::json merged = read_json(file("J/merged.json"));
  ASSERT_TRUE(merged.contains("joint")) << merged.dump(1);
  const nlohmann::json& joint = merged["joint"];
  ASSERT_EQ(joint["status"], "verified") << joint.dump(1);
  EXPECT_TRUE(joint["verified"].get<bool>());
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("J/joint.cert.json")), 0) << output();

  // the independent residual of the true model over all 600 rows
  const LpvModel<double> truth = convert_model<double>(example1_true_model());
  const Experiment<double> e = make_experiment<double>(read_csv(file("d.csv")), truth.columns);
  const double rms_r = rms(Mat<double>(e.y - simulate(truth, e).output));
  const Rational dmax2 = rational_from_text(joint["dmax2_exact"].get<std::string>());
  EXPECT_LE(nearest_double(dmax2), rms_r * rms_r * 1.002 + 1e-12) << joint.dump(1);
  // one Δ for all windows: no better than each window with its own
  Rational pooled_lower;
  for (const auto& w : merged["windows"]) {
    ASSERT_TRUE(w.contains("lower_exact")) << w.dump();
    pooled_lower += rational_from_text(w["lower_exact"].get<std::string>()) / Rational(3);
  }
  EXPECT_GE(dmax2, pooled_lower) << joint.dump(1);

  const nlohmann::json original = read_json(file("J/joint.cert.json"));
  ASSERT_EQ(original["records"].size(), 3u);
  nlohmann::json swapped = original;  // two records' rows swapped
  std::swap(swapped["records"][0]["rows"], swapped["records"][1]["rows"]);
  nlohmann::json j = merge_with(swapped);
  EXPECT_FALSE(j["verified"].get<bool>()) << j.dump(1);
  EXPECT_NE(j["reason"].get<std::string>().find("records[0] certifies rows 200:400"), std::string::npos) << j.dump(1);
  nlohmann::json moved = original;  // one x0 changed
  moved["records"][1]["x0"][0] = "1/3";
  j = merge_with(moved);
  EXPECT_FALSE(j["verified"].get<bool>()) << j.dump(1);
  EXPECT_NE(j["reason"].get<std::string>().find("records[1] starts from x0 = [1/3"), std::string::npos) << j.dump(1);
  nlohmann::json dropped = original;  // a record dropped
  dropped["records"].erase(2);
  j = merge_with(dropped);
  EXPECT_FALSE(j["verified"].get<bool>()) << j.dump(1);
  EXPECT_NE(j["reason"].get<std::string>().find("names 2 record(s)"), std::string::npos) << j.dump(1);
  // the windows are judged as before
  EXPECT_NE(output().find("verified 3, invalidated 0, missing 0, refused 0"), std::string::npos) << output();
  // no joint certificate: missing
  std::filesystem::remove(file("J/joint.cert.json"));
  EXPECT_EQ(run("jobs", "merge --dir " + file("J")), 4) << output();
  EXPECT_EQ(read_json(file("J/merged.json"))["joint"]["status"], "missing");
}

}  // namespace
}  // namespace lpvid
