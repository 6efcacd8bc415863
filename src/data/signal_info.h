#pragma once
/// What the numbers of a record mean physically: the time between samples
/// and the unit of each column. Optional in the model file ("sample_time",
/// "units"); carried into plots (a time axis in seconds, units on the axes)
/// and reports. No bound of Theorem 2.1 or 3.1 depends on it.

#include <string>
#include <utility>
#include <vector>

namespace lpvid {

struct SignalInfo {
  /// Seconds between two samples; 0 when unknown (plots then count samples).
  double sample_time = 0.0;
  /// (column name, unit text) pairs, e.g. ("uEst", "V"), in file order.
  std::vector<std::pair<std::string, std::string>> units;

  bool empty() const { return sample_time == 0.0 && units.empty(); }
  /// The unit of a column, "" when none is given.
  std::string unit_of(const std::string& column) const {
    for (const auto& [name, unit] : units)
      if (name == column) return unit;
    return "";
  }
  /// "name [unit]", or the name alone without a unit.
  std::string label(const std::string& column) const {
    const std::string u = unit_of(column);
    return u.empty() ? column : column + " [" + u + "]";
  }
  /// The time of sample k (file row k of the record): k·T, or k without T.
  double time_of(double k) const { return sample_time > 0 ? k * sample_time : k; }
  /// The x-axis label of a plot over samples.
  std::string time_label() const { return sample_time > 0 ? "time [s]" : "sample"; }
};

}  // namespace lpvid
