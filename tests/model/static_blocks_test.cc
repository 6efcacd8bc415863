// Static blocks (model/static_blocks.h): the maps are exact on rationals and
// satisfy their defining identities; the model file keeps them exactly
// (round trip) and rejects malformed ones with the field named; simulate()
// applies them where the header says (u' before the LPV part,
// g_out after ŷ + Φ).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "core/number_text.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "support/gen_numbers.h"
#include "support/input_error_text.h"

namespace lpvid {
namespace {

using gen::contains;
using gen::error_of;

StaticMap<Rational> map_of(StaticKind k, Rational lo, Rational hi, std::vector<Rational> c = {}) {
  StaticMap<Rational> g;
  g.kind = k;
  g.lower = lo;
  g.upper = hi;
  g.coefficients = std::move(c);
  return g;
}

RC_GTEST_PROP(StaticMapProperty, SaturationAndDeadZoneSplitTheSignal, ()) {
  Rational a = *gen::small_rational(), b = *gen::small_rational();
  if (b < a) std::swap(a, b);
  const Rational v = *gen::small_rational() * Rational(3);
  const auto sat = map_of(StaticKind::kSaturation, a, b), dz = map_of(StaticKind::kDeadZone, a, b);
  RC_ASSERT(sat(v) >= a);
  RC_ASSERT(sat(v) <= b);
  RC_ASSERT(sat(sat(v)) == sat(v));  // idempotent
  RC_ASSERT(sat(v) + dz(v) == v);    // dz(v) = v − sat(v), exactly
  RC_ASSERT((a <= v && v <= b) == (dz(v) == Rational(0) && sat(v) == v) || a == b);
}

RC_GTEST_PROP(StaticMapProperty, AbsAndHornerPolynomialAreExact, ()) {
  const Rational v = *gen::small_rational();
  const auto abs = map_of(StaticKind::kAbs, 0, 0);
  RC_ASSERT(abs(v) >= Rational(0));
  RC_ASSERT(abs(v) * abs(v) == v * v);
  const auto c = *rc::gen::container<std::vector<Rational>>(*rc::gen::inRange(1, 5), gen::small_rational());
  Rational naive(0), power(1);
  for (const Rational& ck : c) {
    naive += ck * power;
    power *= v;
  }
  RC_ASSERT(map_of(StaticKind::kPolynomial, 0, 0, c)(v) == naive);
}

// A polynomial with a range [lo, hi] is the polynomial inside it and, beyond
// it, the tangent line at the nearer end. Known answers from mathematics: the
// value by the power sum Σ c_k v^k and the slope by the derivative's
// coefficients k·c_k (not by Horner); the map is continuous at both ends and
// exactly affine beyond them (equal differences for equal steps).
RC_GTEST_PROP(StaticMapProperty, PolynomialContinuesLinearlyBeyondItsRange, ()) {
  const auto c = *rc::gen::container<std::vector<Rational>>(*rc::gen::inRange(1, 6), gen::small_rational());
  Rational lo = *gen::small_rational(), hi = *gen::small_rational();
  if (hi < lo) std::swap(lo, hi);
  StaticMap<Rational> g = map_of(StaticKind::kPolynomial, 0, 0, c);
  const StaticMap<Rational> free = g;
  g.range = {lo, hi};
  const auto power_sum = [&](const Rational& v) {
    Rational s(0), p(1);
    for (const Rational& ck : c) {
      s += ck * p;
      p *= v;
    }
    return s;
  };
  const auto derivative = [&](const Rational& v) {
    Rational s(0), p(1);
    for (size_t k = 1; k < c.size(); ++k) {
      s += Rational(static_cast<long>(k)) * c[k] * p;
      p *= v;
    }
    return s;
  };
  const Rational t = *gen::small_rational(), a = t < Rational(0) ? Rational(0) - t : t;
  const Rational inside = lo + (hi - lo) * a / (Rational(1) + a);  // in [lo, hi)
  RC_ASSERT(g(inside) == power_sum(inside));
  RC_ASSERT(g(lo) == free(lo));
  RC_ASSERT(g(hi) == free(hi));
  const Rational h = Rational(1) + a;  // a step > 0
  RC_ASSERT(g(hi + h) == power_sum(hi) + derivative(hi) * h);
  RC_ASSERT(g(lo - h) == power_sum(lo) - derivative(lo) * h);
  RC_ASSERT(g(hi + h + h) - g(hi + h) == g(hi + h) - g(hi));  // affine beyond hi
  RC_ASSERT(g(lo - h - h) - g(lo - h) == g(lo - h) - g(lo));  // and below lo
}

StaticMap<Rational> pwl(std::vector<Rational> knots, std::vector<Rational> values) {
  StaticMap<Rational> g;
  g.kind = StaticKind::kPiecewiseLinear;
  g.knots = std::move(knots);
  g.coefficients = std::move(values);
  return g;
}

// The piecewise-linear map interpolates its values at the knots, is affine
// between neighbouring knots (the midpoint gets the mean), extends its end
// segments, and with knots (a, b) and values (a, b) plus flat end segments it
// is exactly the saturation at [a, b] on every point.
RC_GTEST_PROP(StaticMapProperty, PiecewiseLinearInterpolatesExactly, ()) {
  const int m = *rc::gen::inRange(2, 6);
  std::vector<Rational> knots, values;
  Rational x = *gen::small_rational();
  for (int i = 0; i < m; ++i) {
    knots.push_back(x);
    values.push_back(*gen::small_rational());
    const Rational r = *gen::small_rational();
    x += Rational(1, 8) + r * r;  // strictly increasing
  }
  const auto g = pwl(knots, values);
  for (int i = 0; i < m; ++i) RC_ASSERT(g(knots[i]) == values[i]);
  for (int i = 0; i + 1 < m; ++i)
    RC_ASSERT(g((knots[i] + knots[i + 1]) / Rational(2)) == (values[i] + values[i + 1]) / Rational(2));
  // beyond the last knot: the last segment's slope continues
  const Rational slope = (values[m - 1] - values[m - 2]) / (knots[m - 1] - knots[m - 2]);
  RC_ASSERT(g(knots[m - 1] + Rational(3)) == values[m - 1] + Rational(3) * slope);
  // saturation as a piecewise-linear map
  const Rational a = knots[0], b = knots[1], v = *gen::small_rational() * Rational(4);
  const auto sat = pwl({a - Rational(1), a, b, b + Rational(1)}, {a, a, b, b});
  RC_ASSERT(sat(v) == map_of(StaticKind::kSaturation, a, b)(v));
}

TEST(StaticBlocks, DelayHoldsTheFirstSample) {
  StaticBlocks<Rational> s;
  s.input_delay = 2;
  Mat<Rational> u(4, 1);
  u << 1, 2, 3, 4;
  const Mat<Rational> d = s.model_input(u);
  EXPECT_EQ(d(0, 0), Rational(1));
  EXPECT_EQ(d(1, 0), Rational(1));
  EXPECT_EQ(d(2, 0), Rational(1));
  EXPECT_EQ(d(3, 0), Rational(2));
}

const char* kModel = R"({"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1,
  "columns": {"u": ["u"], "y": ["y"]},
  "initial": {"A": [{"basis": "1", "value": [["0.5"]]}], "B": [{"basis": "1", "value": [[1]]}],
              "C": [{"basis": "1", "value": [[1]]}]},
  "static": STATIC})";

