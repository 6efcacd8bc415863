#pragma once
// Random dense double matrices for the tests of src/dense/ (factorisations
// compared bit for bit with Eigen's).
#include <random>

#include <Eigen/Dense>

namespace lpvid::test {

/// B with entries uniform in (−1, 1).
inline Eigen::MatrixXd random_uniform(Eigen::Index rows, Eigen::Index cols, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd B(rows, cols);
  for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = u(rng);
  return B;
}

/// BᵀB/n + I (symmetric positive definite, eigenvalues ≥ 1), B n × n from random_uniform.
inline Eigen::MatrixXd random_spd(Eigen::Index n, std::mt19937_64& rng) {
  const Eigen::MatrixXd B = random_uniform(n, n, rng);
  return B.transpose() * B / static_cast<double>(n) + Eigen::MatrixXd::Identity(n, n);
}

}  // namespace lpvid::test
