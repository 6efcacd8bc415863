#include "core/progress_sink.h"

#include "core/text_printf.h"

#include <cstdarg>
#include <cstdio>
#include <mutex>

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
  std::string line = text_vprintf(format, args);
  va_end(args);
  progress_line(line);
}

void set_progress_sink(std::function<void(const std::string&)> to) {
  Sink& s = sink();
  const std::lock_guard<std::mutex> lock(s.mutex);
  s.to = std::move(to);
}

}  // namespace lpvid
