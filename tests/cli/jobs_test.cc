// lpvid jobs plan / merge: a record cut into windows run as separate
// processes. Known answers by construction: data generated from the true
// Example 1 system, so on every window Δ = 0 with d = y − ŷ_true explains
// the data, and the certified min d_max at a fixed δ can be no larger than
// the RMS of that residual on the window (computed here independently, by
// simulating the true model). Tampering and missing jobs must be caught.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include <nlohmann/json.hpp>

#include "core/rms.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "examples/paper_example1.h"
#include "model/simulate.h"
#include "support/cli_runner.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct Jobs : CliRunner {};

TEST_F(Jobs, PlanRunMergeBoundsEachWindowByItsTrueResidualAndCatchesTampering) {
  ASSERT_EQ(run("generate", "example1 --n 300 --noise-std 0.1 --out " + file("d.csv") + " --truth-out " +
                                file("true.json")),
            0)
      << output();
  ASSERT_EQ(run("jobs", "plan --data " + file("d.csv") + " --model " + file("true.json") + " --delta 0.05 --window-length 100 --dir " +
                            file("J")),
            0)
      << output();
  const std::string jobs = read_text(file("J/jobs.txt"));
  EXPECT_EQ(std::count(jobs.begin(), jobs.end(), '\n'), 3) << jobs;
  EXPECT_NE(jobs.find("--rows 100:200"), std::string::npos) << jobs;
  // the jobs run as separate processes, in any order (here: last first)
  ASSERT_EQ(run_program("tac", file("J/jobs.txt") + " | bash"), 0) << output();

  ASSERT_EQ(run("jobs", "merge --dir " + file("J")), 0) << output();
  EXPECT_NE(output().find("verified 3, invalidated 0, missing 0, refused 0"), std::string::npos) << output();
  const nlohmann::json merged = read_json(file("J/merged.json"));
  ASSERT_EQ(merged["windows"].size(), 3u);

  // the independent residual of the true model (x0 = 0 at row 0)
  const LpvModel<double> truth = convert_model<double>(example1_true_model());
  const Experiment<double> e = make_experiment<double>(read_csv(file("d.csv")), truth.columns);
  const Simulation<double> sim = simulate(truth, e);
  const Mat<double> r = e.y - sim.output;
  for (const auto& w : merged["windows"]) {
    ASSERT_EQ(w["status"], "verified") << w.dump();
    const long b = w["rows"][0], end = w["rows"][1];
    const double rms_r = rms(Mat<double>(r.middleRows(b, end - b)));
    EXPECT_LE(std::stod(w["dmax"].get<std::string>()), rms_r * 1.001 + 1e-9) << w.dump();
    EXPECT_GT(std::stod(w["dmax"].get<std::string>()), 0.0);
    ASSERT_TRUE(w.contains("lower_exact")) << w.dump();
  }

  // a tampered certificate (a smaller d_max² claimed) is refused
  const std::string cert0 = file("J/w00000.cert.json");
  const std::string original = read_text(cert0);
  const std::regex dmax2("\"dmax2\": \"[^\"]*\"");
  ASSERT_TRUE(std::regex_search(original, dmax2)) << original.substr(0, 400);
  write_text(cert0, std::regex_replace(original, dmax2, "\"dmax2\": \"0.000001\"", std::regex_constants::format_first_only));
  EXPECT_EQ(run("jobs", "merge --dir " + file("J")), 4) << output();
  EXPECT_NE(output().find("refused 1"), std::string::npos) << output();
  write_text(cert0, original);
  // a window whose job never ran
  std::filesystem::remove(file("J/w00002.cert.json"));
  EXPECT_EQ(run("jobs", "merge --dir " + file("J")), 4) << output();
  EXPECT_NE(output().find("missing 1"), std::string::npos) << output();
  EXPECT_NE(output().find("INCOMPLETE"), std::string::npos) << output();
  // data changed after the plan: refused before any check
  std::ofstream(file("d.csv"), std::ios::app) << "\n";
  EXPECT_EQ(run("jobs", "merge --dir " + file("J")), 2) << output();
  EXPECT_NE(output().find("changed"), std::string::npos) << output();
}

TEST_F(Jobs, AnInvalidatedWindowInvalidatesTheMerge) {
  // the initial model lacks the ρ2² output factor: at a tiny δ and d_max no
  // window can be explained
  ASSERT_EQ(run("generate", "example1 --n 120 --out " + file("d.csv") + " --model-out " + file("init.json")), 0)
      << output();
  ASSERT_EQ(run("jobs", "plan --data " + file("d.csv") + " --model " + file("init.json") +
                            " --delta 0.001 --dmax 0.001 --window-length 60 --dir " + file("J")),
            0)
      << output();
  ASSERT_EQ(run_program("bash", file("J/jobs.txt")), 1) << output();  // the last job's exit code: invalidated
  EXPECT_EQ(run("jobs", "merge --dir " + file("J")), 1) << output();
  EXPECT_NE(output().find("invalidated 2"), std::string::npos) << output();
}

TEST_F(Jobs, PlanRefusesTheOptionsThatBelongToEachJob) {
  EXPECT_EQ(run("jobs", "plan --data x.csv --model m.json --dir " + file("J") + " --report r.json"), 2) << output();
  EXPECT_NE(output().find("--report"), std::string::npos) << output();
  EXPECT_EQ(run("jobs", "merge --dir " + file("nothing_here")), 2) << output();  // a missing input: usage
}

}  // namespace
}  // namespace lpvid
