#include "diagnose/record_windows.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/input_error.h"

namespace lpvid {

std::pair<size_t, Eigen::Index> record_of_row(const std::vector<Eigen::Index>& records, Eigen::Index row) {
  Eigen::Index first = 0;
  for (size_t k = 0; k < records.size(); ++k) {
    if (row < first + records[k]) return {k, first};
    first += records[k];
  }
  return {records.empty() ? 0 : records.size() - 1, records.empty() ? 0 : first - records.back()};
}

DataReference piece_reference(const std::vector<DataReference>& references, const std::vector<Eigen::Index>& records,
                              const RowWindow& piece) {
  const auto [b, e] = piece;
  const auto [k, first] = record_of_row(records, b);
  if (!records.empty() && e > first + records[k])
    throw InputError("rows " + std::to_string(b) + ":" + std::to_string(e) + " cross the end of record " +
                     std::to_string(k + 1) + " (rows " + std::to_string(first) + ":" + std::to_string(first + records[k]) +
                     " of the stacked records)");
  if (references.empty()) {
    DataReference none;
    none.row_begin = static_cast<long>(b);
    none.row_end = static_cast<long>(e);
    return none;
  }
  if (references.size() != std::max<size_t>(1, records.size()))
    throw std::invalid_argument(std::to_string(references.size()) + " record references for " +
                                std::to_string(std::max<size_t>(1, records.size())) + " records");
  return references[k].rows(static_cast<long>(b - first), static_cast<long>(e - first));
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
