#include "data/csv_writer.h"

#include <fstream>
#include <stdexcept>

#include "core/file_io.h"
#include "core/number_text.h"

namespace lpvid {

std::string csv_text(const std::vector<TextColumn>& columns) {
  std::string out;
  size_t rows = columns.empty() ? 0 : columns[0].cells.size();
  for (size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].cells.size() != rows) throw std::runtime_error("write_csv: column '" + columns[c].name + "' has a different length");
    out += (c ? "," : "") + columns[c].name;
  }
  out += "\n";
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < columns.size(); ++c) out += (c ? "," : "") + columns[c].cells[r];
    out += "\n";
  }
  return out;
}

void write_csv(const std::string& path, const std::vector<TextColumn>& columns) {
  write_text_file(path, csv_text(columns), "CSV file");
}

std::vector<std::string> column_text(const Mat<Rational>& m, Eigen::Index j) {
  std::vector<std::string> out;
  out.reserve(static_cast<size_t>(m.rows()));
  for (Eigen::Index i = 0; i < m.rows(); ++i) out.push_back(exact_decimal_or_fraction(m(i, j)));
  return out;
}

std::vector<std::string> column_text(const Mat<double>& m, Eigen::Index j) {
  std::vector<std::string> out;
  out.reserve(static_cast<size_t>(m.rows()));
  for (Eigen::Index i = 0; i < m.rows(); ++i) out.push_back(double_to_text(m(i, j)));
  return out;
}

std::vector<TextColumn> experiment_columns(const ColumnMap& columns, const Experiment<Rational>& e) {
  std::vector<TextColumn> cols;
  const auto add = [&cols](const std::vector<std::string>& names, const Mat<Rational>& m) {
    for (size_t j = 0; j < names.size(); ++j) cols.push_back({names[j], column_text(m, static_cast<Eigen::Index>(j))});
  };
  add(columns.u, e.u);
  add(columns.y, e.y);
  add(columns.rho, e.rho);
  return cols;
}

}  // namespace lpvid
