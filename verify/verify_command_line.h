#pragma once
/// The whole `lpvid-verify` command line as a function, so that it runs in
/// another process's code too (the Python module runs it in-process).

#include <string>
#include <vector>

#include "core/option_table.h"

namespace lpvid {

/// Runs `program args...` as the `lpvid-verify` executable would and
/// returns its exit code (docs/exit_codes.md). `args` excludes the program
/// name; `program` is the name shown in usage and help text. Every call
/// starts from the default input limits. Not reentrant: the limits are per
/// process. A check stopped from another thread (core/stop_request.h) ends
/// with exit 130 (kExitInterrupted), nothing decided.
int run_lpvid_verify(const std::vector<std::string>& args, const std::string& program = "lpvid-verify");

/// The options run_lpvid_verify accepts, read from the app it parses with:
/// "lpvid-verify" the top-level options (limits), "lpvid-verify psd" and
/// "lpvid-verify certificate" those of the subcommands.
OptionTable lpvid_verify_option_table();

}  // namespace lpvid
