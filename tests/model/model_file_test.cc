#include "model/model_file.h"

#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "core/number_text.h"
#include "json/json_number.h"
#include "support/generators.h"

#include "support/input_error_text.h"

namespace lpvid {
namespace {

using gen::error_of;

using gen::contains;

Rational q(const char* text) { return rational_from_text(text); }

Mat<Rational> mat(std::initializer_list<std::initializer_list<const char*>> rows) {
  Mat<Rational> m(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(rows.begin()->size()));
  Eigen::Index i = 0;
  for (const auto& row : rows) {
    Eigen::Index j = 0;
    for (const char* v : row) m(i, j++) = q(v);
    ++i;
  }
  return m;
}

/// A small valid model text; `replace` swaps one fragment for another so
/// that each test breaks exactly one thing.
std::string model_text(const std::string& from = "", const std::string& to = "") {
  std::string s = R"({
  "format": "lpvid-model/1",
  "states": 2, "inputs": 1, "outputs": 1,
  "scheduling": ["rho1", "rho2"],
  "columns": {"u": ["u"], "y": ["y"], "rho": ["r1", "r2"]},
  "initial": {
    "A": [{"basis": "1", "value": [[0, 1], [-0.3, -0.6]]},
          {"basis": "rho1", "value": [[0, 0], ["-1/100", 0]]}],
    "B": [{"basis": "1", "value": [[0], [1]]}],
    "C": [{"basis": "1", "value": [[1, 0]]}],
    "D": []
  },
  "correction": {"basis": ["rho1*rho2", "rho2^2"],
                 "A": [{"basis": "rho2^2", "value": [[0, 0], [0, 0.5]]}]},
  "uncertainty": {"structure": "multiplicative", "weight": 0.01},
  "offset": {"basis": ["1", "rho1"], "values": [[0.1], ["1/3"]]},
  "x0": [0, "2.5e-1"]
}
)";
  if (!from.empty()) {
    const size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  }
  return s;
}

TEST(ModelFileTest, ReadsEveryFieldExactly) {
  const LpvModel<Rational> m = parse_model_json<Rational>(model_text(), "m.json");
  EXPECT_EQ(m.nx, 2);
  EXPECT_EQ(m.nu, 1);
  EXPECT_EQ(m.ny, 1);
  EXPECT_EQ(m.scheduling, (std::vector<std::string>{"rho1", "rho2"}));
  EXPECT_EQ(m.columns.u, std::vector<std::string>{"u"});
  EXPECT_EQ(m.columns.rho, (std::vector<std::string>{"r1", "r2"}));
  ASSERT_EQ(m.A.terms.size(), 2u);
  EXPECT_EQ(m.A.rows, 2);
  EXPECT_EQ(m.A.terms[0].value, mat({{"0", "1"}, {"-3/10", "-3/5"}}));
  EXPECT_EQ(m.A.terms[1].basis.powers, (std::vector<int>{1, 0}));
  EXPECT_EQ(m.A.terms[1].value(1, 0), Rational(-1) / Rational(100));
  EXPECT_EQ(m.D.rows, 1);
  EXPECT_EQ(m.D.cols, 1);
  EXPECT_TRUE(m.D.terms.empty());
  ASSERT_EQ(m.correction.basis.size(), 2u);
  EXPECT_EQ(m.correction.basis[1].powers, (std::vector<int>{0, 2}));
  ASSERT_EQ(m.correction.A.size(), 2u);
  EXPECT_TRUE(m.correction.A[0].isZero());
  EXPECT_EQ(m.correction.A[1](1, 1), Rational(1) / Rational(2));
  ASSERT_EQ(m.correction.B.size(), 2u);
  EXPECT_EQ(m.correction.B[0].rows(), 2);
  EXPECT_EQ(m.correction.B[0].cols(), 1);
  EXPECT_EQ(m.uncertainty.structure, UncertaintyStructure::kMultiplicative);
  EXPECT_EQ(m.uncertainty.weight, Rational(1) / Rational(100));
  ASSERT_EQ(m.offset.values.size(), 2u);
  EXPECT_EQ(m.offset.values[0](0), Rational(1) / Rational(10));  // 0.1 is exactly 1/10
  EXPECT_EQ(m.offset.values[1](0), Rational(1) / Rational(3));   // "1/3" is exactly 1/3
  EXPECT_EQ(m.x0(1), Rational(1) / Rational(4));

  const LpvModel<double> d = parse_model_json<double>(model_text(), "m.json");
  EXPECT_EQ(d.A.terms[0].value(1, 0), -0.3);
  EXPECT_EQ(d.offset.values[1](0), 1.0 / 3.0);
  EXPECT_EQ(d.uncertainty.weight, 0.01);
}

