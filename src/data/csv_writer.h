#pragma once
/// Writing data tables as CSV (header row, comma separated, LF line ends).

#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/column_map.h"
#include "data/experiment.h"

namespace lpvid {

/// A named column of numbers already rendered as text.
struct TextColumn {
  std::string name;
  std::vector<std::string> cells;
};

/// Writes columns of equal length; throws std::runtime_error if the file
/// cannot be written or the lengths differ.
void write_csv(const std::string& path, const std::vector<TextColumn>& columns);
std::string csv_text(const std::vector<TextColumn>& columns);

/// Renders column j of m: exact_decimal_or_fraction (Rational: a decimal when
/// it terminates, else p/q); shortest round-trip text (double).
std::vector<std::string> column_text(const Mat<Rational>& m, Eigen::Index j);
std::vector<std::string> column_text(const Mat<double>& m, Eigen::Index j);

/// The columns of an exact experiment under the names of `columns`: u, then
/// y, then ρ, each in exact text (what a data file of that model holds).
std::vector<TextColumn> experiment_columns(const ColumnMap& columns, const Experiment<Rational>& e);

}  // namespace lpvid
