// The exact JSON layer (json/json_tree.h, json/json_number.h,
// json/json_members.h): numbers keep their text and line, every rational
// survives the trip to JSON text and back unchanged, and each malformed
// member is refused naming the file, the line and the JSON path.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>

#include "core/input_error.h"
#include "json/json_members.h"
#include "json/json_number.h"
#include "json/json_tree.h"
#include "support/input_error_text.h"

namespace lpvid {
namespace {

using gen::contains;
using gen::error_of;

TEST(ExactJsonTree, NumbersKeepTheirTextAndLine) {
  const JsonNode root = parse_exact_json("{\"a\": 0.1000,\n \"b\": [1e-30,\n 7]}", "t.json");
  ASSERT_TRUE(root.is_object());
  ASSERT_NE(root.find("a"), nullptr);
  EXPECT_EQ(root.find("a")->text, "0.1000");  // as written, not as a double prints it
  EXPECT_EQ(root.find("a")->line, 1);
  const JsonNode& b = *root.find("b");
  ASSERT_EQ(b.items.size(), 2u);
  EXPECT_EQ(b.items[0].text, "1e-30");
  EXPECT_EQ(b.items[1].line, 3);
  // 0.1 read exactly is 1/10, which no double is
  EXPECT_EQ(number_from_json<Rational>(*root.find("a"), "t.json", "a"), Rational(1, 10));
}

TEST(ExactJsonTree, DuplicateKeysAndDeepNestingAreRefused) {
  EXPECT_TRUE(contains(error_of([] { parse_exact_json("{\"a\": 1,\n \"a\": 2}", "d.json"); }), "d.json:2"));
  std::string deep;
  for (int i = 0; i <= kMaxJsonDepth; ++i) deep += "[";
  for (int i = 0; i <= kMaxJsonDepth; ++i) deep += "]";
  EXPECT_FALSE(error_of([&] { parse_exact_json(deep, "deep.json"); }).empty());
}

// Any rational p/q: written by rational_to_json, printed, parsed and read
// back exactly, it is the same rational (integers stay JSON integers).
RC_GTEST_PROP(ExactJsonNumbers, EveryRationalSurvivesTheRoundTrip, ()) {
  const long p = *rc::gen::inRange<long>(-2000000000L, 2000000000L);
  const long q = *rc::gen::inRange<long>(1L, 2000000000L);
  const int shift = *rc::gen::inRange(0, 80);
  Rational x(p, q);
  for (int i = 0; i < shift; ++i) x = x * Rational(1, 3);  // denominators beyond any double
  const nlohmann::ordered_json j = nlohmann::ordered_json::array({rational_to_json(x)});
  const JsonNode back = parse_exact_json(j.dump(), "r.json");
  RC_ASSERT(back.items.size() == 1u);
  RC_ASSERT(number_from_json<Rational>(back.items[0], "r.json", "[0]") == x);
  if (x.denominator() == 1) RC_ASSERT(back.items[0].is_number());
}

TEST(ExactJsonMembers, MissingAndMistypedMembersNameFileLineAndPath) {
  const JsonNode root = parse_exact_json("{\n \"claim\": {\n  \"n\": -3,\n  \"name\": 4,\n  \"m\": [[1, 2], [3]]}}", "c.json");
  const JsonNode& claim = member(root, "claim", "c.json", "");
  const std::string missing = error_of([&] { member(claim, "delta2", "c.json", "claim"); });
  EXPECT_TRUE(contains(missing, "c.json:2")) << missing;
  EXPECT_TRUE(contains(missing, "claim.delta2")) << missing;
  EXPECT_TRUE(contains(missing, "missing")) << missing;
  const std::string not_string = error_of([&] { string_member(claim, "name", "c.json", "claim"); });
  EXPECT_TRUE(contains(not_string, "c.json:4")) << not_string;
  EXPECT_TRUE(contains(not_string, "claim.name")) << not_string;
  const std::string negative = error_of([&] { integer_member(*claim.find("n"), "c.json", "claim.n"); });
  EXPECT_TRUE(contains(negative, "c.json:3")) << negative;
  const std::string short_row = error_of([&] { matrix_member(*claim.find("m"), "c.json", "claim.m", 2); });
  EXPECT_TRUE(contains(short_row, "claim.m[1]")) << short_row;
}

TEST(ExactJsonMembers, IntegersAndMatricesReadExactly) {
  const JsonNode root = parse_exact_json("{\"k\": 123456789012, \"big\": 1234567890123, \"m\": [[\"1/3\", 0.25]]}", "i.json");
  EXPECT_EQ(integer_member(*root.find("k"), "i.json", "k"), 123456789012L);
  EXPECT_FALSE(error_of([&] { integer_member(*root.find("big"), "i.json", "big"); }).empty());  // 13 digits
  const Mat<Rational> m = matrix_member(*root.find("m"), "i.json", "m", 2);
  EXPECT_EQ(m(0, 0), Rational(1, 3));
  EXPECT_EQ(m(0, 1), Rational(1, 4));
  // and written back, the same numbers
  const JsonNode again = parse_exact_json(matrix_json(m).dump(), "w.json");
  EXPECT_EQ(matrix_member(again, "w.json", "m", 2), m);
}

}  // namespace
}  // namespace lpvid
