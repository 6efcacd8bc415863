#pragma once
/// Errors for bad input (docs/design.md §13.2, §13.6): every message names the file, the
/// line (1-based) and/or the field, and the reason.

#include <stdexcept>
#include <string>
#include <string_view>

namespace lpvid {

/// Thrown for malformed or inconsistent input files and options.
/// The CLI prints what() and exits with a non-zero code.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// "file:line: field: reason" (parts that are empty/0 are left out).
std::string input_location(const std::string& file, long line, const std::string& field);

/// "rows x cols", the shape of a matrix in a message.
inline std::string shape_text(long long rows, long long cols) {
  return std::to_string(rows) + "x" + std::to_string(cols);
}

/// Up to `max_chars` of the text an input holds, safe to print in a message:
/// control bytes as \xNN, "..." when cut.
std::string printable_excerpt(std::string_view text, size_t max_chars);

[[noreturn]] void throw_input_error(const std::string& file, long line, const std::string& field,
                                    const std::string& reason);

}  // namespace lpvid
