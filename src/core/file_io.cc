#include "core/file_io.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <thread>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "core/deadline.h"
#include "core/exit_codes.h"
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
/// Temporaries being written (removed on interrupt too).
std::vector<std::string>& in_flight() {
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
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid()) + "-" +
                          std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id()) % 100000);
  {
    std::lock_guard<std::mutex> lock(outputs_mutex());
    in_flight().push_back(tmp);
  }
  struct Forget {  // the temporary is renamed or removed below
    std::string name;
    ~Forget() {
      std::lock_guard<std::mutex> lock(outputs_mutex());
      auto& v = in_flight();
      for (size_t i = 0; i < v.size(); ++i)
        if (v[i] == name) {
          v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
          break;
        }
    }
  } forget{tmp};
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

namespace {

/// The directory a file path lives in ("." for a bare name).
std::filesystem::path directory_of(const std::string& path) {
  const std::filesystem::path p(path);
  return p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
}

void require_writable_directory(const std::filesystem::path& dir, const std::string& what, const std::string& path) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0)
    throw IoError("cannot write " + what + " '" + path + "': the directory '" + dir.string() + "' does not exist");
  if (!S_ISDIR(st.st_mode))
    throw IoError("cannot write " + what + " '" + path + "': '" + dir.string() + "' is not a directory");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw IoError("cannot write " + what + " '" + path + "': the directory '" + dir.string() + "' is not writable");
}

}  // namespace

void check_output_file(const std::string& path, const std::string& what) {
  if (path.empty()) return;
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
    throw IoError("cannot write " + what + " '" + path + "': it is a directory");
  require_writable_directory(directory_of(path), what, path);
}

void check_output_directory(const std::string& dir, const std::string& what) {
  if (dir.empty()) return;
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    require_writable_directory(dir, what, dir);
    return;
  }
  std::filesystem::path p(dir);
  while (p.has_relative_path() && p.filename().empty()) p = p.parent_path();  // "plots/" -> "plots"
  require_writable_directory(p.has_parent_path() ? p.parent_path() : std::filesystem::path("."), what, dir);
}

namespace {
int interrupt_pipe[2] = {-1, -1};

/// Removes every output this run wrote (and a temporary being written),
/// says `what` and so on stderr, and ends the process with `code`.
[[noreturn]] void end_run_now(const char* program, const std::string& what, int code) {
  int removed = 0;
  {
    std::lock_guard<std::mutex> lock(outputs_mutex());
    for (const std::string& p : outputs())
      if (std::remove(p.c_str()) == 0) ++removed;
    for (const std::string& p : in_flight()) std::remove(p.c_str());
  }
  std::cerr << "\n" << program << ": " << what << "; removed the " << removed << " file(s) this run had written\n"
            << std::flush;
  std::_Exit(code);
}

extern "C" void on_interrupt(int sig) {
  const unsigned char byte = static_cast<unsigned char>(sig);
  [[maybe_unused]] const ssize_t w = ::write(interrupt_pipe[1], &byte, 1);  // async-signal-safe
}
}  // namespace

void remove_outputs_on_interrupt(const char* program) {
  // A self-pipe, not a blocked mask: children (gnuplot, csdp) start with the
  // default disposition and stop on Ctrl-C like the rest of the process group.
  if (interrupt_pipe[0] >= 0 || ::pipe(interrupt_pipe) != 0) return;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &sa, nullptr);
  std::thread([program]() {
    unsigned char sig = 0;
    while (::read(interrupt_pipe[0], &sig, 1) != 1)
      if (errno != EINTR) return;
    end_run_now(program, "interrupted (signal " + std::to_string(static_cast<int>(sig)) + ")", kExitInterrupted);
  }).detach();
}

void end_run_after_deadline(const char* program) {
  std::thread([program]() {
    for (;;) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      const double timeout = deadline_timeout_seconds();
      if (timeout > 0 && seconds_to_deadline() < -(kDeadlineGraceSeconds + kDeadlineGraceShare * timeout))
        end_run_now(program, timed_out_message() + " (a step without a check ran past it)", kExitTimedOut);
    }
  }).detach();
}

}  // namespace lpvid
