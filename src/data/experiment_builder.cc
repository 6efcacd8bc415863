#include "data/experiment_builder.h"

#include <algorithm>
#include <stdexcept>

#include "core/input_error.h"
#include "core/number_text.h"
#include "data/csv_reader.h"
#include "data/column_map.h"

namespace lpvid {
namespace {

std::string available_columns(const TextTable& table) {
  std::string out;
  for (size_t i = 0; i < table.header.size(); ++i) {
    if (i) out += ", ";
    out += "'" + table.header[i] + "'";
  }
  return out.empty() ? "none" : out;
}

std::vector<size_t> column_indices(const TextTable& table, const std::vector<std::string>& names) {
  std::vector<size_t> idx;
  idx.reserve(names.size());
  for (const std::string& name : names) {
    auto i = find_column(table, name);
    if (!i) throw_input_error(table.file, 0, "", "column '" + name + "' not found (available: " +
                                                    available_columns(table) + ")");
    idx.push_back(*i);
  }
  return idx;
}

template <typename T>
Mat<T> read_columns(const TextTable& table, const std::vector<std::string>& names) {
  const std::vector<size_t> idx = column_indices(table, names);
  const auto n = static_cast<Eigen::Index>(table.rows.size());
  Mat<T> m(n, static_cast<Eigen::Index>(idx.size()));
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto& row = table.rows[static_cast<size_t>(r)];
    const long line = static_cast<size_t>(r) < table.line_numbers.size() ? table.line_numbers[static_cast<size_t>(r)] : 0;
    for (size_t c = 0; c < idx.size(); ++c) {
      const std::string field = "column '" + names[c] + "'";
      if (idx[c] >= row.size()) throw_input_error(table.file, line, field, "missing cell");
      const std::string& cell = row[idx[c]];
      if (cell.empty()) throw_input_error(table.file, line, field, "empty cell is not a number");
      try {
        m(r, static_cast<Eigen::Index>(c)) = number_from_text<T>(cell);
      } catch (const InputError& e) {
        throw_input_error(table.file, line, field, e.what());
      }
    }
  }
  return m;
}

}  // namespace

template <typename T>
Experiment<T> make_experiment(const TextTable& table, const ColumnMap& columns) {
  if (table.rows.empty()) throw_input_error(table.file, 0, "", "no data rows");
  // Report unknown columns before any number, whatever the order.
  column_indices(table, columns.u);
  column_indices(table, columns.y);
  // "@x<i>" scheduling columns are the model's own state (data/column_map.h, model/state_scheduling.h):
  // zero here, computed by simulate() / with_state_scheduling().
  std::vector<std::string> data_rho;
  for (const std::string& c : columns.rho) {
    int i = -1;
    try {
      i = state_scheduling_index(c);
    } catch (const std::invalid_argument& e) {
      throw_input_error(table.file, 0, "", e.what());
    }
    if (i < 0) data_rho.push_back(c);
  }
  column_indices(table, data_rho);
  Experiment<T> exp;
  exp.source = table.file;
  exp.u = read_columns<T>(table, columns.u);
  exp.y = read_columns<T>(table, columns.y);
  const Mat<T> read = read_columns<T>(table, data_rho);
  exp.rho = Mat<T>::Zero(exp.u.rows(), static_cast<Eigen::Index>(columns.rho.size()));
  for (size_t j = 0, r = 0; j < columns.rho.size(); ++j)
    if (state_scheduling_index(columns.rho[j]) < 0) exp.rho.col(static_cast<Eigen::Index>(j)) = read.col(static_cast<Eigen::Index>(r++));
  return exp;
}

