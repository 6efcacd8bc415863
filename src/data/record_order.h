#pragma once
/// The canonical order of several records of one plant: the records sorted
/// by a key made of their samples at the fits' precision
/// (data/fitting_precision.h), so that neither the order the user lists them
/// in nor a one-ulp change of a file changes which record comes first.
/// `lpvid fit-linear` keys an experiment's records by (length, samples);
/// `lpvid diagnose` keys its --data files by (length and samples, rows, path).

#include <algorithm>
#include <cstddef>
#include <vector>

namespace lpvid {

/// order[i] is the index of the record placed i-th: the records sorted by
/// `keys` (operator<), equal keys in the order given.
template <typename Key>
std::vector<size_t> canonical_record_order(const std::vector<Key>& keys) {
  std::vector<size_t> order(keys.size());
  for (size_t r = 0; r < order.size(); ++r) order[r] = r;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  return order;
}

}  // namespace lpvid
