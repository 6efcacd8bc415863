#include "data/column_map.h"

#include <stdexcept>

namespace lpvid {

int state_scheduling_index(const std::string& column) {
  if (column.empty() || column[0] != '@') return -1;
  const std::string bad = "scheduling column '" + column + "': a '@' column must be '@x<i>' (the model's state i, 1-based)";
  if (column.size() < 3 || column[1] != 'x') throw std::invalid_argument(bad);
  long i = 0;
  for (size_t p = 2; p < column.size(); ++p) {
    if (column[p] < '0' || column[p] > '9' || (p == 2 && column[p] == '0')) throw std::invalid_argument(bad);
    i = i * 10 + (column[p] - '0');
    if (i > 1000000) throw std::invalid_argument(bad);
  }
  return static_cast<int>(i - 1);
}

}  // namespace lpvid