template <typename T>
Experiment<T> select_rows(const Experiment<T>& exp, Eigen::Index begin, Eigen::Index end) {
  if (begin < 0 || end < begin || end > exp.n())
    throw_input_error(exp.source, 0, "", "rows [" + std::to_string(begin) + ", " + std::to_string(end) +
                                             ") out of range: the experiment has " + std::to_string(exp.n()) +
                                             " rows");
  Experiment<T> out;
  out.source = exp.source;
  const Eigen::Index len = end - begin;
  out.u = exp.u.middleRows(begin, len);
  out.y = exp.y.middleRows(begin, len);
  out.rho = exp.rho.middleRows(begin, len);
  // The parts of the records inside the window stay records (one part: no
  // record list); a record keeps its own x0 only when the window starts at
  // its first row.
  const std::vector<Eigen::Index> lengths = exp.record_lengths();
  Eigen::Index first = 0;
  bool any_x0 = false;
  std::vector<Vec<T>> x0;
  for (size_t k = 0; k < lengths.size(); ++k) {
    const Eigen::Index b = std::max(first, begin), e = std::min(first + lengths[k], end);
    if (e > b) {
      out.records.push_back(e - b);
      const bool own = b == first && k < exp.record_x0.size() && exp.record_x0[k].size() != 0;
      x0.push_back(own ? exp.record_x0[k] : Vec<T>());
      any_x0 = any_x0 || own;
    }
    first += lengths[k];
  }
  if (any_x0) out.record_x0 = x0;
  if (out.records.size() <= 1) out.records.clear();
  return out;
}

TextTable select_table_rows(const TextTable& table, long begin, long end) {
  const auto n = static_cast<long>(table.rows.size());
  if (begin < 0 || end < begin || end > n)
    throw_input_error(table.file, 0, "", "rows [" + std::to_string(begin) + ", " + std::to_string(end) +
                                             ") out of range: the table has " + std::to_string(n) + " rows");
  TextTable out;
  out.file = table.file;
  out.header = table.header;
  out.rows.assign(table.rows.begin() + begin, table.rows.begin() + end);
  if (static_cast<long>(table.line_numbers.size()) >= end)
    out.line_numbers.assign(table.line_numbers.begin() + begin, table.line_numbers.begin() + end);
  return out;
}

template <typename T>
Experiment<T> stack_records(const std::vector<Experiment<T>>& parts) {
  if (parts.empty()) throw std::invalid_argument("stack_records: no records");
  Experiment<T> out;
  Eigen::Index n = 0;
  for (const Experiment<T>& p : parts) {
    if (p.nu() != parts[0].nu() || p.ny() != parts[0].ny() || p.n_rho() != parts[0].n_rho())
      throw_input_error(p.source, 0, "", "this record has " + std::to_string(p.nu()) + " inputs, " + std::to_string(p.ny()) +
                                             " outputs and " + std::to_string(p.n_rho()) + " scheduling columns; " +
                                             parts[0].source + " has " + std::to_string(parts[0].nu()) + ", " +
                                             std::to_string(parts[0].ny()) + " and " + std::to_string(parts[0].n_rho()));
    if (p.records.size() > 1) throw std::invalid_argument("stack_records: a part is itself stacked");
    n += p.n();
  }
  out.source = parts[0].source;
  out.u = Mat<T>(n, parts[0].nu());
  out.y = Mat<T>(n, parts[0].ny());
  out.rho = Mat<T>(n, parts[0].n_rho());
  Eigen::Index first = 0;
  for (const Experiment<T>& p : parts) {
    out.u.middleRows(first, p.n()) = p.u;
    out.y.middleRows(first, p.n()) = p.y;
    out.rho.middleRows(first, p.n()) = p.rho;
    out.records.push_back(p.n());
    if (first > 0) out.source += ", " + p.source;
    first += p.n();
  }
  if (out.records.size() == 1) out.records.clear();
  return out;
}

template Experiment<double> make_experiment<double>(const TextTable&, const ColumnMap&);
template Experiment<Rational> make_experiment<Rational>(const TextTable&, const ColumnMap&);
template Experiment<double> select_rows<double>(const Experiment<double>&, Eigen::Index, Eigen::Index);
template Experiment<Rational> select_rows<Rational>(const Experiment<Rational>&, Eigen::Index, Eigen::Index);
template Experiment<double> stack_records<double>(const std::vector<Experiment<double>>&);
template Experiment<Rational> stack_records<Rational>(const std::vector<Experiment<Rational>>&);

}  // namespace lpvid
