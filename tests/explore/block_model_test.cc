// explore/block_model.h: the linear model with candidate effects around it.
// With neutral effect parameters it is the linear model; an input delay that
// the data has is found by the output-error fit.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "explore/block_model.h"
#include "support/gen_lti.h"

namespace lpvid {
namespace {

RC_GTEST_PROP(BlockModelProperty, NeutralEffectsReproduceTheLinearModel, ()) {
  const int n = *gen::uniform_int(1, 3);
  ObserverForm f = *gen::stable_system(n, 1);
  f.has_offset = *rc::gen::arbitrary<bool>();
  f.offset = *gen::hundredths(-300, 300);
  const Vec<double> u = gen::white_input(150, 1)(rc::Random(7), 50).value().col(0) * 3.0;
  const Vec<double> y = simulate_observer(f, u);
  EffectSet e;
  e.input_degree = *gen::uniform_int(1, 3);
  e.input_paths = *gen::uniform_int(1, 3);
  e.output_degree = *gen::uniform_int(1, 3);
  e.output_saturation = *rc::gen::arbitrary<bool>();  // level starts at max y: inactive
  e.lpv = *rc::gen::element(Scheduling::kNone, Scheduling::kInput, Scheduling::kOutputLag);
  const BlockModel m = neutral_block_model(f, e, u, y);
  RC_ASSERT((simulate_block_model(m, u) - y).cwiseAbs().maxCoeff() <= 1e-12 * (1 + y.cwiseAbs().maxCoeff()));
  BlockModel back = m;  // parameter vector round trip
  back.set_parameters(m.parameters());
  RC_ASSERT(back.parameters() == m.parameters());
}

TEST(BlockModelTest, FitRecoversAnInputDelay) {
  ObserverForm truth = zero_observer_form(2, 1, false);
  truth.a << -1.1, 0.3;
  truth.B << 1.0, 0.5;
  const Vec<double> u = gen::white_input(400, 1)(rc::Random(8), 50).value().col(0);
  Vec<double> delayed(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) delayed(k) = u(std::max<Eigen::Index>(k - 2, 0));
  const Vec<double> y = simulate_observer(truth, delayed);
  ObserverForm start = zero_observer_form(2, 1, false);
  start.a << -0.5, 0.0;
  start.B << 0.5, 0.0;
  auto fitted_rms = [&](int delay) {
    EffectSet e;
    e.delay = delay;
    BlockModel m = neutral_block_model(start, e, u, y);
    fit_block_model(m, u, y, /*fix_dynamics=*/false);
    return block_validation_rms(m, u, y, 5);
  };
  EXPECT_LT(fitted_rms(2), 1e-6);
  EXPECT_GT(fitted_rms(0), 0.1);
}

}  // namespace
}  // namespace lpvid
