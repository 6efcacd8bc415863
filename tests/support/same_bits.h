#pragma once
/// Bit-for-bit equality of two double matrices (same shape, same bytes: a
/// −0 against a +0 or two NaNs of different payloads count as different),
/// the check of every "same operations, same numbers" test.

#include <cstring>

#include <Eigen/Dense>

namespace lpvid::test {

inline bool same_bits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         (a.size() == 0 || std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0);
}

}  // namespace lpvid::test
