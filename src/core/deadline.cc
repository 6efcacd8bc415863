#include "core/deadline.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/number_text.h"

namespace lpvid {

namespace {

using Clock = std::chrono::steady_clock;

/// Deadline in steady_clock nanoseconds since its epoch; 0: none.
std::atomic<std::int64_t> deadline_ns{0};
std::atomic<double> deadline_timeout{0.0};

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

}  // namespace

void set_deadline(double seconds) {
  if (!(seconds > 0) || !std::isfinite(seconds)) {
    clear_deadline();
    return;
  }
  deadline_timeout = seconds;
  deadline_ns = now_ns() + static_cast<std::int64_t>(std::min(seconds, 1e9) * 1e9);
}

void clear_deadline() {
  deadline_ns = 0;
  deadline_timeout = 0.0;
}

double deadline_timeout_seconds() { return deadline_timeout; }

double seconds_to_deadline() {
  const std::int64_t d = deadline_ns;
  if (d == 0) return std::numeric_limits<double>::infinity();
  return static_cast<double>(d - now_ns()) * 1e-9;
}

bool deadline_passed() { return seconds_to_deadline() <= 0; }

std::string timed_out_message() {
  const std::string s = double_to_text(deadline_timeout_seconds());
  return "timed out after " + s + " s (--timeout " + s + ")";
}

void check_deadline(const char* stage) {
  check_stop();  // one atomic load: cheap enough for every step
  if (!deadline_passed()) return;
  throw TimedOut(timed_out_message() + (stage != nullptr ? std::string(" while ") + stage : std::string()));
}

}  // namespace lpvid
