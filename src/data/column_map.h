#pragma once
/// Which data columns hold u, y and ρ (docs/design.md §11.1 `columns`), and the name
/// forms that are not data columns: a scheduling variable computed from the
/// model's own simulated state i (model/state_scheduling.h computes it):
///
///   "@x<i>"             x_i
///   "@abs(x<i>-c)"      |x_i − c|
///   "@sqrt(x<i>-c)"     √|x_i − c|
///   "@hinge(x<i>-c)"    max(x_i − c, 0)   (the excess above the level c)
///   "@sqrtpos(x<i>-c)"  √max(x_i − c, 0)  (an outflow that stops when the level falls to c)
///
/// i is 1-based without leading zeros; c is an exact decimal or p/q text
/// ("0.5", "1/3", "2.5e-3"); "x<i>+c" means the shift −c and "x<i>" alone the
/// shift 0.

#include <string>
#include <vector>

namespace lpvid {

struct ColumnMap {
  std::vector<std::string> u, y, rho;
};

/// The function of a state-scheduling column (see above).
enum class StateFunction { kState, kAbs, kSqrt, kHinge, kSqrtPos };

/// "x", "abs", "sqrt", "hinge".
const char* to_string(StateFunction f);

/// A scheduling column parsed: state < 0 for a data column.
struct StateColumn {
  int state = -1;                             ///< 0-based state index, -1: a data column
  StateFunction function = StateFunction::kState;
  std::string shift = "0";                    ///< c as exact number text, sign included ("x1+0.5": "-0.5")
};

/// Parses a scheduling column name. A name that does not start with '@' is a
/// data column (state = -1). Throws std::invalid_argument naming the column
/// for any other "@..." text (unknown function, bad state index, bad c).
StateColumn parse_state_column(const std::string& column);

/// 0-based state index named by a state-scheduling column (any of the forms
/// above), or -1 if the column does not start with '@' (a data column).
/// Throws std::invalid_argument for any other "@..." name.
int state_scheduling_index(const std::string& column);

}  // namespace lpvid
