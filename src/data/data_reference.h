#pragma once
/// Where an experiment's rows came from, made where the data is read: the
/// file as it was opened, the sha256 of the very bytes that were parsed, the
/// column names of a headerless file and the window of rows. Certificates
/// carry it (docs/design.md §10.1) so that the verifier re-reads the same rows;
/// nothing that computes a number looks at it.

#include <optional>
#include <string>
#include <vector>

#include "data/experiment.h"

namespace lpvid {

struct DataReference {
  std::string file;                  ///< the path as opened (relative to the working directory, or absolute)
  std::string sha256;                ///< of the file's bytes; empty: data without a file (made in memory)
  std::vector<std::string> names;    ///< headerless files only
  long row_begin = 0, row_end = -1;  ///< the window [begin, end) of the file's rows; end = -1: to the last row

  bool has_file() const { return !sha256.empty(); }
  /// The rows [begin, end) of THIS window, as a window of the file.
  DataReference rows(long begin, long end) const;
};

/// A table read from a file together with its reference (whole file).
struct DataTable {
  TextTable table;
  DataReference reference;
};

/// Reads `path` once: parse_table on its bytes (csv_reader.h: header or
/// `names`) and the sha256 of the same bytes. Throws InputError like read_table.
DataTable read_data_table(const std::string& path, const std::optional<std::vector<std::string>>& names = std::nullopt);

/// The same for bytes already in memory that stand for the file `path`: the
/// table is parsed from `bytes` and the sha256 is theirs, whatever the file
/// holds now (the file is not opened).
DataTable parse_data_table(const std::string& bytes, const std::string& path,
                           const std::optional<std::vector<std::string>>& names = std::nullopt);

}  // namespace lpvid
