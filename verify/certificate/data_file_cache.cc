#include "verify/certificate/data_file_cache.h"

#include <atomic>
#include <filesystem>
#include <optional>

#include "core/file_io.h"
#include "core/sha256.h"
#include "data/csv_reader.h"
#include "verify/certificate/work_budget.h"

namespace lpvid {
namespace {
std::atomic<std::size_t>& reads() {
  static std::atomic<std::size_t> count{0};
  return count;
}
}  // namespace

std::size_t data_file_reads() { return reads(); }

const DataFileCache::File& DataFileCache::file(const std::string& path) {
  if (const auto found = files_.find(path); found != files_.end()) return found->second;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec) charge_data_file(size, path);  // a missing file: read_text_file says so
  File f;
  f.bytes = read_text_file(path);
  f.sha256 = sha256_hex(f.bytes);
  ++reads();
  return files_.emplace(path, std::move(f)).first->second;
}

const TextTable& DataFileCache::table(const std::string& path, const std::vector<std::string>& names) {
  const auto key = std::make_pair(path, names);
  if (const auto found = tables_.find(key); found != tables_.end()) return found->second;
  const std::string& bytes = file(path).bytes;
  TextTable t = names.empty() ? parse_table(bytes, path) : parse_table(bytes, path, names);
  return tables_.emplace(key, std::move(t)).first->second;
}

}  // namespace lpvid
