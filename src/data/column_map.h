#pragma once
/// Which data columns hold u, y and ρ (SPEC §8 `columns`), and the one name
/// form that is not a data column: "@x<i>", a scheduling variable that is the
/// model's own simulated state i (model/state_scheduling.h computes it).

#include <string>
#include <vector>

namespace lpvid {

struct ColumnMap {
  std::vector<std::string> u, y, rho;
};

/// 0-based state index named by a column "@x<i>", or -1 if the column does
/// not start with '@' (a data column). Throws std::invalid_argument for any
/// other "@..." name.
int state_scheduling_index(const std::string& column);

}  // namespace lpvid
