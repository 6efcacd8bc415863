// Printed = certified, through the real binary: every bound `lpvid
// invalidate` prints is on the safe side of the exact value it certified
// (upper ends not below, lower ends not above), read from the same output
// (δ² and d_max² are printed exactly beside δ and d_max) and from the JSON
// report (the interval's exact ends).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/report.h"
#include "core/number_text.h"
#include "support/cli_runner.h"
#include "support/fixtures.h"

namespace lpvid {
namespace {

using gen::CliRunner;

struct PrintedBounds : CliRunner {};

/// The two numbers of "<name> <= X   (<name>^2 = Q" in the output.
std::pair<Rational, Rational> printed_and_square(const std::string& out, const std::string& name) {
  const std::regex re(name + R"(\s+<=\s+([0-9.eE+-]+)\s+\()" + name + R"(\^2 = ([0-9./eE+-]+))");
  std::smatch m;
  if (!std::regex_search(out, m, re)) throw std::runtime_error(name + " line not found in:\n" + out);
  return {rational_from_text(m[1].str()), rational_from_text(m[2].str())};
}

TEST_F(PrintedBounds, UpperEndsUpLowerEndsDown) {
  const std::string rep = file("r.json");
  ASSERT_EQ(run("invalidate", "--data " + gen::kExample1Fixtures + "noise_free_n40.csv --model " + gen::kExample1Fixtures +
                                  "initial_model.json --max-taps 6 --certificate " + file("c.json") + " --report " + rep),
            0)
      << output();
  for (const char* name : {"delta", "dmax"}) {
    const auto [printed, square] = printed_and_square(output(), name);
    EXPECT_GE(printed * printed, square) << name << ": " << output();
  }
  const nlohmann::json r = nlohmann::json::parse(std::ifstream(rep));
  const nlohmann::json& iv = r.contains("interval") ? r["interval"] : r;
  std::smatch m;
  const std::string out = output();
  if (iv.value("lower_verified", false)) {
    ASSERT_TRUE(std::regex_search(out, m, std::regex(R"(interval\s+\[([0-9.eE+-]+), ([0-9.eE+-]+)\])"))) << out;
    EXPECT_LE(rational_from_text(m[1].str()), rational_from_text(iv["lower_exact"].get<std::string>())) << out;
    EXPECT_GE(rational_from_text(m[2].str()), rational_from_text(iv["upper_exact"].get<std::string>())) << out;
    // the JSON numbers too (doubles, directed like the text)
    EXPECT_LE(Rational(iv["lower"].get<double>()), rational_from_text(iv["lower_exact"].get<std::string>())) << iv;
  }
  EXPECT_GE(Rational(iv["upper"].get<double>()), rational_from_text(iv["upper_exact"].get<std::string>())) << iv;
}

// The report's interval ends as JSON numbers: the nearest double of 1/3 is
// below it and that of 1/10 above it, so a nearest rounding would put both
// ends on the wrong side; directed, the upper end is the smallest double
// >= 1/3 and the lower end the largest <= 1/10.
TEST(PrintedBoundsJson, TheIntervalEndsAreRoundedOutwards) {
  CertifiedBounds b;
  b.outcome = CertifyOutcome::kVerified;
  b.upper = Rational(1, 3);
  b.lower.outcome = LowerEndOutcome::kCertified;
  b.lower.value = Rational(1, 10);
  BoundObjective objective;
  objective.kind = BoundObjective::Kind::kMinDmax;
  const nlohmann::ordered_json j = cli::interval_json(b, objective, CertificateFiles{"c.json", "c.lower.json"});
  const double upper = j["upper"].get<double>(), lower = j["lower"].get<double>();
  EXPECT_GE(Rational(upper), b.upper);
  EXPECT_LT(Rational(std::nextafter(upper, 0.0)), b.upper);
  EXPECT_LE(Rational(lower), b.lower.value);
  EXPECT_GT(Rational(std::nextafter(lower, 1.0)), b.lower.value);
}

TEST_F(PrintedBounds, TheVerifierEchoesTheExactClaimAndRoundsTheLowerEndDown) {
  const std::string rep = file("r.json"), cert = file("c.json");
  ASSERT_EQ(run("invalidate", "--data " + gen::kExample1Fixtures + "noise_free_n40.csv --model " + gen::kExample1Fixtures +
                                  "initial_model.json --delta 0.5 --certificate " + cert + " --report " + rep),
            0)
      << output();
  const nlohmann::json r = nlohmann::json::parse(std::ifstream(rep));
  ASSERT_EQ(run_program(verify_exe, "certificate " + cert), 0) << output();
  const std::string out = output();
  // the claim as exact numbers, read back from the certificate's own report
  EXPECT_NE(out.find("claim: toeplitz mode signal; consistent at delta^2 = " + r["delta2_exact"].get<std::string>() +
                     ", dmax^2 = " + r["dmax2_exact"].get<std::string>()),
            std::string::npos)
      << out;
  const nlohmann::json& iv = r["interval"];
  if (!iv.value("lower_verified", false)) GTEST_SKIP() << "no lower end certified";
  ASSERT_EQ(run_program(verify_exe, "certificate " + iv["lower_certificate"].get<std::string>()), 0) << output();
  std::smatch m;
  const std::string low = output();
  ASSERT_TRUE(std::regex_search(low, m, std::regex(R"(dmax\^2 >= ([0-9.eE+-]+) at delta\^2 = )"))) << low;
  EXPECT_LE(rational_from_text(m[1].str()), rational_from_text(iv["lower_exact"].get<std::string>())) << low;
}

}  // namespace
}  // namespace lpvid
