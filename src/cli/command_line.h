#pragma once
/// The whole `lpvid` command line as a function, so that it runs in another
/// process's code too (the Python module runs it in-process): parse the
/// options, run the one subcommand given, map an exception to its exit code
/// (README "Exit codes") and remove the outputs of a run that failed.

#include <string>
#include <vector>

namespace lpvid::cli {

/// Runs `program args...` as the `lpvid` executable would and returns its
/// exit code. `args` excludes the program name; `program` is the name shown
/// in usage and help text. Messages go to std::cout / std::cerr. Every call
/// starts from the default input limits and from no recorded outputs, so
/// that a failing call removes only what it wrote itself. Not reentrant:
/// the limits and the record of outputs are per process.
int run_lpvid(const std::vector<std::string>& args, const std::string& program = "lpvid");

}  // namespace lpvid::cli
