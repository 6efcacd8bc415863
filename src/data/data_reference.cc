#include "data/data_reference.h"

#include "core/file_io.h"
#include "core/sha256.h"
#include "data/csv_reader.h"

namespace lpvid {

DataReference DataReference::rows(long begin, long end) const {
  DataReference r = *this;
  r.row_begin = row_begin + begin;
  r.row_end = row_begin + end;
  return r;
}

DataTable read_data_table(const std::string& path, const std::optional<std::vector<std::string>>& names) {
  return parse_data_table(read_text_file(path), path, names);
}

DataTable parse_data_table(const std::string& bytes, const std::string& path,
                           const std::optional<std::vector<std::string>>& names) {
  DataTable out{parse_table(bytes, path, names), DataReference{}};
  out.reference.file = path;
  out.reference.sha256 = sha256_hex(bytes);
  if (names) out.reference.names = *names;
  return out;
}

}  // namespace lpvid
