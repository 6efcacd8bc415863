#include "diagnose/record_windows.h"

#include <algorithm>

namespace lpvid {

std::pair<size_t, Eigen::Index> record_of_row(const std::vector<Eigen::Index>& records, Eigen::Index row) {
  Eigen::Index first = 0;
  for (size_t k = 0; k < records.size(); ++k) {
    if (row < first + records[k]) return {k, first};
    first += records[k];
  }
  return {records.empty() ? 0 : records.size() - 1, records.empty() ? 0 : first - records.back()};
}

std::vector<JointWindow> joint_windows(Eigen::Index n, const std::vector<Eigen::Index>& records,
                                       const std::vector<RowWindow>& given) {
  const std::vector<Eigen::Index> lengths = records.size() > 1 ? records : std::vector<Eigen::Index>{n};
  std::vector<JointWindow> out;
  if (!given.empty()) {
    for (const auto& [b, e] : given) {
      JointWindow w;
      Eigen::Index first = 0;
      for (const Eigen::Index len : lengths) {
        const Eigen::Index pb = std::max(b, first), pe = std::min(e, first + len);
        if (pe > pb) w.emplace_back(pb, pe);
        first += len;
      }
      if (w.empty()) w.emplace_back(b, e);  // outside the data: diagnose names it
      out.push_back(w);
    }
    return out;
  }
  Eigen::Index first = 0;
  for (const Eigen::Index len : lengths) {
    const std::vector<RowWindow> tiles = default_bound_windows(len);
    if (out.size() < tiles.size()) out.resize(tiles.size());
    for (size_t j = 0; j < tiles.size(); ++j) out[j].emplace_back(first + tiles[j].first, first + tiles[j].second);
    first += len;
  }
  return out;
}

}  // namespace lpvid
