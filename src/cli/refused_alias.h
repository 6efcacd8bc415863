#pragma once
/// Old option names kept for one release as refused aliases: a renamed or
/// removed option is still recognised, but giving it fails (exit 2) with a
/// message naming what to use instead, never silently doing something else.
/// The alias is hidden from --help and from the option table (it works for
/// nothing); see docs/cli.md "Renamed options".

#include <string>

#include <CLI/CLI.hpp>

namespace lpvid::cli {

/// `--old_name` on `cmd` fails with "lpvid <cmd>: --old was renamed to --new (why)".
/// It takes at most one value (a flag or an option of the old form both
/// reach the message).
void add_renamed_option(CLI::App& cmd, const std::string& old_name, const std::string& new_name,
                        const std::string& why);

/// `--name` on `cmd` fails with "lpvid <cmd>: --name <reason>": an option a
/// shared group defines but this command would ignore, or one that is gone.
void add_refused_option(CLI::App& cmd, const std::string& name, const std::string& reason);

/// Hides `--name` (defined by a shared option group) from `cmd`'s help and
/// option table and refuses it with `reason`: the command would ignore it.
void refuse_shared_option(CLI::App& cmd, const std::string& name, const std::string& reason);

}  // namespace lpvid::cli