TEST(ModelFileTest, ExactNumbersDoNotGoThroughDouble) {
  // 0.1 and 1/3 as JSON number, decimal string and fraction string.
  for (const char* tenth : {"0.1", "\"0.1\"", "\"1/10\"", "1e-1", "\" 2/20 \""}) {
    const LpvModel<Rational> m = parse_model_json<Rational>(model_text("[0.1]", std::string("[") + tenth + "]"), "m.json");
    EXPECT_EQ(m.offset.values[0](0), Rational(1) / Rational(10)) << tenth;
  }
  // More digits than a double holds: the exact text survives.
  const LpvModel<Rational> m =
      parse_model_json<Rational>(model_text("[0.1]", "[0.10000000000000000000000000001]"), "m.json");
  EXPECT_EQ(m.offset.values[0](0), q("0.10000000000000000000000000001"));
  EXPECT_NE(m.offset.values[0](0), Rational(1) / Rational(10));
  // A huge integer (beyond 64 bits) as a JSON number.
  const LpvModel<Rational> big =
      parse_model_json<Rational>(model_text("[0.1]", "[123456789012345678901234567890]"), "m.json");
  EXPECT_EQ(big.offset.values[0](0), q("123456789012345678901234567890"));
}

TEST(ModelFileTest, DesignPageExampleReadsAsWritten) {
  // Copied verbatim from docs/design.md §11.1, comments included.
  const std::string text = R"JSON({
  "format": "lpvid-model/1",
  "states": 2, "inputs": 2, "outputs": 2,
  "scheduling": ["rho1", "rho2"],
  "columns": {"u": ["u1","u2"], "y": ["y1","y2"], "rho": ["rho1","rho2"]},
  "initial": {                       // S_I; each matrix is a list of terms
    "A": [ {"basis": "1",    "value": [[0, 1], [-0.3, -0.6]]},
           {"basis": "rho1", "value": [[0, 0], [-0.01, 0]]} ],
    "B": [ {"basis": "1", "value": [[1, 0], [0, 1]]} ],
    "C": [ {"basis": "1", "value": [[1, 0], [0, 1]]} ],
    "D": []                          // absent or empty: zero
  },
  "correction": {                    // S_C; unknown C_i, D_i
    "basis": ["rho1*rho2", "rho1^2", "rho2^2"],
    "A": [], "B": []                 // optional fixed A_i, B_i, same term form
  },
  "uncertainty": {"structure": "multiplicative"},   // or additive + "weight"
  "offset": {"basis": ["1", "rho1"]},               // optional unknown Φ(ρ)
  "x0": [0, 0]                                       // optional
})JSON";
  const LpvModel<Rational> m = parse_model_json<Rational>(text, "spec.json");
  EXPECT_EQ(m.nx, 2);
  EXPECT_EQ(m.A.terms.size(), 2u);
  EXPECT_EQ(m.A.terms[0].value(1, 0), Rational(-3) / Rational(10));
  EXPECT_EQ(m.A.terms[1].value(1, 0), Rational(-1) / Rational(100));
  EXPECT_EQ(m.correction.basis.size(), 3u);
  EXPECT_EQ(m.correction.basis[1].powers, (std::vector<int>{2, 0}));
  EXPECT_EQ(m.offset.basis.size(), 2u);
  EXPECT_TRUE(m.offset.values.empty());
  EXPECT_EQ(m.uncertainty.structure, UncertaintyStructure::kMultiplicative);
}

