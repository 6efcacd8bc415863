/// parse_monomial (declared in model/monomial.h): basis-function text such as
/// `1`, `rho1`, `rho1*rho2`, `rho2^2`, `rho1^2*rho2` (docs/design.md §5, §11).
///
/// Grammar (spaces and tabs allowed around every token):
///   monomial := "1" | factor ("*" factor)*
///   factor   := name ["^" exponent]
///   exponent := decimal digits, value 1..kMaxMonomialPower
/// Choices:
///   - `^0` is rejected (write `1` for the constant): an exponent 0 is more
///     likely a typo than intent, and it would give two texts for one function.
///   - `1` is only accepted as the whole text, not as a factor (`1*rho1`).
///   - `**` (Python's power) is an empty factor; the message suggests `^`.
///   - Repeated names multiply (`rho1*rho1` = `rho1^2`); the total power of
///     each name is limited to kMaxMonomialPower as well.

#include <cstdio>
#include <string>

#include "core/input_error.h"
#include "model/monomial.h"

namespace lpvid {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

std::string quoted(std::string_view s) { return "'" + printable_excerpt(s, 60) + "'"; }

[[noreturn]] void fail(std::string_view text, const std::string& reason) {
  throw InputError("basis function " + quoted(text) + ": " + reason);
}

std::string known_names(const std::vector<std::string>& names) {
  if (names.empty()) return "the model has no scheduling variables";
  std::string out = "known: ";
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out;
}

}  // namespace

Monomial parse_monomial(std::string_view text, const std::vector<std::string>& names) {
  Monomial m = constant_monomial(names.size());
  const std::string_view whole = trim(text);
  if (whole.empty()) fail(text, "empty basis function (write `1` for the constant)");
  if (whole == "1") return m;

  size_t start = 0;
  while (true) {
    const size_t star = whole.find('*', start);
    const std::string_view factor =
        trim(whole.substr(start, star == std::string_view::npos ? std::string_view::npos : star - start));
    if (factor.empty()) {
      if (start == 0) fail(text, "empty factor before the first '*'");
      if (star == std::string_view::npos) fail(text, "empty factor after the last '*'");
      if (star == start) fail(text, "empty factor at '**' (use '^' for powers, e.g. rho1^2)");
      fail(text, "empty factor between two '*'");
    }
    const size_t caret = factor.find('^');
    const std::string_view name = trim(factor.substr(0, caret));
    int power = 1;
    if (caret != std::string_view::npos) {
      const std::string_view exp = trim(factor.substr(caret + 1));
      if (exp.empty()) fail(text, "missing exponent after '^' in " + quoted(factor));
      if (exp.find_first_not_of("0123456789") != std::string_view::npos)
        fail(text, "bad exponent " + quoted(exp) + " in " + quoted(factor) + " (expected an integer 1.." +
                       std::to_string(kMaxMonomialPower) + ")");
      long value = 0;
      for (char c : exp) {
        value = value * 10 + (c - '0');
        if (value > kMaxMonomialPower) break;
      }
      if (value == 0) fail(text, "exponent 0 in " + quoted(factor) + " (write `1` for the constant)");
      if (value > kMaxMonomialPower)
        fail(text, "exponent " + quoted(exp) + " in " + quoted(factor) + " is larger than " +
                       std::to_string(kMaxMonomialPower));
      power = static_cast<int>(value);
    }
    if (name.empty()) fail(text, "missing scheduling name before '^' in " + quoted(factor));
    if (name == "1") fail(text, "'1' is only allowed as the whole basis function, not as a factor");
    size_t k = 0;
    while (k < names.size() && names[k] != name) ++k;
    if (k == names.size()) fail(text, "unknown scheduling name " + quoted(name) + " (" + known_names(names) + ")");
    m.powers[k] += power;
    if (m.powers[k] > kMaxMonomialPower)
      fail(text, "total power of '" + names[k] + "' is larger than " + std::to_string(kMaxMonomialPower));
    if (star == std::string_view::npos) break;
    start = star + 1;
  }
  return m;
}

}  // namespace lpvid
