#pragma once
/// The command-line options that raise or lower core/limits.h's limits,
/// shared by `lpvid` and `lpvid-verify` (header-only: the executables link
/// CLI11, the libraries do not). Given before or after the subcommand.

#include <string>

#include <CLI/CLI.hpp>

#include "core/limits.h"

namespace lpvid {

inline void add_limit_options(CLI::App& app) {
  InputLimits& l = input_limits();
  const InputLimits d;
  app.add_option_function<double>(
         "--max-file-mb", [&l](double mb) { l.max_file_bytes = static_cast<std::uintmax_t>(mb * 1048576.0); },
         "largest input file read, MiB (default " + std::to_string(d.max_file_bytes >> 20) + ")")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-digits", l.max_number_digits,
                 "most decimal digits in one number of an input (default " + std::to_string(d.max_number_digits) + ")")
      ->check(CLI::Range(1L, 100000000L));
  app.add_option("--max-degree", l.max_degree,
                 "highest degree of a static polynomial map (default " + std::to_string(d.max_degree) + ")")
      ->check(CLI::Range(1, 100000));
  app.add_option("--max-samples", l.max_samples,
                 "most data rows / samples of an input (default " + std::to_string(d.max_samples) + ")")
      ->check(CLI::Range(1L, 1000000000L));
  app.fallthrough();
}

}  // namespace lpvid