TEST(ModelFileTest, DefaultsWhenOptionalKeysAreAbsent) {
  const std::string text = R"({"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1,
    "columns": {"u": ["u"], "y": ["y"]}, "initial": {}})";
  const LpvModel<Rational> m = parse_model_json<Rational>(text, "min.json");
  EXPECT_TRUE(m.scheduling.empty());
  EXPECT_TRUE(m.columns.rho.empty());
  EXPECT_TRUE(m.A.terms.empty());
  EXPECT_EQ(m.A.rows, 1);
  EXPECT_TRUE(m.correction.basis.empty());
  EXPECT_EQ(m.uncertainty.structure, UncertaintyStructure::kMultiplicative);
  EXPECT_EQ(m.uncertainty.weight, Rational(1));
  EXPECT_TRUE(m.offset.basis.empty());
  EXPECT_EQ(m.x0.size(), 1);
  EXPECT_EQ(m.x0(0), Rational(0));
  // rho columns default to the scheduling names.
  const LpvModel<double> s = parse_model_json<double>(model_text(", \"rho\": [\"r1\", \"r2\"]", ""), "m.json");
  EXPECT_EQ(s.columns.rho, (std::vector<std::string>{"rho1", "rho2"}));
}

TEST(ModelFileTest, StaticModelWithZeroStates) {
  const std::string text = R"({"format": "lpvid-model/1", "states": 0, "inputs": 2, "outputs": 1,
    "columns": {"u": ["a", "b"], "y": ["y"]},
    "initial": {"A": [{"basis": "1", "value": []}], "B": [{"basis": "1", "value": []}],
                "C": [{"basis": "1", "value": [[]]}], "D": [{"basis": "1", "value": [[2, 3]]}]}})";
  const LpvModel<Rational> m = parse_model_json<Rational>(text, "static.json");
  EXPECT_EQ(m.nx, 0);
  EXPECT_EQ(m.C.terms[0].value.rows(), 1);
  EXPECT_EQ(m.C.terms[0].value.cols(), 0);
  EXPECT_EQ(m.D.terms[0].value(0, 1), Rational(3));
  EXPECT_TRUE(gen::files::same_model(parse_model_json<Rational>(write_model_json(m), "w"), m));
}

struct BadCase {
  const char* from;
  const char* to;
  const char* expected;  // substring of the message
};

