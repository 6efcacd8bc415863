#include "diagnose/bound_windows.h"

#include <algorithm>
#include <stdexcept>

namespace lpvid {

std::vector<RowWindow> tile_windows(Eigen::Index n, Eigen::Index length, Eigen::Index min_last) {
  if (length < 1) throw std::invalid_argument("tile_windows: length must be >= 1");
  std::vector<RowWindow> out;
  for (Eigen::Index b = 0; b < n; b += length) out.emplace_back(b, std::min(n, b + length));
  if (out.size() > 1 && out.back().second - out.back().first < min_last) {
    const Eigen::Index end = out.back().second;
    out.pop_back();
    out.back().second = end;
  }
  return out;
}

std::vector<RowWindow> default_bound_windows(Eigen::Index n) {
  return tile_windows(n, kDefaultWindowLength, kDefaultMinLastWindow);
}

}  // namespace lpvid
