#pragma once
/// The lengths of several records (experiments) stacked row-wise in one
/// signal matrix: record k holds rows [start_k, start_k + n_k),
/// start_k = n_1 + … + n_{k−1} (toeplitz/record_segments.h computes on them).

#include <stdexcept>
#include <string>
#include <vector>

#include "core/scalar.h"

namespace lpvid {

/// n_1 … n_K (each ≥ 1); empty: one record of all rows.
using RecordLengths = std::vector<Eigen::Index>;

/// The lengths, {n} when `lengths` is empty; throws std::invalid_argument
/// when they do not add up to n or one is not positive.
inline RecordLengths record_lengths_of(const RecordLengths& lengths, Eigen::Index n) {
  if (lengths.empty()) return RecordLengths{n};
  Eigen::Index sum = 0;
  for (const Eigen::Index l : lengths) {
    if (l <= 0) throw std::invalid_argument("a record has " + std::to_string(l) + " rows (each record needs at least one)");
    sum += l;
  }
  if (sum != n)
    throw std::invalid_argument("the records' lengths add up to " + std::to_string(sum) + ", not the " + std::to_string(n) +
                                " stacked rows");
  return lengths;
}

/// True when `lengths` describes more than one record.
inline bool several_records(const RecordLengths& lengths) { return lengths.size() > 1; }

/// The first row of each record (K entries) and, last, the total.
inline std::vector<Eigen::Index> record_starts(const RecordLengths& lengths) {
  std::vector<Eigen::Index> s{0};
  for (const Eigen::Index l : lengths) s.push_back(s.back() + l);
  return s;
}

}  // namespace lpvid
