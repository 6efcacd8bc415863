#pragma once
/// Wall-clock seconds since a start, for the timing fields of reports (never
/// for a decision: no answer may depend on the clock).

#include <chrono>

namespace lpvid {

class Stopwatch {
 public:
  /// Seconds since construction or the last restart().
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  void restart() { start_ = std::chrono::steady_clock::now(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace lpvid