TEST(ModelFileTest, RejectsMalformedModelsWithPathAndReason) {
  const BadCase cases[] = {
      {"\"lpvid-model/1\"", "\"lpvid-model/2\"", "m.json:2: format: expected \"lpvid-model/1\", got \"lpvid-model/2\""},
      {"\"format\": \"lpvid-model/1\",", "", "missing required key \"format\""},
      {"\"states\": 2,", "\"states\": 2, \"colums\": {},", "colums: unknown key \"colums\""},
      {"\"states\": 2", "\"states\": -1", "states: expected an integer in 0..1000, got -1"},
      {"\"states\": 2", "\"states\": 1.5", "states: expected an integer, got 1.5"},
      {"\"inputs\": 1", "\"inputs\": 0", "inputs: expected an integer in 1..1000"},
      {"\"states\": 2", "\"states\": \"two\"", "states: 'two' is not a number"},
      {"[[0, 1], [-0.3, -0.6]]", "[[0, 1, 2], [-0.3, -0.6, 0]]",
       "m.json:7: initial.A[0].value: expected 2x2 matrix, got 2x3"},
      {"[[0, 0], [\"-1/100\", 0]]", "[[0, 0], [\"-1/100\"]]", "initial.A[1].value[1]: ragged matrix"},
      {"[[0], [1]]", "[[0], [1], [2]]", "initial.B[0].value: expected 2x1 matrix, got 3x1"},
      {"[[1, 0]]", "[[1, \"abc\"]]", "initial.C[0].value[0][1]: 'abc' is not a number"},
      {"[[1, 0]]", "[[1, \"nan\"]]", "initial.C[0].value[0][1]: 'nan' is not a number"},
      {"[[1, 0]]", "[[1, \"inf\"]]", "initial.C[0].value[0][1]: 'inf' is not a number"},
      {"[[1, 0]]", "[[1, null]]", "initial.C[0].value[0][1]: expected a number"},
      {"[[1, 0]]", "[[1, \"1/0\"]]", "zero denominator"},
      {"{\"basis\": \"rho1\"", "{\"basis\": \"rho3\"", "initial.A[1].basis: basis function 'rho3': unknown scheduling name 'rho3'"},
      {"{\"basis\": \"rho1\"", "{\"basis\": \"rho1^x\"", "initial.A[1].basis: basis function 'rho1^x': bad exponent 'x'"},
      {"{\"basis\": \"rho1\"", "{\"basis\": \"rho1**2\"", "'**'"},
      {"{\"basis\": \"rho1\"", "{\"basis\": 1", "expected a basis function as a string"},
      {"\"value\": [[0], [1]]", "\"value\": [[0], [1]], \"scale\": 2", "initial.B[0].scale: unknown key \"scale\""},
      {"\"y\": [\"y\"]", "\"y\": [\"y\", \"y2\"]", "columns.y: expected 1 column names (outputs), got 2"},
      {"\"rho\": [\"r1\", \"r2\"]", "\"rho\": [\"r1\"]", "columns.rho: expected 2 column names"},
      {"[\"rho1\", \"rho2\"]", "[\"rho1\", \"rho1\"]", "scheduling[1]: scheduling name \"rho1\" is listed twice"},
      {"[\"rho1\", \"rho2\"]", "[\"rho1\", \"rho 2\"]", "scheduling[1]: scheduling name \"rho 2\" must start"},
      {"[\"rho1*rho2\", \"rho2^2\"]", "[\"rho1*rho2\", \"rho2*rho1\"]", "correction.basis[1]: basis function \"rho2*rho1\" is listed twice"},
      {"\"A\": [{\"basis\": \"rho2^2\"", "\"A\": [{\"basis\": \"rho1\"", "correction.A[0].basis: \"rho1\" is not in correction.basis"},
      {"\"correction\": {", "\"correction\": {\"C\": [], ", "correction.C: unknown key \"C\""},
      {"\"multiplicative\"", "\"relative\"", "uncertainty.structure: expected \"multiplicative\", \"additive\" or \"general\""},
      {"\"weight\": 0.01", "\"weight\": 0", "uncertainty.weight: weight must be positive"},
      {"\"weight\": 0.01", "\"weight\": -1", "weight must be positive"},
      {"\"multiplicative\", \"weight\": 0.01", "\"general\", \"weight\": 0.01", "uncertainty.weight: unknown key \"weight\""},
      {"\"multiplicative\", \"weight\": 0.01", "\"general\"", "structure \"general\" needs \"nz\""},
      {"\"multiplicative\", \"weight\": 0.01", "\"general\", \"C1\": [{\"basis\": \"1\", \"value\": [[1, 0], [0, 1]]}], \"D1\": [{\"basis\": \"1\", \"value\": [[1]]}]",
       "uncertainty.D1[0].value: expected 2x1 matrix, got 1x1"},
      {"[[0.1], [\"1/3\"]]", "[[0.1]]", "offset.values: expected 2 vectors"},
      {"[[0.1], [\"1/3\"]]", "[[0.1], [1, 2]]", "offset.values[1]: expected a vector of 1 numbers, got 2 entries"},
      {"\"x0\": [0, \"2.5e-1\"]", "\"x0\": [0]", "x0: expected a vector of 2 numbers, got 1 entries"},
      {"\"x0\": [0, \"2.5e-1\"]", "\"x0\": {}", "x0: expected an array, got an object"},
      {"\"x0\": [0, \"2.5e-1\"]", "\"x0\": [0, 1], \"x0\": [0, 1]", "duplicate key \"x0\""},
      {"\"D\": []", "\"D\": [],", "JSON syntax error"},
      {"\"states\": 2", "\"states\": 1e400", "JSON syntax error"},
      {"\"initial\": {", "\"initial\": [", "JSON syntax error"},
  };
  for (const BadCase& c : cases) {
    const std::string text = model_text(c.from, c.to);
    for (int path = 0; path < 2; ++path) {
      const std::string e = error_of([&] {
        if (path == 0) parse_model_json<Rational>(text, "m.json");
        else parse_model_json<double>(text, "m.json");
      });
      EXPECT_TRUE(contains(e, c.expected)) << "replacing " << c.from << " by " << c.to << "\n  got: " << e
                                           << "\n  want: " << c.expected;
      EXPECT_EQ(e.rfind("m.json", 0), 0u) << e;
    }
  }
}

