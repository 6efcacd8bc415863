#include "core/stop_request.h"

#include <atomic>

namespace lpvid {

namespace {
std::atomic<bool> stop_flag{false};
}  // namespace

void request_stop() { stop_flag.store(true, std::memory_order_relaxed); }

void clear_stop() { stop_flag.store(false, std::memory_order_relaxed); }

bool stop_requested() { return stop_flag.load(std::memory_order_relaxed); }

void check_stop() {
  if (stop_requested()) throw Interrupted();
}

}  // namespace lpvid
