// `lpvid fit-linear` (the real binary, when built in the same tree): exit
// codes, the model file it writes, and clear errors for bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "fit/linear_fit.h"
#include "model/model_file.h"
#include "support/cli_runner.h"
#include "support/gen_lti.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

struct FitLinearCommandTest : gen::CliRunner {
  int run(const std::string& args) { return CliRunner::run("fit-linear", args); }
  /// Est/val columns of a second-order system with offset 2 (no noise).
  std::string write_data(const std::string& bad_cell = "") {
    ObserverForm f = zero_observer_form(2, 1, true);
    f.a << -1.2, 0.5;
    f.B << 1.0, 0.4;
    f.offset = 2.0;
    const Mat<double> u = gen::white_input(600, 1)(rc::Random(9), 50).value();
    const Vec<double> y = simulate_observer(f, u);
    const fs::path p = dir / "data.csv";
    std::ofstream out(p);
    out << "uEst,uVal,yEst,yVal\n";
    for (int k = 0; k < 300; ++k)
      out << u(k) << "," << u(k + 300) << "," << (k == 7 && !bad_cell.empty() ? bad_cell : std::to_string(y(k)))
          << "," << y(k + 300) << "\n";
    return p.string();
  }
};

TEST_F(FitLinearCommandTest, WritesAModelThatReproducesTheData) {
  const std::string data = write_data();
  const std::string model = (dir / "m.json").string();
  ASSERT_EQ(run("--data " + data + " --u uEst --y yEst --order auto --offset --validation-columns uVal,yVal"
                " --model-out " + model + " --report " + (dir / "r.json").string()),
            0)
      << output();
  EXPECT_NE(output().find("order 2"), std::string::npos) << output();
  // the order is chosen on the selection data given, and the rule is stated
  EXPECT_NE(output().find("free run scored on the validation (selection) data"), std::string::npos) << output();
  EXPECT_NE(output().find("chosen: order 2, the smallest order whose held-out free-run RMS is within 5%"),
            std::string::npos)
      << output();
  const LpvModel<double> m = read_model_file<double>(model);
  EXPECT_EQ(m.nx, 2);
  EXPECT_TRUE(m.scheduling.empty());
  EXPECT_EQ(m.columns.u, std::vector<std::string>{"uEst"});
  EXPECT_TRUE(fs::exists(dir / "r.json"));
}

TEST_F(FitLinearCommandTest, BadInputExitsWithTwoAndSaysWhy) {
  const std::string data = write_data();
  EXPECT_EQ(run("--data " + data + " --u uEst --y yEst --order 0"), 2);
  EXPECT_NE(output().find("--order"), std::string::npos) << output();
  EXPECT_EQ(run("--data " + data + " --u uEst --y yEst --order x"), 2);
  EXPECT_EQ(run("--data " + data + " --u uEst --y nope --order 1"), 2);
  EXPECT_NE(output().find("'nope' not found"), std::string::npos) << output();
  EXPECT_EQ(run("--data " + data + " --u uEst --y yEst --order 1 --rows 0:5"), 2);
  EXPECT_NE(output().find("too few"), std::string::npos) << output();
  EXPECT_EQ(run("--data " + write_data("nan") + " --u uEst --y yEst --order 1"), 2);
  EXPECT_NE(output().find("not a number"), std::string::npos) << output();
}

TEST_F(FitLinearCommandTest, SeveralRecordsGiveOneModelEachRecordItsOwnInitialState) {
  // the same file twice, once as rows 0:150 and once as rows 150:300: two
  // records of one noise-free system, each starting in its own state
  const std::string data = write_data();
  const std::string report = (dir / "r2.json").string();
  ASSERT_EQ(run("--data " + data + " --rows 0:150 --data " + data + " --rows 150:300 --u uEst --y yEst --offset"
                " --order auto --report " + report),
            0)
      << output();
  EXPECT_NE(output().find("record 2 of 2, its own x0"), std::string::npos) << output();
  EXPECT_NE(output().find("the last third of each record, rows 100:150, 100:150"), std::string::npos) << output();
  EXPECT_NE(output().find("chosen: order 2"), std::string::npos) << output();
  std::ifstream in(report);
  const nlohmann::json r = nlohmann::json::parse(in);
  ASSERT_EQ(r.at("records").size(), 2u);
  for (const auto& rec : r.at("records")) EXPECT_LT(rec.at("rms_estimation").get<double>(), 1e-6) << rec;
  // one --rows for two --data is refused, naming the option
  EXPECT_EQ(run("--data " + data + " --data " + data + " --rows 0:150 --u uEst --y yEst --order 1"), 2);
  EXPECT_NE(output().find("--rows: give one per --data"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
