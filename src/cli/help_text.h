#pragma once
/// Help texts that state an option's default from the value the option
/// starts with, so that the default is written once (where the library or
/// the command's arguments define it) and the help can never disagree.

#include <concepts>
#include <string>

#include "core/number_text.h"

namespace lpvid::cli {

/// `help` + " (default V)", V the shortest decimal text of `value`.
inline std::string with_default(const std::string& help, double value) {
  return help + " (default " + double_to_text(value) + ")";
}

/// `help` + " (default N)".
template <std::integral I>
std::string with_default(const std::string& help, I value) {
  return help + " (default " + std::to_string(value) + ")";
}

}  // namespace lpvid::cli
