// The weighted objective is stated on signals scaled by
// powers of ten to RMS ~1 (certify/bound_scaling.h). Known answers:
//  - by arithmetic: the exponents, and λ_orig = λ s_z²/(λ s_z² + 1 − λ);
//  - by construction: multiplying u and y of a linear model's data by 10³
//    multiplies z and r by exactly 10³, so the scaled programs are the same
//    and the certified δ is unchanged while d_max is multiplied by 10³
//    (eq. (*) of bound_scaling.h). Without the scaling the same data gives
//    another δ: λ then trades δ against d_max in the data's units.
#include <gtest/gtest.h>

#include <cmath>

#include "certify/bound_scaling.h"
#include "certify/certify.h"
#include "support/gen_identify.h"
#include "support/scratch_dir.h"
#include "support/siso_window_case.h"
#include "verify/certificate/certificate_check.h"
#include "solvers/solver_factory.h"

namespace lpvid {
namespace {

using namespace gen;

TEST(BoundScaling, DecimalExponents) {
  EXPECT_EQ(decimal_exponent(1.0), 0);
  EXPECT_EQ(decimal_exponent(0.8), 0);
  EXPECT_EQ(decimal_exponent(0.04), -1);  // log10 = −1.40
  EXPECT_EQ(decimal_exponent(0.02), -2);  // log10 = −1.70
  EXPECT_EQ(decimal_exponent(1234.0), 3);
  EXPECT_EQ(decimal_exponent(0.0), 0);
  EXPECT_EQ(decimal_exponent(NAN), 0);
}

TEST(BoundScaling, LambdaInOriginalUnits) {
  const Mat<double> z = Mat<double>::Constant(4, 1, 10.0), y = Mat<double>::Constant(4, 1, 1000.0);
  const SignalScales s = signal_scales(z, y, weighted_objective(0.5), false);
  EXPECT_TRUE(s.applied);
  EXPECT_EQ(s.z_exponent, 1);
  EXPECT_EQ(s.y_exponent, 3);
  EXPECT_NEAR(s.lambda_original, 100.0 / 101.0, 1e-15);
  EXPECT_NEAR(signal_scales(z, y, weighted_objective(0.2), false).lambda_original, 0.2 * 100 / (0.2 * 100 + 0.8), 1e-15);
  // multiplicative: z = W·ŷ is output-side, s_z = s_y = 10^3, δ' = δ
  const SignalScales m = signal_scales(z, y, weighted_objective(0.5), true);
  EXPECT_EQ(m.z_exponent, 3);
  EXPECT_NEAR(m.lambda_original, 1e6 / (1e6 + 1), 1e-15);
  EXPECT_DOUBLE_EQ(m.scaled_delta(2.0), 2.0);
  EXPECT_DOUBLE_EQ(s.scaled_delta(2.0), 2.0 * 1e-2);
  EXPECT_DOUBLE_EQ(s.scaled_dmax(2.0), 2.0 * 1e-3);
  // one bound fixed: nothing to rescale
  EXPECT_FALSE(signal_scales(z, y, min_dmax_objective(0.1), false).applied);
  EXPECT_EQ(objective_in_original_units(min_dmax_objective(0.1), s).kind, BoundObjective::Kind::kMinDmax);
}

struct Certified {
  CertifiedBounds b;
  std::string certificate;
};

Certified certify_file(const ScratchDir& dir, const std::string& tag, int decimals, bool scale) {
  std::vector<long> u, y;
  siso_generated(100, 50000, u, y);  // noise ≤ 0.05 on a signal of RMS ~0.8
  const std::string data = dir.file(tag + ".csv");
  write_siso_csv(data, u, y, decimals);
  const LpvModel<Rational> m = parse_model_json<Rational>(siso_window_model_json(), "G");
  CertifyOptions o = gen::certify_options(weighted_objective(), data);
  o.scale_signals = scale;
  auto solver = make_solver("csdp");
  const std::string certificate = dir.file(tag + ".cert.json");
  return {gen::written(certify_fixed_model(m, read_siso_csv(data, m), o, *solver), certificate), certificate};
}

TEST(BoundScaling, BoundsScaleWithTheDataExactlyAsDerived) {
  ScratchDir dir("bound_scaling");
  const Certified a = certify_file(dir, "unit", 6, true);
  const Certified k = certify_file(dir, "kilo", 3, true);  // the same integers: u, y times 10^3
  ASSERT_TRUE(a.b.verified()) << a.b.reason;
  ASSERT_TRUE(k.b.verified()) << k.b.reason;
  EXPECT_TRUE(check_certificate_file(k.certificate).holds);
  EXPECT_EQ(a.b.scales.y_exponent + 3, k.b.scales.y_exponent);
  EXPECT_EQ(a.b.scales.z_exponent + 3, k.b.scales.z_exponent);
  EXPECT_NEAR(k.b.delta, a.b.delta, 1e-4 * a.b.delta);
  EXPECT_NEAR(k.b.dmax, 1e3 * a.b.dmax, 1e-4 * 1e3 * a.b.dmax);
  EXPECT_NEAR(k.b.scales.scaled_dmax(k.b.dmax), a.b.scales.scaled_dmax(a.b.dmax), 1e-4 * a.b.dmax);

  // the control: λ in the data's units moves the optimum
  const Certified raw = certify_file(dir, "kilo_raw", 3, false);
  ASSERT_TRUE(raw.b.verified()) << raw.b.reason;
  EXPECT_FALSE(raw.b.scales.applied);
  EXPECT_GT(std::abs(raw.b.delta - a.b.delta), 0.1 * a.b.delta) << raw.b.delta << " vs " << a.b.delta;
}

}  // namespace
}  // namespace lpvid
