#include "verify/psd/rational_matrix_io.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"

namespace lpvid {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

[[noreturn]] void fail(const std::string& name, long line, long column, const std::string& reason) {
  std::string where = name.empty() ? std::string("<input>") : name;
  if (line > 0) where += ":" + std::to_string(line);
  if (column > 0) where += ":" + std::to_string(column);
  throw InputError(where + ": " + reason);
}

/// Names NaN / infinity explicitly (the generic message would say "not a number").
bool looks_like_nan_or_inf(std::string_view t) {
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.remove_prefix(1);
  std::string lower;
  for (char c : t) lower += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return lower == "nan" || lower == "inf" || lower == "infinity";
}

}  // namespace

Mat<Rational> read_rational_matrix(std::istream& in, const std::string& name) {
  std::vector<Rational> entries;
  long cols = -1, rows = 0, first_row_line = 0, last_row_line = 0;
  std::string text;
  long line_no = 0;
  while (std::getline(in, text)) {
    ++line_no;
    std::string_view line(text);
    if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    long count = 0;
    size_t pos = 0;
    while (pos < line.size()) {
      while (pos < line.size() && is_blank(line[pos])) ++pos;
      if (pos >= line.size()) break;
      size_t end = pos;
      while (end < line.size() && !is_blank(line[end])) ++end;
      std::string_view token = line.substr(pos, end - pos);
      const long column = static_cast<long>(pos) + 1;
      if (looks_like_nan_or_inf(token))
        fail(name, line_no, column, "'" + std::string(token) + "': NaN and infinity are not allowed");
      if (auto problem = number_text_problem(token)) fail(name, line_no, column, *problem);
      entries.push_back(rational_from_text(token));
      ++count;
      pos = end;
    }
    if (count == 0) continue;  // blank or comment line
    if (cols < 0) {
      cols = count;
      first_row_line = line_no;
    } else if (count != cols) {
      fail(name, line_no, 0,
           "ragged row: " + std::to_string(count) + " entries, but the first row (line " +
               std::to_string(first_row_line) + ") has " + std::to_string(cols));
    }
    ++rows;
    last_row_line = line_no;
  }
  if (in.bad()) fail(name, line_no, 0, "read error");
  if (rows == 0) fail(name, 0, 0, "no matrix rows (empty file or only comments)");
  if (rows != cols)
    fail(name, last_row_line, 0,
         "matrix is not square: " + std::to_string(rows) + " rows of " + std::to_string(cols) + " entries");
  Mat<Rational> M(rows, cols);
  size_t k = 0;
  for (long i = 0; i < rows; ++i)
    for (long j = 0; j < cols; ++j) M(i, j) = entries[k++];
  return M;
}

Mat<Rational> read_rational_matrix_file(const std::string& path) {
  std::istringstream in(read_text_file(path));
  return read_rational_matrix(in, path);
}

void write_rational_matrix(std::ostream& out, const Mat<Rational>& M, const std::string& comment) {
  if (!comment.empty()) {
    std::istringstream lines(comment);
    std::string l;
    while (std::getline(lines, l)) out << "# " << l << "\n";
  }
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    for (Eigen::Index j = 0; j < M.cols(); ++j) {
      if (j) out << ' ';
      out << rational_to_text(M(i, j));
    }
    out << '\n';
  }
}

void write_rational_matrix_file(const std::string& path, const Mat<Rational>& M, const std::string& comment) {
  std::ostringstream out;
  write_rational_matrix(out, M, comment);
  write_text_file(path, out.str(), "matrix");
}

}  // namespace lpvid
