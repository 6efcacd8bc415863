#pragma once
/// Reading data tables as text (docs/design.md §4, §11.3: "Data files are CSV with a
/// header; columns are found by name"). Cells stay text so that the double
/// path and the exact verifier each read the numbers in their own scalar
/// (see experiment_builder.h). Every error is an InputError naming the file
/// and the 1-based line.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "data/experiment.h"

namespace lpvid {

/// Parses CSV text. `name` is the file name used in messages.
///
/// - The first non-blank line is the header of column names; later lines are
///   data rows. Blank lines (only spaces/tabs/CR) are skipped anywhere.
/// - Cells are separated by commas; LF or CRLF line ends; a UTF-8 byte order
///   mark at the very start is ignored.
/// - A cell may be double-quoted ("uEst"); inside quotes a comma is text and
///   `""` is one quote. Quoted cells cannot span lines. Every cell (quoted
///   or not) is trimmed of spaces, tabs and CR. A `"` inside an unquoted
///   cell is an error.
/// - One trailing empty cell on any line (a trailing comma, as in the
///   Cascaded Tanks benchmark file) is dropped.
/// - Errors (InputError "file:line: reason"): no header, empty or duplicate
///   column name, a row whose cell count differs from the header's,
///   unterminated quote, text after a closing quote.
/// Cells are not checked as numbers here (an empty `Ts` cell is fine until a
/// model uses that column).
TextTable parse_csv(std::string_view text, const std::string& name);

/// Reads the whole file and calls parse_csv. Throws InputError if the file
/// cannot be opened.
TextTable read_csv(const std::string& path);

/// Parses a headerless table whose cells are separated by spaces and/or tabs
/// (e.g. the DaISy dryer.dat, columns `u y`). `names` gives the column names
/// (non-empty, unique). Blank lines and lines starting with `#` or `%` are
/// skipped. Every other line must have exactly names.size() cells.
TextTable parse_whitespace_table(std::string_view text, const std::string& name,
                                 const std::vector<std::string>& names);

/// Reads a file with parse_whitespace_table.
TextTable read_whitespace_table(const std::string& path, const std::vector<std::string>& names);

/// Reads a data file, choosing the format by this rule:
///
///   Look at the first line that is not blank (and not a `#`/`%` comment).
///   If every cell of it, split on commas and whitespace, is a number, the
///   file has no header:
///     - with `names` given: it is read headerless with those names, as CSV
///       if that line contains a comma, else as a whitespace table (both
///       skip blank lines and `#`/`%` comment lines);
///     - without `names`: InputError ("looks like numbers, not a header").
///   Otherwise the file is CSV with a header row, and `names`, if given, is
///   ignored (the header names the columns).
TextTable read_table(const std::string& path, const std::optional<std::vector<std::string>>& names = std::nullopt);

/// parse_* counterpart of read_table (same rule, text already in memory).
TextTable parse_table(std::string_view text, const std::string& name,
                      const std::optional<std::vector<std::string>>& names = std::nullopt);

/// Index of the column called `column`, or std::nullopt.
std::optional<size_t> find_column(const TextTable& table, std::string_view column);

}  // namespace lpvid
