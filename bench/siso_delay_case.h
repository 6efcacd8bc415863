#pragma once
// The SISO delayed-Δ case of the interval benches: the LTI model of
// fixtures/models/lti_siso.json, u ~ N(0, 1) (6 digits), y = ŷ + 0.48·z(k − d)
// + noise U(−0.002, 0.002) (10 digits), d = min(70, n/2): the true Δ is a
// delay of 0.48, which no 64-tap FIR can represent when d ≥ 64. Seeded by n.
#include <algorithm>
#include <string>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "examples/random_stream.h"
#include "model/model_file.h"
#include "model/simulate.h"

namespace lpvid::bench {

inline void siso_delay_case(int n, LpvModel<Rational>* model, Experiment<Rational>* exp) {
  *model = read_model_file<Rational>(std::string(LPVID_SOURCE_DIR) + "/fixtures/models/lti_siso.json");
  RandomStream rng(1000 + static_cast<uint64_t>(n));
  exp->u = Mat<Rational>(n, 1);
  exp->rho = Mat<Rational>(n, 0);
  exp->y = Mat<Rational>::Zero(n, 1);
  for (int k = 0; k < n; ++k) exp->u(k, 0) = round_to_digits(rng.normal(), 6);
  const Simulation<Rational> s = simulate(*model, *exp);
  const int d = std::min(70, n / 2);
  for (int k = 0; k < n; ++k) {
    const double w = k >= d ? 0.48 * nearest_double(s.z(k - d, 0)) : 0.0;
    exp->y(k, 0) = round_to_digits(nearest_double(s.output(k, 0)) + w + 0.002 * (2 * rng.uniform() - 1), 10);
  }
}

}  // namespace lpvid::bench
