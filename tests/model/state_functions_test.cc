// State functions as scheduling columns and the state offset E(ρ)
// (model/state_scheduling.h, model/lpv_model.h). Known answers from
// the definitions, never from the program's output:
//  - grid(√v) = floor(√(v·4^b) + 1/2)/2^b, checked by the bracket
//    (m − 1/2)² ≤ v·4^b < (m + 1/2)² on m = grid·2^b (exact rationals),
//    on perfect squares (r² → grid(r)) and on midpoints (ties upward);
//  - the exact and the double simulation of a model with the three
//    functions and a state offset follow the same trajectory, and every
//    state column equals its function of the exact state;
//  - the model file keeps the new fields exactly and refuses bad column
//    texts naming them.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/input_error.h"
#include "core/number_text.h"
#include "examples/model_literals.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"
#include "toeplitz/system_toeplitz.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid {
namespace {

using namespace literals;

/// The 2-vector of two decimal texts.
Vec<Rational> sf_vec(const char* a, const char* b) {
  Vec<Rational> v(2);
  v << dec(a), dec(b);
  return v;
}

const Rational kStep = Rational(1) / Rational(4294967296.0);  // 2^-32
const Rational kFourB = Rational(4294967296.0) * Rational(4294967296.0);  // 4^32

// ------------------------------------------------------------ column texts

TEST(StateFunctions, ColumnTextsParse) {
  StateColumn c = parse_state_column("@sqrt(x1-0.5)");
  EXPECT_EQ(c.state, 0);
  EXPECT_EQ(c.function, StateFunction::kSqrt);
  EXPECT_EQ(rational_from_text(c.shift), dec("0.5"));
  c = parse_state_column("@abs(x12+1/3)");
  EXPECT_EQ(c.state, 11);
  EXPECT_EQ(c.function, StateFunction::kAbs);
  EXPECT_EQ(rational_from_text(c.shift), Rational(-1, 3));
  c = parse_state_column("@hinge(x2)");
  EXPECT_EQ(c.state, 1);
  EXPECT_EQ(c.function, StateFunction::kHinge);
  EXPECT_EQ(rational_from_text(c.shift), Rational(0));
  c = parse_state_column("@sqrtpos(x2-7.5)");
  EXPECT_EQ(c.state, 1);
  EXPECT_EQ(c.function, StateFunction::kSqrtPos);
  EXPECT_EQ(rational_from_text(c.shift), dec("7.5"));
  EXPECT_EQ(parse_state_column("@x3").function, StateFunction::kState);
  EXPECT_EQ(parse_state_column("rho1").state, -1);
  EXPECT_EQ(state_scheduling_index("@sqrt(x2-1e-3)"), 1);
  for (const char* bad : {"@sqrt(x1-abc)", "@sqrt(x0)", "@cbrt(x1)", "@sqrt(x1--1)", "@sqrt(x1-0.5", "@sqrt()",
                          "@sqrt(y1)", "@abs(x1-1/0)", "@hinge(x1-)", "@sqrt(x1*2)", "@x1-0.5"}) {
    try {
      parse_state_column(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  try {
    state_scheduled({"rho1", "@sqrt(x9)"}, 2);
    ADD_FAILURE() << "state 9 of 2 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("@sqrt(x9)"), std::string::npos) << e.what();
  }
  const auto own = state_scheduled({"rho1", "@x1", "@abs(x2-1)"}, 2);
  ASSERT_EQ(own.size(), 2u);
  EXPECT_EQ(own[1], std::make_pair(2, 1));
}

RC_GTEST_PROP(StateFunctions, RenderedShiftReadsBackExactly, ()) {
  const double c = *rc::gen::inRange(-1000000000, 1000000000) * std::ldexp(1.0, *rc::gen::inRange(-40, 10)) / 7.0;
  const StateFunction f = *rc::gen::element(StateFunction::kAbs, StateFunction::kSqrt, StateFunction::kHinge);
  const int i = *rc::gen::inRange(0, 12);
  const std::string text = state_column_text(f, i, c);
  const StateColumn p = parse_state_column(text);
  RC_ASSERT(p.state == i);
  RC_ASSERT(p.function == f);
  RC_ASSERT(double_from_text(p.shift) == c);
  // the exact reader takes the text as the definition: its value rounds to c
  RC_ASSERT(nearest_double(rational_from_text(p.shift)) == c);
}

// ------------------------------------------------------------ exact √ grid

/// m = grid·2^b must be an integer with (m − 1/2)² ≤ |v|·4^b < (m + 1/2)²
/// (for m = 0 only the upper bound): floor(√N + 1/2) = m by definition.
void check_bracket(const Rational& v) {
  const Rational g = scheduling_grid_sqrt(v);
  const Rational m = g / kStep;
  RC_ASSERT(m.denominator() == 1);
  RC_ASSERT(m >= 0);
  const Rational N = (v < 0 ? Rational(-v) : v) * kFourB;
  const Rational half(1, 2);
  if (m > 0) RC_ASSERT((m - half) * (m - half) <= N);
  RC_ASSERT(N < (m + half) * (m + half));
}

RC_GTEST_PROP(StateFunctions, ExactSqrtGridIsTheRoundedRoot, ()) {
  const long p = *rc::gen::inRange<long>(-2000000000L, 2000000000L);
  const long q = *rc::gen::inRange<long>(1L, 2000000000L);
  const int scale = *rc::gen::inRange(-40, 20);
  Rational v = Rational(p) / Rational(q);
  v = scale >= 0 ? v * Rational(std::ldexp(1.0, scale)) : v / Rational(std::ldexp(1.0, -scale));
  check_bracket(v);
  // the double path: within one grid step of the exact one
  const double d = nearest_double(v);
  RC_ASSERT(CGAL::abs(Rational(scheduling_grid_sqrt(d)) - scheduling_grid_sqrt(Rational(d))) <= kStep);
}

RC_GTEST_PROP(StateFunctions, PerfectSquaresAndMidpoints, ()) {
  // r² → grid(√(r²)) = grid(r) (the independent rule of scheduling_grid)
  const Rational r = Rational(*rc::gen::inRange<long>(0, 4000000000L)) / Rational(*rc::gen::inRange<long>(1, 100000L));
  RC_ASSERT(scheduling_grid_sqrt(r * r) == scheduling_grid(r));
  RC_ASSERT(scheduling_grid_sqrt(Rational(-1) * r * r) == scheduling_grid(r));  // √|v|
  // an exact midpoint (m + 1/2)·2^-b squared rounds up to m + 1; just below it, to m
  const Rational m(*rc::gen::inRange<long>(0, 100000000000L));
  const Rational mid = (m + Rational(1, 2)) * kStep;
  RC_ASSERT(scheduling_grid_sqrt(mid * mid) == (m + 1) * kStep);
  RC_ASSERT(scheduling_grid_sqrt(mid * mid - kStep * kStep / Rational(1000000)) == m * kStep);
  // a grid point squared is a fixed point
  RC_ASSERT(scheduling_grid_sqrt(m * kStep * m * kStep) == m * kStep);
  check_bracket(mid * mid);
}

TEST(StateFunctions, FunctionValues) {
  const Rational x = dec("2.75"), c = dec("0.5");
  EXPECT_EQ(state_function_value(StateFunction::kAbs, x, c), dec("2.25"));
  EXPECT_EQ(state_function_value(StateFunction::kAbs, c, x), dec("2.25"));
  EXPECT_EQ(state_function_value(StateFunction::kSqrt, x, c), dec("1.5"));  // √2.25
  EXPECT_EQ(state_function_value(StateFunction::kSqrt, c, x), dec("1.5"));  // √|−2.25|
  EXPECT_EQ(state_function_value(StateFunction::kHinge, x, c), dec("2.25"));
  EXPECT_EQ(state_function_value(StateFunction::kHinge, c, x), Rational(0));
  EXPECT_EQ(state_function_value(StateFunction::kSqrtPos, x, c), dec("1.5"));  // √max(2.25, 0)
  EXPECT_EQ(state_function_value(StateFunction::kSqrtPos, c, x), Rational(0));  // below the level: no outflow
  EXPECT_EQ(state_function_value(StateFunction::kSqrtPos, 0.5, 2.75), 0.0);
  EXPECT_EQ(state_function_value(StateFunction::kState, x, Rational(0)), x);
  EXPECT_EQ(state_function_value(StateFunction::kSqrt, 2.75, 0.5), 1.5);
  EXPECT_EQ(state_function_value(StateFunction::kHinge, 0.5, 2.75), 0.0);
}

// ------------------------------------------------------------ simulation

/// x1+ = 0.6 x1 + u − 0.1·√|x1 + 1/4| − 0.5·max(x1 − 1.5, 0) + 0.02,
/// x2+ = 0.3 x1 + 0.5 x2 + 0.05·|x2 − 1/2|, y = x2: the three functions and a
/// constant in E(ρ) (scheduling s, a, h; the columns are state functions).
LpvModel<Rational> three_function_model() {
  LpvModel<Rational> m;
  m.nx = 2;
  m.nu = m.ny = 1;
  m.scheduling = {"s", "a", "h"};
  m.columns = {{"u1"}, {"y1"}, {"@sqrt(x1+1/4)", "@abs(x2-1/2)", "@hinge(x1-1.5)"}};
  const Monomial one{{0, 0, 0}}, s{{1, 0, 0}}, a{{0, 1, 0}}, h{{0, 0, 1}};
  m.A = ParamMatrix<Rational>(2, 2);
  m.A.add(one, literals::mat(2, 2, {"0.6", "0", "0.3", "0.5"}));
  m.B = ParamMatrix<Rational>(2, 1);
  m.B.add(one, sf_vec("1", "0"));
  m.C = ParamMatrix<Rational>(1, 2);
  m.C.add(one, literals::mat(1, 2, {"0", "1"}));
  m.D = ParamMatrix<Rational>(1, 1);
  m.state_offset.basis = {s, a, h, one};
  m.state_offset.values = {sf_vec("-0.1", "0"), sf_vec("0", "0.05"), sf_vec("-0.5", "0"),
                           sf_vec("0.02", "0")};
  m.x0 = sf_vec("0.25", "-0.75");
  return m;
}

Experiment<Rational> dyadic_input(int n, unsigned seed) {
  Experiment<Rational> e;
  e.u.resize(n, 1);
  unsigned s = seed;
  for (int k = 0; k < n; ++k) {
    s = s * 1103515245u + 12345u;
    e.u(k, 0) = Rational(static_cast<int>((s >> 8) % 1024)) / Rational(512);  // [0, 2), exact in double
  }
  e.rho = Mat<Rational>::Zero(n, 3);
  return e;
}

TEST(StateFunctions, ExactAndDoubleSimulationAgree) {
  const LpvModel<Rational> m = three_function_model();
  const Experiment<Rational> e = dyadic_input(60, 7);
  const Simulation<Rational> sq = simulate(m, e);
  const Simulation<double> sd = simulate(convert_model<double>(m), nearest_double(e));
  bool above = false, below = false;  // the hinge is active at some samples and not at others
  for (Eigen::Index k = 0; k < e.n(); ++k) {
    // every state column is its function of the exact state
    EXPECT_EQ(sq.rho(k, 0), scheduling_grid_sqrt(sq.x(k, 0) + Rational(1, 4))) << k;
    const Rational d2 = sq.x(k, 1) - Rational(1, 2);
    EXPECT_EQ(sq.rho(k, 1), scheduling_grid(d2 < 0 ? Rational(-d2) : d2)) << k;
    const Rational d1 = sq.x(k, 0) - dec("1.5");
    EXPECT_EQ(sq.rho(k, 2), scheduling_grid(d1 > 0 ? d1 : Rational(0))) << k;
    (d1 > 0 ? above : below) = true;
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(nearest_double(sq.x(k, i)), sd.x(k, i), 1e-8) << k;
    EXPECT_NEAR(nearest_double(sq.output(k, 0)), sd.output(k, 0), 1e-8) << k;
  }
  EXPECT_TRUE(above && below);
  // the state equation by hand at k = 0 (x0 = (1/4, −3/4), ρ from x0):
  // x1 = 0.15 + u0 − 0.1·grid(√(1/2)) + 0.02, x2 = 0.075 − 0.375 + 0.05·1.25
  const Rational x1 = dec("0.15") + e.u(0, 0) - dec("0.1") * scheduling_grid_sqrt(Rational(1, 2)) + dec("0.02");
  EXPECT_EQ(sq.x(1, 0), x1);
  EXPECT_EQ(sq.x(1, 1), dec("0.075") - dec("0.375") + dec("0.0625"));
  // without the state offset the trajectory differs (E is not ignored)
  LpvModel<Rational> plain = m;
  plain.state_offset = {};
  EXPECT_NE(simulate(plain, e).x(1, 0), sq.x(1, 0));
}

TEST(StateFunctions, PaperModeRefusesAStateOffset) {
  LpvModel<Rational> m = three_function_model();
  m.x0 = Vec<Rational>::Zero(2);
  Experiment<Rational> e = dyadic_input(10, 3);
  e = with_state_scheduling(m, e);
  try {
    T_z(m, e, ToeplitzMode::kPaper);
    ADD_FAILURE() << "paper mode accepted a state offset";
  } catch (const std::invalid_argument& ex) {
    EXPECT_NE(std::string(ex.what()).find("state_offset"), std::string::npos) << ex.what();
  }
  EXPECT_THROW(system_toeplitz(m, e), std::invalid_argument);
  // signal mode needs only z from the simulation
  EXPECT_EQ(T_z(m, e, ToeplitzMode::kSignal).rows(), 10);
}

TEST(StateFunctions, SizesOfTheStateOffsetAreChecked) {
  LpvModel<Rational> m = three_function_model();
  m.state_offset.values[1] = literals::mat(1, 1, {"1"});
  EXPECT_THROW(system_matrices(m), std::invalid_argument);
  m = three_function_model();
  m.state_offset.values.pop_back();
  EXPECT_THROW(system_matrices(m), std::invalid_argument);
  m = three_function_model();
  m.state_offset.basis[0] = Monomial{{1, 0}};
  EXPECT_THROW(system_matrices(m), std::invalid_argument);
}

// ------------------------------------------------------------ model file

std::string error_text(const std::string& text) {
  try {
    parse_model_json<Rational>(text, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StateFunctions, ModelFileRoundTrip) {
  const LpvModel<Rational> m = three_function_model();
  const std::string text = write_model_json(m);
  EXPECT_NE(text.find("\"state_offset\""), std::string::npos);
  EXPECT_NE(text.find("@sqrt(x1+1/4)"), std::string::npos);
  for (int pass = 0; pass < 2; ++pass) {
    const LpvModel<Rational> r = parse_model_json<Rational>(pass == 0 ? text : write_model_json(parse_model_json<Rational>(text, "a")), "m.json");
    EXPECT_EQ(r.columns.rho, m.columns.rho);
    ASSERT_EQ(r.state_offset.basis.size(), m.state_offset.basis.size());
    for (size_t j = 0; j < m.state_offset.basis.size(); ++j) {
      EXPECT_TRUE(r.state_offset.basis[j] == m.state_offset.basis[j]) << j;
      EXPECT_EQ(r.state_offset.values[j], m.state_offset.values[j]) << j;
    }
    // the same exact trajectory
    const Experiment<Rational> e = dyadic_input(20, 11);
    EXPECT_EQ(simulate(r, e).x, simulate(m, e).x);
  }
  // the double reader reads the same text
  const LpvModel<double> d = parse_model_json<double>(text, "m.json");
  EXPECT_EQ(d.state_offset.values[0](0), -0.1);
  // a model without a state offset writes no such key
  LpvModel<Rational> plain = m;
  plain.state_offset = {};
  EXPECT_EQ(write_model_json(plain).find("state_offset"), std::string::npos);
}

TEST(StateFunctions, ModelFileRefusesBadTextsNamingThem) {
  std::string text = write_model_json(three_function_model());
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) t.replace(at, from.size(), to);
    return t;
  };
  for (const std::string bad : {"@sqrt(x9)", "@sqrt(x1-abc)", "@sqr(x1)", "@abs(x1--2)"}) {
    const std::string e = error_text(with("@sqrt(x1+1/4)", bad));
    EXPECT_NE(e.find(bad), std::string::npos) << e;
    EXPECT_NE(e.find("columns.rho[0]"), std::string::npos) << e;
  }
  // state_offset: values required, nx entries each, basis texts known
  EXPECT_NE(error_text(with("\"values\": [", "\"valuez\": [")).find("state_offset"), std::string::npos);
  const std::string e2 = error_text(with("\"state_offset\": {", "\"state_offset\": {\"extra\": 1, "));
  EXPECT_NE(e2.find("state_offset"), std::string::npos) << e2;
  // the writer refuses a model whose column names a missing state
  LpvModel<Rational> m = three_function_model();
  m.columns.rho[1] = "@abs(x3-1)";
  EXPECT_THROW(write_model_json(m), std::invalid_argument);
}

}  // namespace
}  // namespace lpvid
