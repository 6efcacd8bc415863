#include "verify/psd/check_progress.h"

#include <mutex>

#include "core/progress_sink.h"
#include "core/stopwatch.h"

namespace lpvid {
namespace {

struct CheckClock {
  std::mutex mutex;
  Stopwatch since_start;
  double last_line = 0;  ///< seconds since the start at the last line
  bool talking = false;
};

CheckClock& check_clock() {
  static CheckClock clock;
  return clock;
}

constexpr double kQuietSeconds = 5;

}  // namespace

void start_check_progress(bool talking) {
  CheckClock& c = check_clock();
  const std::lock_guard<std::mutex> lock(c.mutex);
  c.since_start.restart();
  c.last_line = 0;
  c.talking = talking;
}

void check_progress(double step_work, const std::string& stage) {
  CheckClock& c = check_clock();
  const std::lock_guard<std::mutex> lock(c.mutex);
  if (!c.talking) return;
  const double now = c.since_start.seconds();
  if (step_work < kAnnouncedWork && now - c.last_line < kQuietSeconds) return;
  c.last_line = now;
  progress_printf("[lpvid-verify %7.1f s] %s", now, stage.c_str());
}

}  // namespace lpvid
