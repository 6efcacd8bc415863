#pragma once
/// The whole `lpvid` command line as a function, so that it runs in another
/// process's code too (the Python module runs it in-process): parse the
/// options, run the one subcommand given, map an exception to its exit code
/// (docs/exit_codes.md) and remove the outputs of a run that failed. A run
/// stopped from another thread (core/stop_request.h) ends with exit 130 and
/// its outputs removed, like Ctrl-C of the program.

#include <string>
#include <vector>

#include "core/option_table.h"

namespace lpvid::cli {

/// Runs `program args...` as the `lpvid` executable would and returns its
/// exit code. `args` excludes the program name; `program` is the name shown
/// in usage and help text. Messages go to std::cout / std::cerr. Every call
/// starts from the default input limits and from no recorded outputs, so
/// that a failing call removes only what it wrote itself. Not reentrant:
/// the limits and the record of outputs are per process.
int run_lpvid(const std::vector<std::string>& args, const std::string& program = "lpvid");

/// The options run_lpvid accepts, read from the app it parses with: "" the
/// top-level options (--timeout, the input limits), then one entry per
/// command path ("invalidate", "jobs plan", ...).
OptionTable lpvid_option_table();

}  // namespace lpvid::cli