std::string model_with(const std::string& st) {
  std::string s = kModel;
  s.replace(s.find("STATIC"), 6, st);
  return s;
}

TEST(StaticBlocks, ModelFileRoundTripIsExact) {
  const std::string text = model_with(
      R"({"input_delay": 1, "input": {"kind": "saturation", "lower": "-1/3", "upper": "0.7"},
          "output": {"kind": "polynomial", "coefficients": ["0.1", 1, "-2/7"]}})");
  const LpvModel<Rational> m = parse_model_json<Rational>(text, "m.json");
  EXPECT_EQ(m.statics.input_delay, 1);
  EXPECT_EQ(m.statics.input.kind, StaticKind::kSaturation);
  EXPECT_EQ(m.statics.input.lower, Rational(-1) / Rational(3));
  EXPECT_EQ(m.statics.output.coefficients.at(2), Rational(-2) / Rational(7));
  const LpvModel<Rational> back = parse_model_json<Rational>(write_model_json(m), "back.json");
  EXPECT_EQ(back.statics.input.lower, m.statics.input.lower);
  EXPECT_EQ(back.statics.input.upper, m.statics.input.upper);
  EXPECT_EQ(back.statics.output.coefficients, m.statics.output.coefficients);
  EXPECT_EQ(back.statics.input_delay, 1);
}

TEST(StaticBlocks, PolynomialRangeRoundTripsAndBadRangesAreNamed) {
  const LpvModel<Rational> m = parse_model_json<Rational>(
      model_with(R"({"output": {"kind": "polynomial", "coefficients": [0, 1, "-1/2"], "range": ["-1/3", "2.5"]}})"), "m.json");
  ASSERT_EQ(m.statics.output.range.size(), 2u);
  EXPECT_EQ(m.statics.output.range[0], Rational(-1) / Rational(3));
  // beyond 2.5: p(2.5) + p'(2.5)(v − 2.5) = (2.5 − 3.125) + (1 − 2.5)(v − 2.5); at v = 3.5: −0.625 − 1.5 = −2.125
  EXPECT_EQ(m.statics.output(Rational(7, 2)), Rational(-17, 8));
  const LpvModel<Rational> back = parse_model_json<Rational>(write_model_json(m), "back.json");
  EXPECT_EQ(back.statics.output.range, m.statics.output.range);
  const LpvModel<double> d = parse_model_json<double>(write_model_json(m), "back.json");
  EXPECT_EQ(d.statics.output.range.size(), 2u);
  const auto error = [](const std::string& map) {
    return error_of([&] { parse_model_json<Rational>(model_with(R"({"output": )" + map + "}"), "m.json"); });
  };
  EXPECT_TRUE(contains(error(R"({"kind": "polynomial", "coefficients": [1], "range": [2, 1]})"), "lo must not exceed hi"));
  EXPECT_TRUE(contains(error(R"({"kind": "polynomial", "coefficients": [1], "range": [1, 2, 3]})"), "static.output.range"));
  EXPECT_TRUE(contains(error(R"({"kind": "saturation", "lower": 0, "upper": 1, "range": [0, 1]})"), "range"));
}

