#include "solvers/watchdog_child.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace lpvid {

WatchdogOutcome run_in_watched_child(const std::function<void(std::FILE* result)>& work, std::FILE* result,
                                     const WatchdogOptions& options) {
  WatchdogOutcome out;
  int fds[2];
  if (pipe(fds) != 0) {
    out.error = std::string("pipe failed: ") + std::strerror(errno);
    return out;
  }
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    out.error = std::string("fork failed: ") + std::strerror(errno);
    return out;
  }
  if (pid == 0) {  // child
    close(fds[0]);
    dup2(fds[1], STDOUT_FILENO);
    close(fds[1]);
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    work(result);
    std::fflush(result);
    std::fflush(stdout);
    _exit(0);
  }
  close(fds[1]);
  using clock = std::chrono::steady_clock;
  const auto started = clock::now();
  auto last = started;
  bool heard = false;
  double longest = 0.0;      // longest silence between two outputs so far
  double first_delay = 0.0;  // setup + first iteration: the scale of one healthy step
  char buf[4096];
  for (;;) {
    const double limit = std::max(options.min_stall_seconds, options.stall_factor * std::max(longest, first_delay));
    const double waited = std::chrono::duration<double>(clock::now() - last).count();
    const int timeout_ms = heard ? static_cast<int>(std::max(1.0, (limit - waited) * 1000.0)) : -1;
    pollfd pfd{fds[0], POLLIN, 0};
    const int ready = poll(&pfd, 1, timeout_ms);
    if (ready < 0 && errno == EINTR) continue;
    const double silent = std::chrono::duration<double>(clock::now() - last).count();
    if (ready == 0) {
      if (silent < limit) continue;
      kill(pid, SIGKILL);
      out.stalled = true;
      out.stall_seconds = silent;
      break;
    }
    const ssize_t got = read(fds[0], buf, sizeof buf);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;  // EOF: the child closed stdout (exited)
    if (options.echo) std::fwrite(buf, 1, static_cast<size_t>(got), stdout);
    if (heard) longest = std::max(longest, silent);
    else first_delay = std::chrono::duration<double>(clock::now() - started).count();
    heard = true;
    last = clock::now();
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (out.stalled) return out;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    out.finished = true;
    std::fseek(result, 0, SEEK_SET);
  } else if (WIFEXITED(status)) {
    out.error = "the solver process exited with code " + std::to_string(WEXITSTATUS(status));
  } else {
    out.error = "the solver process was killed by signal " + std::to_string(WTERMSIG(status));
  }
  return out;
}

}  // namespace lpvid
