#pragma once
/// The options of a CLI11 command line as data: for every command path
/// ("" the top level, "invalidate", "jobs plan", ...) the options it takes,
/// with their long names, whether they take a value, several values, are
/// required, and their help text. Read from the same App objects the
/// programs parse with, so that a caller (the Python module checking keyword
/// arguments) never keeps its own copy of the option lists.

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace lpvid {

struct OptionInfo {
  std::vector<std::string> names;  ///< long names without dashes ("out", "model-out"); a positional's name
  bool flag = false;               ///< takes no value
  bool multi = false;              ///< takes several values or may be given several times
  bool required = false;
  bool positional = false;         ///< given without a name ("lpvid-verify psd FILE")
  std::string help;
};

/// Command path → its options in the order they were added.
using OptionTable = std::map<std::string, std::vector<OptionInfo>>;

/// Adds the options of `app` under `path` and those of every subcommand
/// under "path name" (option groups are merged into their command). --help
/// and --version are left out: they are not options of a run.
void add_option_table(const CLI::App& app, const std::string& path, OptionTable& out);

}  // namespace lpvid
