#include "core/progress_sink.h"

#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <vector>

namespace lpvid {

namespace {

struct Sink {
  std::mutex mutex;
  std::function<void(const std::string&)> to;
};

Sink& sink() {
  static Sink s;
  return s;
}

}  // namespace

void progress_line(const std::string& line) {
  Sink& s = sink();
  const std::lock_guard<std::mutex> lock(s.mutex);
  if (s.to) {
    s.to(line);
    return;
  }
  std::fprintf(stderr, "%s\n", line.c_str());
}

void progress_printf(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::vector<char> buf(static_cast<size_t>(n > 0 ? n : 0) + 1);
  std::vsnprintf(buf.data(), buf.size(), format, again);
  va_end(again);
  progress_line(std::string(buf.data()));
}

void set_progress_sink(std::function<void(const std::string&)> to) {
  Sink& s = sink();
  const std::lock_guard<std::mutex> lock(s.mutex);
  s.to = std::move(to);
}

}  // namespace lpvid
