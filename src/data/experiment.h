#pragma once
/// Measured data (SPEC §1): n samples of u (nu), y (ny) and ρ (nρ).

#include <string>
#include <vector>

#include "core/number_text.h"
#include "core/scalar.h"

namespace lpvid {

/// A CSV (or whitespace) table kept as text so that each path reads the
/// numbers in its own scalar (exactly, for the verifier).
struct TextTable {
  std::string file;                           ///< path, for messages
  std::vector<std::string> header;            ///< column names
  std::vector<std::vector<std::string>> rows; ///< cells as written (trimmed, unquoted)
  std::vector<long> line_numbers;             ///< 1-based file line of each row
};

/// Rows k = 0..n-1; u is n × nu, y is n × ny, rho is n × nρ (nρ may be 0).
template <typename T>
struct Experiment {
  std::string source;  ///< file name (for messages and reports)
  Mat<T> u, y, rho;
  Eigen::Index n() const { return u.rows(); }
  Eigen::Index nu() const { return u.cols(); }
  Eigen::Index ny() const { return y.cols(); }
  Eigen::Index n_rho() const { return rho.cols(); }
};

/// The same experiment with every number rounded to the nearest double
/// (the floating path reads what the exact path reads).
inline Experiment<double> nearest_double(const Experiment<Rational>& e) {
  Experiment<double> d;
  d.source = e.source;
  d.u = nearest_double(e.u);
  d.y = nearest_double(e.y);
  d.rho = nearest_double(e.rho);
  return d;
}

}  // namespace lpvid
