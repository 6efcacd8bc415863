#pragma once
/// [lo, hi] of the finite values of a signal: the range a static map's
/// argument covers on a record (a polynomial map's fitted range, the range
/// of a state nonlinearity's argument, a test record's excursion beyond
/// the estimation range). NaN and ±inf are left out; with no finite value
/// the range is empty (lo > hi).

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace lpvid {

struct FiniteRange {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  bool any() const { return lo <= hi; }
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

/// The finite range of every entry of m (a matrix, a column, a row).
template <typename Derived>
FiniteRange finite_range(const Eigen::DenseBase<Derived>& m) {
  FiniteRange r;
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) r.add(m(i, j));
  return r;
}

}  // namespace lpvid