TEST(ModelFileTest, SyntaxErrorsGiveLineAndColumn) {
  const std::string e = error_of([] { parse_model_json<Rational>("{\n  \"format\": tru\n}", "s.json"); });
  EXPECT_TRUE(contains(e, "s.json:2: JSON syntax error (column")) << e;
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>("", "s.json"); }), "s.json:1: JSON syntax error"));
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>("[1, 2]", "s.json"); }), "expected an object"));
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>("{} {}", "s.json"); }), "JSON syntax error"));
  std::string deep(200, '[');
  EXPECT_TRUE(contains(error_of([&] { parse_model_json<Rational>(deep, "s.json"); }), "nesting deeper"));
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>("{\"format\": \"\xff\"}", "s.json"); }),
                       "JSON syntax error"));
}

TEST(ModelFileTest, SemanticErrorLinesPointAtTheValue) {
  const std::string e = error_of([] { parse_model_json<Rational>(model_text("[[1, 0]]", "[[1, 0, 3]]"), "m.json"); });
  EXPECT_TRUE(contains(e, "m.json:10: initial.C[0].value: expected 1x2 matrix, got 1x3")) << e;
  const std::string e2 = error_of([] { parse_model_json<Rational>(model_text("\"x0\": [0, \"2.5e-1\"]", "\"x0\": [0,\n \"x\"]"), "m.json"); });
  EXPECT_TRUE(contains(e2, "m.json:18: x0[1]: 'x' is not a number")) << e2;
}

TEST(ModelFileTest, WriterUsesExactText) {
  EXPECT_EQ(exact_decimal_or_fraction(q("1/3")), "1/3");
  EXPECT_EQ(exact_decimal_or_fraction(q("-0.3")), "-0.3");
  EXPECT_EQ(exact_decimal_or_fraction(q("1/8")), "0.125");
  EXPECT_EQ(exact_decimal_or_fraction(q("-1/1024")), "-0.0009765625");
  EXPECT_EQ(exact_decimal_or_fraction(q("12")), "12");
  EXPECT_EQ(exact_decimal_or_fraction(q("1e-50")), "1/100000000000000000000000000000000000000000000000000");
  EXPECT_EQ(rational_to_json(q("7")).dump(), "7");
  EXPECT_EQ(rational_to_json(q("-1/3")).dump(), "\"-1/3\"");
  EXPECT_EQ(rational_to_json(q("123456789012345678901234567890")).dump(), "\"123456789012345678901234567890\"");
  EXPECT_THROW(double_to_json(std::nan("")), std::invalid_argument);

  const LpvModel<Rational> m = parse_model_json<Rational>(model_text(), "m.json");
  const std::string text = write_model_json(m);
  EXPECT_TRUE(contains(text, "\"-1/100\"") || contains(text, "\"-0.01\"")) << text;
  EXPECT_TRUE(contains(text, "\"1/3\"")) << text;
  EXPECT_TRUE(gen::files::same_model(parse_model_json<Rational>(text, "w.json"), m)) << text;
  EXPECT_EQ(write_model_json(parse_model_json<Rational>(text, "w.json")), text);

  const LpvModel<double> d = parse_model_json<double>(model_text(), "m.json");
  const std::string dtext = write_model_json(d);
  EXPECT_TRUE(gen::files::same_model(parse_model_json<double>(dtext, "w.json"), d)) << dtext;
}

TEST(ModelFileTest, WriterRejectsModelsItCannotWrite) {
  LpvModel<Rational> m = parse_model_json<Rational>(model_text(), "m.json");
  LpvModel<Rational> bad = m;
  bad.columns.y.clear();
  EXPECT_THROW(write_model_json(bad), std::invalid_argument);
  bad = m;
  bad.A.terms[0].value = Mat<Rational>::Zero(3, 3);
  EXPECT_THROW(write_model_json(bad), std::invalid_argument);
  bad = m;
  bad.uncertainty.structure = UncertaintyStructure::kGeneral;
  EXPECT_THROW(write_model_json(bad), std::invalid_argument);  // weight 0.01 with general
  LpvModel<double> d = parse_model_json<double>(model_text(), "m.json");
  d.x0(0) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(write_model_json(d), std::invalid_argument);
}

