#include "data/csv_reader.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "core/deadline.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/limits.h"
#include "core/number_text.h"

namespace lpvid {
namespace {

/// Rows read between two looks at the --timeout and a requested stop.
constexpr long kRowsBetweenChecks = 4096;

bool is_blank_char(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && is_blank_char(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank_char(s.back())) s.remove_suffix(1);
  return s;
}

/// One physical line of the input, without its line end.
struct Line {
  std::string_view text;
  long number = 0;  // 1-based
};

/// Splits text into lines (LF or CRLF; a final line without LF counts),
/// dropping a leading UTF-8 byte order mark.
std::vector<Line> split_lines(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<Line> lines;
  long number = 1;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back({line, number});
    ++number;
    start = end + 1;
  }
  return lines;
}

bool is_blank_line(std::string_view line) { return trim_blanks(line).empty(); }

bool is_comment_line(std::string_view line) {
  std::string_view t = trim_blanks(line);
  return !t.empty() && (t.front() == '#' || t.front() == '%');
}

std::string show(std::string_view s) { return printable_excerpt(s, 40); }

/// Splits one CSV line into trimmed, unquoted cells.
std::vector<std::string> split_csv_line(const Line& line, const std::string& file) {
  std::string_view s = line.text;
  std::vector<std::string> cells;
  size_t i = 0;
  const size_t n = s.size();
  while (true) {
    while (i < n && is_blank_char(s[i])) ++i;
    std::string cell;
    const size_t cell_number = cells.size() + 1;
    if (i < n && s[i] == '"') {
      ++i;
      bool closed = false;
      while (i < n) {
        if (s[i] == '"') {
          if (i + 1 < n && s[i + 1] == '"') {
            cell += '"';
            i += 2;
          } else {
            ++i;
            closed = true;
            break;
          }
        } else {
          cell += s[i++];
        }
      }
      if (!closed)
        throw_input_error(file, line.number, "", "cell " + std::to_string(cell_number) +
                                                     ": unterminated quote (quoted cells cannot span lines)");
      while (i < n && is_blank_char(s[i])) ++i;
      if (i < n && s[i] != ',')
        throw_input_error(file, line.number, "", "cell " + std::to_string(cell_number) +
                                                     ": unexpected text after closing quote: '" +
                                                     show(s.substr(i)) + "'");
      cell = std::string(trim_blanks(cell));
    } else {
      size_t start = i;
      while (i < n && s[i] != ',') {
        if (s[i] == '"')
          throw_input_error(file, line.number, "", "cell " + std::to_string(cell_number) +
                                                       ": quote inside an unquoted cell: '" +
                                                       show(s.substr(start)) + "'");
        ++i;
      }
      cell = std::string(trim_blanks(s.substr(start, i - start)));
    }
    cells.push_back(std::move(cell));
    if (i >= n) break;
    ++i;  // the comma; if it was the last character, the loop adds an empty cell
  }
  return cells;
}

void drop_one_trailing_empty(std::vector<std::string>& cells, size_t expected) {
  if (cells.size() == expected + 1 && cells.back().empty()) cells.pop_back();
}

std::string list_names(const std::vector<std::string>& names) {
  std::string out;
  constexpr size_t kMax = 20;
  for (size_t i = 0; i < names.size() && i < kMax; ++i) {
    if (i) out += ", ";
    out += "'" + names[i] + "'";
  }
  if (names.size() > kMax) out += ", ... (" + std::to_string(names.size()) + " columns)";
  return out;
}

/// Checks column names: non-empty, unique.
void check_names(const std::vector<std::string>& names, const std::string& file, long line) {
  if (names.empty()) throw_input_error(file, line, "", "no column names");
  std::unordered_map<std::string, size_t> seen;
  for (size_t i = 0; i < names.size(); ++i) {
    if (names[i].empty()) throw_input_error(file, line, "", "column " + std::to_string(i + 1) + " has an empty name");
    auto [it, inserted] = seen.emplace(names[i], i);
    if (!inserted)
      throw_input_error(file, line, "", "duplicate column name '" + show(names[i]) + "' (columns " +
                                            std::to_string(it->second + 1) + " and " + std::to_string(i + 1) + ")");
  }
}

/// CSV data rows from lines[first..] against a known header.
TextTable csv_rows(const std::vector<Line>& lines, size_t first, std::vector<std::string> header,
                   const std::string& name, bool skip_comments) {
  TextTable table;
  table.file = name;
  table.header = std::move(header);
  const size_t width = table.header.size();
  for (size_t k = first; k < lines.size(); ++k) {
    if (static_cast<long>(k) % kRowsBetweenChecks == 0) check_deadline("a data file was read");  // a big file: --timeout or a stop
    if (is_blank_line(lines[k].text) || (skip_comments && is_comment_line(lines[k].text))) continue;
    std::vector<std::string> cells = split_csv_line(lines[k], name);
    drop_one_trailing_empty(cells, width);
    if (cells.size() != width)
      throw_input_error(name, lines[k].number, "",
                        "expected " + std::to_string(width) + " cells (" + list_names(table.header) + "), got " +
                            std::to_string(cells.size()));
    if (static_cast<long>(table.rows.size()) >= input_limits().max_samples)
      throw_input_error(name, lines[k].number, "",
                        "more than " + std::to_string(input_limits().max_samples) + " data rows" +
                            limit_hint(static_cast<long double>(input_limits().max_samples), "--max-samples"));
    table.rows.push_back(std::move(cells));
    table.line_numbers.push_back(lines[k].number);
  }
  return table;
}

/// Index of the first line that is neither blank nor (if `comments`) a comment.
size_t first_content_line(const std::vector<Line>& lines, bool comments) {
  size_t k = 0;
  while (k < lines.size() && (is_blank_line(lines[k].text) || (comments && is_comment_line(lines[k].text)))) ++k;
  return k;
}

std::vector<std::string_view> split_whitespace(std::string_view s) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_blank_char(s[i])) ++i;
    size_t start = i;
    while (i < s.size() && !is_blank_char(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

/// True if the line, split on commas and whitespace, is one or more numbers.
bool is_numeric_line(std::string_view s) {
  size_t count = 0, i = 0;
  while (i <= s.size()) {
    size_t end = i;
    while (end < s.size() && s[end] != ',' && !is_blank_char(s[end])) ++end;
    std::string_view token = s.substr(i, end - i);
    if (!token.empty()) {
      if (number_text_problem(token)) return false;
      ++count;
    }
    i = end + 1;
  }
  return count > 0;
}

TextTable parse_headerless_csv(std::string_view text, const std::string& name, const std::vector<std::string>& names) {
  check_names(names, name, 0);
  std::vector<Line> lines = split_lines(text);
  return csv_rows(lines, 0, names, name, true);
}

}  // namespace

TextTable parse_csv(std::string_view text, const std::string& name) {
  std::vector<Line> lines = split_lines(text);
  size_t h = first_content_line(lines, false);
  if (h == lines.size()) throw_input_error(name, 0, "", "no header row (the file is empty)");
  std::vector<std::string> header = split_csv_line(lines[h], name);
  if (header.size() > 1 && header.back().empty()) header.pop_back();
  check_names(header, name, lines[h].number);
  return csv_rows(lines, h + 1, std::move(header), name, false);
}

TextTable read_csv(const std::string& path) { return parse_csv(read_text_file(path), path); }

TextTable parse_whitespace_table(std::string_view text, const std::string& name,
                                 const std::vector<std::string>& names) {
  check_names(names, name, 0);
  TextTable table;
  table.file = name;
  table.header = names;
  for (const Line& line : split_lines(text)) {
    if (line.number % kRowsBetweenChecks == 0) check_deadline("a data file was read");
    if (is_blank_line(line.text) || is_comment_line(line.text)) continue;
    std::vector<std::string_view> cells = split_whitespace(line.text);
    if (cells.size() != names.size())
      throw_input_error(name, line.number, "",
                        "expected " + std::to_string(names.size()) + " whitespace-separated cells (" +
                            list_names(names) + "), got " + std::to_string(cells.size()));
    table.rows.emplace_back(cells.begin(), cells.end());
    table.line_numbers.push_back(line.number);
  }
  return table;
}

TextTable read_whitespace_table(const std::string& path, const std::vector<std::string>& names) {
  return parse_whitespace_table(read_text_file(path), path, names);
}

TextTable parse_table(std::string_view text, const std::string& name,
                      const std::optional<std::vector<std::string>>& names) {
  std::vector<Line> lines = split_lines(text);
  size_t k = first_content_line(lines, true);
  if (k < lines.size() && is_numeric_line(lines[k].text)) {
    if (!names)
      throw_input_error(name, lines[k].number, "",
                        "the first line looks like numbers, not a header of column names; "
                        "give the column names");
    if (lines[k].text.find(',') != std::string_view::npos) return parse_headerless_csv(text, name, *names);
    return parse_whitespace_table(text, name, *names);
  }
  return parse_csv(text, name);
}

TextTable read_table(const std::string& path, const std::optional<std::vector<std::string>>& names) {
  return parse_table(read_text_file(path), path, names);
}

std::optional<size_t> find_column(const TextTable& table, std::string_view column) {
  for (size_t i = 0; i < table.header.size(); ++i)
    if (table.header[i] == column) return i;
  return std::nullopt;
}

}  // namespace lpvid
