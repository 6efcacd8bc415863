#pragma once
/// Measured data (docs/design.md §4): n samples of u (nu), y (ny) and ρ (nρ).

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
  /// Several records (experiments) of one system stacked row-wise
  /// (toeplitz/record_segments.h): record k is the rows [start_k, start_k +
  /// records[k]). Empty: one record of all rows (how one file's data is
  /// stored); read it through record_lengths() and record_count(), which
  /// always name at least one record. The model is simulated record by
  /// record, each from its own initial state, and Δ acts on each record from
  /// rest (docs/several_records.md).
  std::vector<Eigen::Index> records;
  /// Record k's own initial state (an empty vector: the model's x0). Empty
  /// list: the model's x0 for every record.
  std::vector<Vec<T>> record_x0;
  Eigen::Index n() const { return u.rows(); }
  Eigen::Index nu() const { return u.cols(); }
  Eigen::Index ny() const { return y.cols(); }
  Eigen::Index n_rho() const { return rho.cols(); }
  /// The records' lengths, at least one (all rows when `records` is empty).
  std::vector<Eigen::Index> record_lengths() const { return records.empty() ? std::vector<Eigen::Index>{n()} : records; }
  /// How many records, at least one.
  size_t record_count() const { return records.empty() ? 1 : records.size(); }
};

/// The same experiment with every number rounded to the nearest double
/// (the floating path reads what the exact path reads).
inline Experiment<double> nearest_double(const Experiment<Rational>& e) {
  Experiment<double> d;
  d.source = e.source;
  d.u = nearest_double(e.u);
  d.y = nearest_double(e.y);
  d.rho = nearest_double(e.rho);
  d.records = e.records;
  for (const Vec<Rational>& x0 : e.record_x0) d.record_x0.push_back(nearest_double(Mat<Rational>(x0)).col(0));
  return d;
}

}  // namespace lpvid
