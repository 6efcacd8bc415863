#include "diagnose/record_windows.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/input_error.h"

namespace lpvid {

std::pair<size_t, Eigen::Index> record_of_row(const std::vector<Eigen::Index>& lengths, Eigen::Index row) {
  if (lengths.empty()) throw std::invalid_argument("record_of_row: no record lengths");
  Eigen::Index first = 0;
  for (size_t k = 0; k + 1 < lengths.size(); ++k) {
    if (row < first + lengths[k]) return {k, first};
    first += lengths[k];
  }
  return {lengths.size() - 1, first};
}

DataReference piece_reference(const std::vector<DataReference>& references, const std::vector<Eigen::Index>& lengths,
                              const RowWindow& piece) {
  const auto [b, e] = piece;
  const auto [k, first] = record_of_row(lengths, b);
  if (e > first + lengths[k])
    throw InputError("rows " + std::to_string(b) + ":" + std::to_string(e) + " cross the end of record " +
                     std::to_string(k + 1) + " (rows " + std::to_string(first) + ":" + std::to_string(first + lengths[k]) +
                     " of the stacked records)");
  if (references.empty()) {
    DataReference none;
    none.row_begin = static_cast<long>(b);
    none.row_end = static_cast<long>(e);
    return none;
  }
  if (references.size() != lengths.size())
    throw std::invalid_argument(std::to_string(references.size()) + " record references for " +
                                std::to_string(lengths.size()) + " records");
  return references[k].rows(static_cast<long>(b - first), static_cast<long>(e - first));
}

std::vector<JointWindow> joint_windows(const std::vector<Eigen::Index>& lengths, const std::vector<RowWindow>& given) {
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