TEST(ModelFileTest, FileRoundTripAndMissingFile) {
  const LpvModel<Rational> m = parse_model_json<Rational>(model_text(), "m.json");
  const std::string path = std::string(LPVID_BINARY_DIR) + "/model_file_test_roundtrip.json";
  write_model_file(path, m);
  EXPECT_TRUE(gen::files::same_model(read_model_file<Rational>(path), m));
  std::filesystem::remove(path);
  const std::string e = error_of([] { read_model_file<double>("/nonexistent/model.json"); });
  EXPECT_TRUE(contains(e, "/nonexistent/model.json") && contains(e, "cannot open")) << e;
}

// ---------------------------------------------------------------- fixtures

const std::string kFixtures = LPVID_SOURCE_DIR "/fixtures/models/";

TEST(ModelFixturesTest, Example1Initial) {
  const LpvModel<Rational> m = read_model_file<Rational>(kFixtures + "example1_initial.json");
  EXPECT_EQ(m.nx, 2);
  EXPECT_EQ(m.nu, 2);
  EXPECT_EQ(m.ny, 2);
  EXPECT_EQ(m.scheduling, (std::vector<std::string>{"rho1", "rho2"}));
  EXPECT_EQ(m.columns.u, (std::vector<std::string>{"u1", "u2"}));
  EXPECT_EQ(m.columns.y, (std::vector<std::string>{"y1", "y2"}));
  EXPECT_EQ(m.columns.rho, (std::vector<std::string>{"rho1", "rho2"}));
  // A(ρ) = [[0, 1], [-(0.3 + 0.01 ρ1), -(0.6 + 0.6 ρ2)]] (eq. 17) at ρ = (2, -1/2).
  Vec<Rational> rho(2);
  rho << Rational(2), Rational(-1) / Rational(2);
  EXPECT_EQ(m.A.at(rho), mat({{"0", "1"}, {"-0.32", "-0.3"}}));
  EXPECT_EQ(m.B.at(rho), mat({{"1", "0"}, {"0", "1"}}));
  EXPECT_EQ(m.C.at(rho), mat({{"1", "0"}, {"0", "1"}}));  // lacks the ρ2² of the true C
  EXPECT_TRUE(m.D.terms.empty());
  ASSERT_EQ(m.correction.basis.size(), 5u);
  EXPECT_EQ(m.correction.basis[4].text(m.scheduling), "rho2^2");
  EXPECT_EQ(m.correction.basis[2].text(m.scheduling), "rho1*rho2");
  EXPECT_EQ(m.correction.A.size(), 5u);
  for (const auto& a : m.correction.A) EXPECT_TRUE(a.isZero());
  EXPECT_EQ(m.uncertainty.structure, UncertaintyStructure::kMultiplicative);
  EXPECT_EQ(m.uncertainty.weight, Rational(1) / Rational(100));
  EXPECT_TRUE(gen::files::same_model(parse_model_json<Rational>(write_model_json(m), "w"), m));
}

TEST(ModelFixturesTest, LtiSiso) {
  const LpvModel<Rational> m = read_model_file<Rational>(kFixtures + "lti_siso.json");
  EXPECT_EQ(m.nx, 2);
  EXPECT_EQ(m.nu, 1);
  EXPECT_EQ(m.ny, 1);
  EXPECT_TRUE(m.scheduling.empty());
  const Vec<Rational> none(0);
  EXPECT_EQ(m.A.at(none), mat({{"0", "1"}, {"-3/25", "7/10"}}));
  EXPECT_EQ(m.B.at(none), mat({{"0"}, {"1"}}));
  EXPECT_EQ(m.C.at(none), mat({{"1/4", "1/2"}}));
  EXPECT_EQ(m.D.at(none), mat({{"0"}}));
  EXPECT_EQ(m.uncertainty.structure, UncertaintyStructure::kAdditive);
  EXPECT_EQ(m.uncertainty.weight, Rational(1) / Rational(10));
  EXPECT_EQ(m.correction.basis.size(), 1u);
  EXPECT_TRUE(m.correction.basis[0].is_constant());
  const LpvModel<double> d = read_model_file<double>(kFixtures + "lti_siso.json");
  EXPECT_EQ(d.A.terms[0].value(1, 0), -0.12);
  EXPECT_EQ(d.A.terms[0].value(1, 1), 0.7);
}

}  // namespace
}  // namespace lpvid
