#include "diagnose/signal_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/finite_range.h"

namespace lpvid {

namespace {

void add_role(SignalRole role, const Mat<double>& est, const Mat<double>& test, std::vector<SignalExcursion>& out) {
  if (est.cols() != test.cols())
    throw std::invalid_argument("signal ranges: the estimation record has " + std::to_string(est.cols()) +
                                " columns of a role where the test record has " + std::to_string(test.cols()));
  for (Eigen::Index c = 0; c < est.cols(); ++c) {
    SignalExcursion e;
    e.role = role;
    e.column = c;
    const FiniteRange er = finite_range(est.col(c)), tr = finite_range(test.col(c));
    e.estimation_lo = er.lo;
    e.estimation_hi = er.hi;
    e.test_lo = tr.lo;
    e.test_hi = tr.hi;
    for (Eigen::Index i = 0; i < test.rows(); ++i) {
      const double v = test(i, c);
      if (!std::isfinite(v)) continue;
      ++e.samples;
      if (v < e.estimation_lo) ++e.below;
      if (v > e.estimation_hi) ++e.above;
    }
    out.push_back(e);
  }
}

}  // namespace

double SignalExcursion::beyond() const {
  if (outside() == 0) return 0.0;
  const double distance = std::max(below > 0 ? estimation_lo - test_lo : 0.0, above > 0 ? test_hi - estimation_hi : 0.0);
  const double width = estimation_hi - estimation_lo;
  return width > 0 ? distance / width : distance;
}

std::vector<SignalExcursion> signal_excursions(const Experiment<double>& estimation, const Experiment<double>& test) {
  std::vector<SignalExcursion> out;
  add_role(SignalRole::kInput, estimation.u, test.u, out);
  add_role(SignalRole::kOutput, estimation.y, test.y, out);
  add_role(SignalRole::kScheduling, estimation.rho, test.rho, out);
  return out;
}

}  // namespace lpvid
