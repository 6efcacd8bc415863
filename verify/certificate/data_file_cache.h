#pragma once
/// The data files of one certificate check, each read, hashed and parsed
/// once whatever the number of records that name it (a certificate of many
/// records of one file would otherwise read and hash that file once per
/// record). Keyed by the path as resolved; the parse is kept per set of
/// column names (a headerless file may be named with different names).

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "data/experiment.h"

namespace lpvid {

class DataFileCache {
 public:
  /// The file's bytes as read once (throws InputError / IoError like read_text_file).
  struct File {
    std::string bytes;
    std::string sha256;
  };
  const File& file(const std::string& path);

  /// The table parsed from those bytes with `names` (empty: the file's header).
  const TextTable& table(const std::string& path, const std::vector<std::string>& names);

  /// Distinct files read so far.
  std::size_t files() const { return files_.size(); }

 private:
  std::map<std::string, File> files_;
  std::map<std::pair<std::string, std::vector<std::string>>, TextTable> tables_;
};

/// Data files read by every DataFileCache of this process so far (tests:
/// a file named by many records is read once per check).
std::size_t data_file_reads();

}  // namespace lpvid
