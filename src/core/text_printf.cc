#include "core/text_printf.h"

#include <cstdarg>
#include <cstdio>
#include <vector>

namespace lpvid {

std::string text_vprintf(const char* format, std::va_list args) {
  std::va_list again;
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  std::vector<char> buf(static_cast<size_t>(n > 0 ? n : 0) + 1);
  std::vsnprintf(buf.data(), buf.size(), format, again);
  va_end(again);
  return std::string(buf.data());
}

std::string text_printf(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::string text = text_vprintf(format, args);
  va_end(args);
  return text;
}

}  // namespace lpvid
