#pragma once
/// printf-style formatting into a std::string, so that formatted tables go
/// through std::cout (which the Python module captures) like every other
/// line of a command's output, never around it.

#include <cstdarg>
#include <string>

namespace lpvid {

/// The text printf would print for `format` and its arguments.
[[gnu::format(printf, 1, 2)]] std::string text_printf(const char* format, ...);

/// The same with the arguments as a va_list (left unusable, as by vprintf).
[[gnu::format(printf, 1, 0)]] std::string text_vprintf(const char* format, std::va_list args);

}  // namespace lpvid
