#include "oracle/outside_command.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "core/input_error.h"
#include "oracle/process_tree.h"

namespace lpvid {

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string substitute_placeholders(const std::string& command, const std::map<std::string, std::string>& values) {
  std::string out;
  for (size_t i = 0; i < command.size(); ++i) {
    if (command[i] != '{') {
      out += command[i];
      continue;
    }
    const size_t close = command.find('}', i);
    const std::string name = close == std::string::npos ? "" : command.substr(i + 1, close - i - 1);
    const auto it = values.find(name);
    if (it == values.end()) {
      std::string known;
      for (const auto& [k, v] : values) known += (known.empty() ? "{" : ", {") + k + "}";
      throw InputError("--command: unknown placeholder '" + command.substr(i, close == std::string::npos ? 1 : close - i + 1) +
                       "' at character " + std::to_string(i) + " (known: " + known + ")");
    }
    out += shell_quote(it->second);
    i = close;
  }
  return out;
}

CommandRun run_shell_command(const std::string& command, double timeout_seconds, const std::string& log_path) {
  CommandRun run;
  const auto start = std::chrono::steady_clock::now();
  run.error = become_child_subreaper();
  if (!run.error.empty()) return run;
  const int log = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (log < 0) {
    run.error = "cannot write the log '" + log_path + "': " + std::strerror(errno);
    return run;
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    run.error = std::string("fork failed: ") + std::strerror(errno);
    ::close(log);
    return run;
  }
  if (pid == 0) {  // child: only async-signal-safe calls until exec
    ::setsid();  // a session of its own: its processes can never join lpvid's
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) ::dup2(null_in, STDIN_FILENO);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(log);
  run.started = true;
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) {
      run.error = std::string("waitpid failed: ") + std::strerror(errno);
      break;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (timeout_seconds > 0 && elapsed > timeout_seconds) {
      run.timed_out = true;
      ::kill(-pid, SIGKILL);  // its group (once the child has called setsid)
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  run.survivors = end_processes_of_other_sessions();  // whatever the command left running
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  else if (WIFSIGNALED(status)) run.exit_code = 128 + WTERMSIG(status);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace lpvid
