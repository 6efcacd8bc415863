// `lpvid invalidate --delta 0` through the real binaries: answered in closed
// form (certify/closed_form.h), at once, with the interval's ends equal to
// ‖r‖²/(n·ny) — recomputed here from the data text (y = ŷ + e for a known
// model, tests/support/noise_only_case.h) — and both certificates accepted by
// lpvid-verify; a fixed d_max below it is invalidated, one above consistent.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/number_text.h"
#include "support/cli_runner.h"
#include "support/noise_only_case.h"

namespace lpvid {
namespace {

struct ZeroDeltaCli : gen::CliRunner {
  Rational exact;  ///< ‖r‖²/(n·ny) of the data text
  std::string inputs;

  void SetUp() override {
    gen::CliRunner::SetUp();
    if (IsSkipped()) return;
    const std::vector<Rational> a{Rational(1, 2), Rational(-1, 2)};  // 2 × 2
    write_text(file("model.json"), gen::diagonal_model_json({"1/2", "-1/2"}));
    const gen::NoiseOnlyRecord r = gen::noise_only_record(a, 30, 3);
    write_text(file("data.csv"), r.csv);
    exact = gen::residual_energy_of_text(read_text(file("data.csv")), a) / Rational(60);
    inputs = "--data " + file("data.csv") + " --model " + file("model.json");
  }
};

TEST_F(ZeroDeltaCli, TheIntervalAtDeltaZeroHasEqualEndsAndNoSolve) {
  ASSERT_EQ(run("invalidate", inputs + " --delta 0 --certificate " + file("c.json") + " --report " + file("r.json")), 0)
      << output();
  const std::string out = output();
  EXPECT_NE(out.find("closed form (delta = 0)"), std::string::npos) << out;  // the progress line and the text
  EXPECT_NE(out.find("relative gap 0"), std::string::npos) << out;
  const nlohmann::json r = read_json(file("r.json"));
  EXPECT_EQ(r["solver"], "closed form (delta = 0)");
  const nlohmann::json& iv = r["interval"];
  EXPECT_EQ(iv["relative_gap"].get<double>(), 0.0);
  EXPECT_EQ(rational_from_text(iv["upper_exact"].get<std::string>()), exact);
  EXPECT_EQ(rational_from_text(iv["lower_exact"].get<std::string>()), exact);
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("c.json")), 0) << output();
  EXPECT_EQ(output().rfind("consistent", 0), 0u) << output();
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("c.lower.json")), 0) << output();
  EXPECT_EQ(output().rfind("lower_bound", 0), 0u) << output();
  EXPECT_NE(output().find("form zero_delta"), std::string::npos) << output();
}

TEST_F(ZeroDeltaCli, AFixedDmaxIsDecidedOnEitherSide) {
  const double root = std::sqrt(nearest_double(exact));
  const std::string below = double_to_text(root * (1 - 1e-9)), above = double_to_text(root * (1 + 1e-9));
  ASSERT_LT(rational_from_text(below) * rational_from_text(below), exact);
  ASSERT_GT(rational_from_text(above) * rational_from_text(above), exact);
  ASSERT_EQ(run("invalidate", inputs + " --delta 0 --dmax " + below + " --certificate " + file("inv.json")), 1) << output();
  EXPECT_NE(output().find("INVALIDATED"), std::string::npos) << output();
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("inv.json")), 0) << output();
  EXPECT_EQ(output().rfind("invalidated", 0), 0u) << output();
  ASSERT_EQ(run("invalidate", inputs + " --delta 0 --dmax " + above + " --certificate " + file("ok.json")), 0) << output();
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("ok.json")), 0) << output();
  EXPECT_EQ(output().rfind("consistent", 0), 0u) << output();
}

}  // namespace
}  // namespace lpvid