TEST(StaticBlocks, PiecewiseLinearRoundTripIsExactAndBadKnotsAreNamed) {
  const LpvModel<Rational> m = parse_model_json<Rational>(
      model_with(R"({"output": {"kind": "piecewise_linear", "knots": [0, "1.5", 3], "values": [0, "1.5", "2/1"]}})"),
      "m.json");
  ASSERT_EQ(m.statics.output.kind, StaticKind::kPiecewiseLinear);
  EXPECT_EQ(m.statics.output(Rational(9, 4)), Rational(7, 4));  // 1.5 + (2.25 − 1.5)/3
  const LpvModel<Rational> back = parse_model_json<Rational>(write_model_json(m), "back.json");
  EXPECT_EQ(back.statics.output.knots, m.statics.output.knots);
  EXPECT_EQ(back.statics.output.coefficients, m.statics.output.coefficients);
  // the error of a model whose output map is {"kind": "piecewise_linear", <fields>}
  const auto pwl_error = [](const std::string& fields) {
    return error_of([&] {
      parse_model_json<Rational>(model_with(R"({"output": {"kind": "piecewise_linear", )" + fields + "}}"), "m.json");
    });
  };
  EXPECT_TRUE(contains(pwl_error(R"("knots": [0, 1, 1], "values": [0, 1, 2])"), "strictly increasing"));
  EXPECT_TRUE(contains(pwl_error(R"("knots": [0, 1], "values": [0])"), "one value per knot"));
  EXPECT_TRUE(contains(pwl_error(R"("knots": [0], "values": [0])"), "at least two knots"));
  EXPECT_TRUE(contains(pwl_error(R"("knots": [0, 1], "values": [0, 1], "slope": 2)"), "slope"));
}

TEST(StaticBlocks, MalformedBlocksNameTheField) {
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>(model_with(R"({"input": {"kind": "clip"}})"), "m.json"); }),
                       "static.input.kind"));
  EXPECT_TRUE(contains(error_of([] {
                         parse_model_json<Rational>(
                             model_with(R"({"input": {"kind": "saturation", "lower": 2, "upper": 1}})"), "m.json");
                       }),
                       "lower must not exceed upper"));
  EXPECT_TRUE(contains(
      error_of([] { parse_model_json<Rational>(model_with(R"({"output": {"kind": "polynomial", "coefficients": []}})"), "m.json"); }),
      "at least one coefficient"));
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>(model_with(R"({"input_delay": -1})"), "m.json"); }),
                       "static.input_delay"));
  EXPECT_TRUE(contains(error_of([] { parse_model_json<Rational>(model_with(R"({"gain": 2})"), "m.json"); }), "gain"));
}

/// x+ = 0.5 x + u', y = x; u' = sat(u, −1/3, 0.7) delayed by 1; out = 0.1 + v − 2/7 v².
TEST(StaticBlocks, SimulateAppliesInputThenOutputMap) {
  const std::string text = model_with(
      R"({"input_delay": 1, "input": {"kind": "saturation", "lower": "-1/3", "upper": "0.7"},
          "output": {"kind": "polynomial", "coefficients": ["0.1", 1, "-2/7"]}})");
  const LpvModel<Rational> m = parse_model_json<Rational>(text, "m.json");
  Experiment<Rational> e;
  e.u.resize(4, 1);
  e.u << 2, -1, 0, 1;
  e.y = Mat<Rational>::Zero(4, 1);
  e.rho.resize(4, 0);
  const Simulation<Rational> s = simulate(m, e);
  // u' = sat(u_{k-1}) with u_{-1} := u_0: 0.7, 0.7, −1/3, 0
  Rational x(0);
  const Rational up[4] = {Rational(7, 10), Rational(7, 10), Rational(-1, 3), Rational(0)};
  for (int k = 0; k < 4; ++k) {
    const Rational v = x;  // ŷ = C x, D = 0
    EXPECT_EQ(s.yhat(k, 0), v);
    EXPECT_EQ(s.output(k, 0), Rational(1, 10) + v - Rational(2, 7) * v * v) << k;
    x = Rational(1, 2) * x + up[k];
  }
}

}  // namespace
}  // namespace lpvid
