#include "cli/compare_columns.h"

#include <algorithm>

#include "core/input_error.h"

namespace lpvid::cli {
namespace {

/// Index of the model's data-read scheduling columns (not "@..." forms).
std::vector<size_t> data_rho_columns(const std::vector<std::string>& rho) {
  std::vector<size_t> out;
  for (size_t j = 0; j < rho.size(); ++j)
    if (rho[j].empty() || rho[j][0] != '@') out.push_back(j);
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

void check_count(const char* option, size_t given, size_t expected, const std::string& what,
                 const std::string& model_path, const std::vector<std::string>& columns) {
  if (given != 0 && given != expected)
    throw InputError(std::string(option) + ": " + std::to_string(given) + " column(s) given, but " + model_path + " has " +
                     std::to_string(expected) + " " + what + " (" + (columns.empty() ? "none" : joined(columns)) +
                     "); name one data column per " + what.substr(0, what.size() - 1) + ", in the model's order");
}

}  // namespace

LpvModel<double> map_model_columns(const LpvModel<double>& model, const ColumnMappingArgs& a,
                                   const std::string& model_path) {
  const std::vector<size_t> data_rho = data_rho_columns(model.columns.rho);
  std::vector<std::string> data_rho_names;
  for (size_t j : data_rho) data_rho_names.push_back(model.columns.rho[j]);
  check_count("--u", a.u.size(), model.columns.u.size(), "input columns", model_path, model.columns.u);
  check_count("--y", a.y.size(), model.columns.y.size(), "output columns", model_path, model.columns.y);
  check_count("--rho", a.rho.size(), data_rho.size(), "scheduling data columns", model_path, data_rho_names);
  std::vector<std::pair<std::string, std::string>> renamed;  // (model column, data column)
  for (size_t i = 0; i < a.u.size(); ++i) renamed.emplace_back(model.columns.u[i], a.u[i]);
  for (size_t i = 0; i < a.y.size(); ++i) renamed.emplace_back(model.columns.y[i], a.y[i]);
  for (size_t i = 0; i < a.rho.size(); ++i) renamed.emplace_back(data_rho_names[i], a.rho[i]);
  const auto follow = [&](const std::string& c) {
    for (const auto& [from, to] : renamed)
      if (from == c) return to;
    return c;
  };
  LpvModel<double> m = model;
  if (!a.u.empty()) m.columns.u = a.u;
  if (!a.y.empty()) m.columns.y = a.y;
  if (!a.rho.empty())
    for (size_t i = 0; i < data_rho.size(); ++i) m.columns.rho[data_rho[i]] = a.rho[i];
  else
    for (size_t j : data_rho) m.columns.rho[j] = follow(model.columns.rho[j]);
  for (auto& [column, unit] : m.signal_info.units) column = follow(column);
  return m;
}

void check_mapped_columns(const ColumnMappingArgs& a, const std::vector<std::string>& header,
                          const std::string& data_path) {
  const auto check = [&](const char* option, const std::vector<std::string>& given) {
    for (const std::string& c : given)
      if (std::find(header.begin(), header.end(), c) == header.end())
        throw InputError(std::string(option) + ": column '" + c + "' is not in " + data_path + " (its columns: " +
                         joined(header) + ")");
  };
  check("--u", a.u);
  check("--y", a.y);
  check("--rho", a.rho);
}

}  // namespace lpvid::cli
