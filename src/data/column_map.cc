#include "data/column_map.h"

#include <stdexcept>

#include "core/number_text.h"

namespace lpvid {

namespace {

/// The state index of "x<i>" (0-based), or -1 if `s` is not of that form.
int state_text_index(const std::string& s) {
  if (s.size() < 2 || s[0] != 'x') return -1;
  long i = 0;
  for (size_t p = 1; p < s.size(); ++p) {
    if (s[p] < '0' || s[p] > '9' || (p == 1 && s[p] == '0')) return -1;
    i = i * 10 + (s[p] - '0');
    if (i > 1000000) return -1;
  }
  return static_cast<int>(i - 1);
}

}  // namespace

const char* to_string(StateFunction f) {
  switch (f) {
    case StateFunction::kState: return "x";
    case StateFunction::kAbs: return "abs";
    case StateFunction::kSqrt: return "sqrt";
    case StateFunction::kHinge: return "hinge";
    case StateFunction::kSqrtPos: return "sqrtpos";
  }
  return "?";
}

StateColumn parse_state_column(const std::string& column) {
  StateColumn out;
  if (column.empty() || column[0] != '@') return out;
  const std::string bad = "scheduling column '" + column +
                          "': a '@' column must be '@x<i>', '@abs(x<i>-c)', '@sqrt(x<i>-c)', '@hinge(x<i>-c)' or '@sqrtpos(x<i>-c)' "
                          "(the model's state i, 1-based; c an exact decimal or p/q, '+c' or omitted allowed)";
  const std::string body = column.substr(1);
  if (body.empty() || body[0] == 'x') {  // "@x<i>"
    out.state = state_text_index(body);
    if (out.state < 0) throw std::invalid_argument(bad);
    return out;
  }
  const size_t open = body.find('(');
  if (open == std::string::npos || body.back() != ')') throw std::invalid_argument(bad);
  const std::string fn = body.substr(0, open), arg = body.substr(open + 1, body.size() - open - 2);
  if (fn == "abs") out.function = StateFunction::kAbs;
  else if (fn == "sqrt") out.function = StateFunction::kSqrt;
  else if (fn == "hinge") out.function = StateFunction::kHinge;
  else if (fn == "sqrtpos") out.function = StateFunction::kSqrtPos;
  else throw std::invalid_argument(bad + ": unknown function '" + fn + "'");
  const size_t op = arg.find_first_of("+-");
  out.state = state_text_index(arg.substr(0, op));
  if (out.state < 0) throw std::invalid_argument(bad + ": '" + arg.substr(0, op) + "' is not x<i>");
  if (op == std::string::npos) return out;
  const std::string c = arg.substr(op + 1);
  // c itself carries no sign: "x1--0.5" is refused
  if (c.empty() || !((c[0] >= '0' && c[0] <= '9') || c[0] == '.'))
    throw std::invalid_argument(bad + ": the shift '" + c + "' must be an unsigned decimal or p/q");
  if (const auto problem = number_text_problem(c))
    throw std::invalid_argument(bad + ": the shift '" + c + "' is not a number (" + *problem + ")");
  out.shift = arg[op] == '-' ? c : "-" + c;
  return out;
}

int state_scheduling_index(const std::string& column) { return parse_state_column(column).state; }

}  // namespace lpvid
