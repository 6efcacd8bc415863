#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/input_error.h"
#include "model/monomial.h"
#include "support/input_error_text.h"

namespace lpvid {
namespace {

const std::vector<std::string> kNames = {"rho1", "rho2"};

std::string parse_error(std::string_view text, const std::vector<std::string>& names = kNames) {
  try {
    parse_monomial(text, names);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an InputError for '" << text << "'";
  return "";
}

using gen::contains;

TEST(MonomialParserTest, ParsesTheSpecForms) {
  EXPECT_EQ(parse_monomial("1", kNames).powers, (std::vector<int>{0, 0}));
  EXPECT_EQ(parse_monomial("rho1", kNames).powers, (std::vector<int>{1, 0}));
  EXPECT_EQ(parse_monomial("rho1*rho2", kNames).powers, (std::vector<int>{1, 1}));
  EXPECT_EQ(parse_monomial("rho2^2", kNames).powers, (std::vector<int>{0, 2}));
  EXPECT_EQ(parse_monomial("rho1^2*rho2", kNames).powers, (std::vector<int>{2, 1}));
  EXPECT_EQ(parse_monomial("  rho1 ^ 2 *\trho2 ", kNames).powers, (std::vector<int>{2, 1}));
  EXPECT_EQ(parse_monomial("rho2*rho1*rho1", kNames).powers, (std::vector<int>{2, 1}));
  EXPECT_EQ(parse_monomial("1", {}).powers, std::vector<int>{});
  EXPECT_EQ(parse_monomial("rho1^16", kNames).powers, (std::vector<int>{16, 0}));
}

TEST(MonomialParserTest, RejectsWithTheToken) {
  EXPECT_TRUE(contains(parse_error("rho3"), "unknown scheduling name 'rho3'")) << parse_error("rho3");
  EXPECT_TRUE(contains(parse_error("rho3"), "known: rho1, rho2"));
  EXPECT_TRUE(contains(parse_error("rho1", {}), "no scheduling variables"));
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"rho1^x", "bad exponent 'x'"},
      {"rho1^-1", "bad exponent '-1'"},
      {"rho1^1.5", "bad exponent '1.5'"},
      {"rho1^0", "exponent 0"},
      {"rho1^17", "larger than 16"},
      {"rho1^99999999999999999999", "larger than 16"},
      {"rho1^", "missing exponent"},
      {"^2", "missing scheduling name"},
      {"rho1**2", "'**'"},
      {"rho1* *rho2", "empty factor"},
      {"*rho1", "empty factor"},
      {"rho1*", "empty factor"},
      {"", "empty basis function"},
      {"  ", "empty basis function"},
      {"1*rho1", "'1' is only allowed"},
      {"2", "unknown scheduling name '2'"},
      {"rho1^2^3", "bad exponent"},
      {"rho1^9*rho1^9", "total power of 'rho1'"},
      {"rho 1", "unknown scheduling name 'rho 1'"},
  };
  for (const auto& [text, expected] : cases) {
    EXPECT_TRUE(contains(parse_error(text), expected)) << text << " -> " << parse_error(text);
  }
  // The message names the whole text, too.
  EXPECT_TRUE(contains(parse_error("rho1*rho3"), "basis function 'rho1*rho3'"));
}

RC_GTEST_PROP(MonomialParserProperty, TextRoundTrips, ()) {
  const int n = *rc::gen::inRange(0, 4);
  std::vector<std::string> names;
  for (int k = 0; k < n; ++k) names.push_back(*rc::gen::element<std::string>("rho", "p", "x_", "Theta") + std::to_string(k));
  Monomial m{std::vector<int>(static_cast<size_t>(n), 0)};
  for (int& p : m.powers) p = *rc::gen::inRange(0, kMaxMonomialPower + 1);
  RC_ASSERT(parse_monomial(m.text(names), names) == m);
}

RC_GTEST_PROP(MonomialParserProperty, ArbitraryTextParsesOrThrowsInputError, (const std::string& text)) {
  try {
    const Monomial m = parse_monomial(text, kNames);
    RC_ASSERT(m.powers.size() == kNames.size());
    RC_ASSERT(parse_monomial(m.text(kNames), kNames) == m);
  } catch (const InputError&) {
  }
}

}  // namespace
}  // namespace lpvid
