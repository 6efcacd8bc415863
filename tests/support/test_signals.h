#pragma once
// Test signals for the residual analysis and plot tests.

#include <random>

#include "core/scalar.h"

namespace lpvid {

/// n × cols samples of N(0, scale²) from a fixed seed (std::mt19937).
inline Mat<double> gaussian(Eigen::Index n, Eigen::Index cols, unsigned seed, double scale = 1.0) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, scale);
  Mat<double> m(n, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < n; ++i) m(i, j) = g(rng);
  return m;
}

}  // namespace lpvid
