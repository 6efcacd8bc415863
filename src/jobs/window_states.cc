#include "jobs/window_states.h"

#include "core/decimal_rounding.h"
#include "model/simulate.h"

namespace lpvid::jobs {

std::vector<Vec<Rational>> window_start_states(const LpvModel<double>& model, const Experiment<double>& exp,
                                               const std::vector<Eigen::Index>& first_rows, int digits) {
  const Simulation<double> sim = simulate(model, exp);
  std::vector<Vec<Rational>> states;
  for (const Eigen::Index b : first_rows) {
    Vec<Rational> x(model.x0.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) x(i) = round_to_digits(sim.x(b, i), digits);
    states.push_back(x);
  }
  return states;
}

}  // namespace lpvid::jobs
