#pragma once
/// Exact matrix text files (docs/design.md §11.2, `lpvid-verify psd M.txt`).
///
/// Format: one matrix row per line; entries are exact decimals ("0.1",
/// "-2.5e-3") or fractions ("1/3"), separated by spaces and/or tabs. Blank
/// lines are ignored; a `#` starts a comment that runs to the end of the line
/// (whole-line comments and trailing comments). CRLF line ends are accepted.
/// Every row must have the same number of entries and the matrix must be
/// square. Numbers are read exactly (0.1 is 1/10), never through double.
///
/// Errors throw InputError naming "file:line:column: reason" (1-based line and
/// column), for: unreadable file, empty file (no rows), bad number text,
/// NaN/inf, zero denominator, ragged row, non-square matrix.

#include <iosfwd>
#include <string>

#include "core/scalar.h"

namespace lpvid {

/// Reads a square matrix from `in`; `name` is used in error messages.
Mat<Rational> read_rational_matrix(std::istream& in, const std::string& name);

/// Reads a square matrix from the file at `path`.
Mat<Rational> read_rational_matrix_file(const std::string& path);

/// Writes M in the same format: exact "p/q" (or "p") text, one row per line,
/// entries separated by one space, preceded by `# comment` lines if given.
void write_rational_matrix(std::ostream& out, const Mat<Rational>& M, const std::string& comment = "");

/// Writes M to the file at `path` (throws InputError if it cannot be written).
void write_rational_matrix_file(const std::string& path, const Mat<Rational>& M, const std::string& comment = "");

}  // namespace lpvid
