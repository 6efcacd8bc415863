#include "verify/certificate/number_range.h"

#include <cfloat>
#include <cstdlib>

#include "core/input_error.h"
#include "core/number_text.h"

namespace lpvid {
namespace {

/// The digits of `s` from `pos` on; returns how many there were.
std::size_t digit_run(std::string_view s, std::size_t& pos) {
  const std::size_t start = pos;
  while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9') ++pos;
  return pos - start;
}

/// Significant digits of an unsigned digit run (leading zeros removed).
long significant(std::string_view digits) {
  const std::size_t first = digits.find_first_not_of('0');
  return first == std::string_view::npos ? 0 : static_cast<long>(digits.size() - first);
}

/// From the text alone: `order` with |x| < 10^order, or false when the text
/// is not a number. A decimal with a integer digits (leading zeros removed)
/// and exponent e is < 10^(a+e); p/q with a and b significant digits is
/// < 10^(a−b+1).
bool decimal_order(std::string_view s, long& order) {
  std::size_t pos = 0;
  if (pos < s.size() && (s[pos] == '+' || s[pos] == '-')) ++pos;
  const std::size_t int_start = pos;
  if (digit_run(s, pos) == 0) return false;
  const long a = significant(s.substr(int_start, pos - int_start));
  if (pos < s.size() && s[pos] == '/') {
    const std::size_t den_start = ++pos;
    if (digit_run(s, pos) == 0 || pos != s.size()) return false;
    order = a - significant(s.substr(den_start)) + 1;
    return true;
  }
  if (pos < s.size() && s[pos] == '.') {
    ++pos;
    digit_run(s, pos);
  }
  long e = 0;
  if (pos < s.size() && (s[pos] == 'e' || s[pos] == 'E')) {
    ++pos;
    const bool negative = pos < s.size() && s[pos] == '-';
    if (pos < s.size() && (s[pos] == '+' || s[pos] == '-')) ++pos;
    const std::size_t exp_start = pos;
    if (digit_run(s, pos) == 0) return false;
    const std::string_view exp = s.substr(exp_start, pos - exp_start);
    // Saturate: any exponent beyond 10⁹ digits is decided by its sign.
    e = significant(exp) > 9 ? 1000000000L : std::strtol(std::string(exp).c_str(), nullptr, 10);
    if (negative) e = -e;
  }
  if (pos != s.size()) return false;
  order = a + e;
  return true;
}

/// The fields whose strings are names or free text, not numbers.
bool is_text_field(const std::string& path) {
  return path == "info" || path == "data" || path == "model.columns" || path == "format";
}

void walk(const JsonNode& n, const std::string& path, const std::string& file) {
  if (is_text_field(path)) return;
  if ((n.is_number() || n.is_string()) && number_text_overflows_double(n.text))
    throw_input_error(file, n.line, path,
                      "the number " + n.text.substr(0, 40) + (n.text.size() > 40 ? "..." : "") +
                          " is beyond the range of a double (|x| > 1.8e308): no certificate needs it");
  for (std::size_t i = 0; i < n.items.size(); ++i) walk(n.items[i], path + "[" + std::to_string(i) + "]", file);
  for (const auto& [key, value] : n.members) walk(value, path.empty() ? key : path + "." + key, file);
}

}  // namespace

bool number_text_overflows_double(std::string_view text) {
  long order = 0;
  if (!decimal_order(text, order)) return false;
  if (order <= 308) return false;  // |x| < 10^308 < DBL_MAX
  // Exactly, within the digit limit (a text beyond it is its reader's error, named as such).
  try {
    const Rational q = rational_from_text(text);
    return q > Rational(DBL_MAX) || q < Rational(-DBL_MAX);
  } catch (const InputError&) {
    return false;  // not a number after all: its reader reports it
  }
}

void require_double_range(const JsonNode& root, const std::string& file) { walk(root, "", file); }

}  // namespace lpvid
