#include "core/file_io.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <mutex>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "core/input_error.h"
#include "core/limits.h"

namespace lpvid {
namespace {

std::mutex& outputs_mutex() {
  static std::mutex m;
  return m;
}
std::vector<std::string>& outputs() {
  static std::vector<std::string> v;
  return v;
}

std::string os_reason() { return std::strerror(errno); }

}  // namespace

std::string read_text_file(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    if (errno == ENOENT || errno == ENOTDIR) throw_input_error(path, 0, "", "cannot open: no such file");
    throw IoError(path + ": cannot open (" + os_reason() + ")");
  }
  if (S_ISDIR(st.st_mode)) throw_input_error(path, 0, "", "is a directory, not a file");
  if (!S_ISREG(st.st_mode))
    throw_input_error(path, 0, "", "is not a regular file (a device, FIFO or socket cannot be read as input)");
  const std::uintmax_t limit = input_limits().max_file_bytes;
  if (static_cast<std::uintmax_t>(st.st_size) > limit)
    throw_input_error(path, 0, "",
                      "file too large: " + std::to_string(st.st_size) + " bytes" +
                          limit_hint(static_cast<long double>(limit), "--max-file-mb"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open (" + os_reason() + ")");
  std::string text;
  text.resize(static_cast<size_t>(st.st_size));
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad() || static_cast<size_t>(in.gcount()) != text.size())
    throw IoError(path + ": read error (the file changed or could not be read)");
  return text;
}

void write_text_file(const std::string& path, const std::string& text, const std::string& what) {
  if (path.empty()) throw IoError("cannot write " + what + ": empty file name");
  // The temporary sits in the same directory so that rename() is atomic.
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw IoError("cannot write " + what + " '" + path + "' (" + os_reason() + ")");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) {
      const std::string reason = os_reason();
      std::remove(tmp.c_str());
      throw IoError("error while writing " + what + " '" + path + "' (" + reason + ")");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = os_reason();
    std::remove(tmp.c_str());
    throw IoError("cannot write " + what + " '" + path + "' (" + reason + ")");
  }
  std::lock_guard<std::mutex> lock(outputs_mutex());
  outputs().push_back(path);
}

int discard_outputs_of_this_run() {
  std::lock_guard<std::mutex> lock(outputs_mutex());
  int removed = 0;
  for (const std::string& p : outputs())
    if (std::remove(p.c_str()) == 0) ++removed;
  outputs().clear();
  return removed;
}

void keep_outputs_of_this_run() {
  std::lock_guard<std::mutex> lock(outputs_mutex());
  outputs().clear();
}

}  // namespace lpvid
