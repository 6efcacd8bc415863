#include "diagnose/signal_ranges.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace lpvid {

namespace {

/// [lo, hi] of the finite entries of one column (lo > hi when there are none).
std::pair<double, double> finite_range(const Mat<double>& m, Eigen::Index c) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    if (std::isfinite(m(i, c))) {
      lo = std::min(lo, m(i, c));
      hi = std::max(hi, m(i, c));
    }
  return {lo, hi};
}

void add_role(SignalRole role, const Mat<double>& est, const Mat<double>& test, std::vector<SignalExcursion>& out) {
  if (est.cols() != test.cols())
    throw std::invalid_argument("signal ranges: the estimation record has " + std::to_string(est.cols()) +
                                " columns of a role where the test record has " + std::to_string(test.cols()));
  for (Eigen::Index c = 0; c < est.cols(); ++c) {
    SignalExcursion e;
    e.role = role;
    e.column = c;
    std::tie(e.estimation_lo, e.estimation_hi) = finite_range(est, c);
    std::tie(e.test_lo, e.test_hi) = finite_range(test, c);
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
