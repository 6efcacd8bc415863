#include "json/json_members.h"

#include "core/input_error.h"
#include "json/json_number.h"

namespace lpvid {

const JsonNode& member(const JsonNode& obj, const char* key, const std::string& file, const std::string& path) {
  const JsonNode* n = obj.find(key);
  if (!n) throw_input_error(file, obj.line, path.empty() ? key : path + "." + key, "missing");
  return *n;
}

std::string string_member(const JsonNode& obj, const char* key, const std::string& file, const std::string& path) {
  const JsonNode& n = member(obj, key, file, path);
  if (!n.is_string()) throw_input_error(file, n.line, path.empty() ? key : path + "." + key, "expected a string");
  return n.text;
}

long integer_member(const JsonNode& n, const std::string& file, const std::string& path) {
  if (!n.is_number() || n.text.find_first_not_of("0123456789") != std::string::npos || n.text.size() > 12)
    throw_input_error(file, n.line, path, "expected a non-negative integer");
  return std::stol(n.text);
}

Mat<Rational> matrix_member(const JsonNode& n, const std::string& file, const std::string& path, Eigen::Index cols) {
  if (!n.is_array()) throw_input_error(file, n.line, path, "expected a list of rows");
  Mat<Rational> m(static_cast<Eigen::Index>(n.items.size()), cols);
  for (size_t r = 0; r < n.items.size(); ++r) {
    const JsonNode& row = n.items[r];
    const std::string rp = path + "[" + std::to_string(r) + "]";
    if (!row.is_array() || static_cast<Eigen::Index>(row.items.size()) != cols)
      throw_input_error(file, row.line, rp, "expected a list of " + std::to_string(cols) + " numbers");
    for (size_t c = 0; c < row.items.size(); ++c)
      m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) =
          number_from_json<Rational>(row.items[c], file, rp + "[" + std::to_string(c) + "]");
  }
  return m;
}

nlohmann::ordered_json matrix_json(const Mat<Rational>& m) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(rational_to_json(m(r, c)));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace lpvid
