#pragma once
/// "did you mean --x?" for a misspelt option: the unknown words of a command
/// line that failed to parse, each matched by edit distance against the
/// options its command takes (core/option_table.h), so that the list is the
/// one the program parses with.

#include <ostream>
#include <string>
#include <vector>

#include "core/option_table.h"

namespace lpvid {

/// The closest long option name (with "--") to `word` among `names`, when
/// it is within a small edit distance (at most 2, or a quarter of the longer
/// name); "" otherwise.
std::string closest_option(const std::string& word, const std::vector<std::string>& names);

/// For every word of `args` that looks like an option ("--name" or
/// "--name=value") and that neither the parsed command of `app` nor the top
/// level takes: prints "<program> <command>: unknown option --word; did you
/// mean --x?" to `err` when a close name exists. `root` is the table's path
/// of the top level ("" for lpvid, "lpvid-verify" for lpvid-verify).
/// Returns how many suggestions were printed.
int print_option_suggestions(const CLI::App& app, const OptionTable& table, const std::string& root,
                             const std::vector<std::string>& args, std::ostream& err);

}  // namespace lpvid
