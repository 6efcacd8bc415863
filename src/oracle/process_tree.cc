#include "oracle/process_tree.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace lpvid {
namespace {

struct ChildProcess {
  pid_t pid = 0;
  char state = 0;  ///< as /proc shows it: 'Z' (or 'X') has ended already
  std::string name;
};

/// The child of `self` outside `session` whose /proc/<pid>/stat line is
/// `line` ("pid (name) state ppid pgrp session ..."; the name may hold
/// spaces and parentheses, so the fields are read after its last ')').
bool child_of_other_session(const std::string& line, pid_t self, pid_t session, ChildProcess& out) {
  const size_t open = line.find('('), close = line.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return false;
  std::istringstream fields(line.substr(close + 1));
  char state = 0;
  long ppid = 0, group = 0, sid = 0;
  if (!(fields >> state >> ppid >> group >> sid) || ppid != self || sid == session) return false;
  out.pid = static_cast<pid_t>(std::stol(line.substr(0, open)));
  out.state = state;
  out.name = line.substr(open + 1, close - open - 1);
  return true;
}

/// This process's children outside its session, from /proc.
std::vector<ChildProcess> children_of_other_sessions() {
  const pid_t self = ::getpid(), session = ::getsid(0);
  std::vector<ChildProcess> found;
  std::error_code ec;
  for (std::filesystem::directory_iterator it("/proc", ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream stat(it->path() / "stat");
    std::string line;
    ChildProcess c;
    if (std::getline(stat, line) && child_of_other_session(line, self, session, c)) found.push_back(c);
  }
  return found;
}

}  // namespace

std::string become_child_subreaper() {
  if (::prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0) return "";
  return std::string("cannot become a child subreaper: ") + std::strerror(errno);
}

std::vector<std::string> end_processes_of_other_sessions() {
  std::vector<std::string> killed;
  for (;;) {
    const std::vector<ChildProcess> found = children_of_other_sessions();
    if (found.empty()) return killed;
    for (const ChildProcess& c : found) {
      if (c.state == 'Z' || c.state == 'X') continue;
      killed.push_back(std::to_string(c.pid) + " (" + c.name + ")");
      ::kill(c.pid, SIGKILL);
    }
    for (const ChildProcess& c : found)
      while (::waitpid(c.pid, nullptr, 0) < 0 && errno == EINTR) {
      }
  }
}

}  // namespace lpvid
