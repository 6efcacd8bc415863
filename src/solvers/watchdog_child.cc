#include "solvers/watchdog_child.h"

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/deadline.h"

namespace lpvid {

namespace {

/// The longest wait between two looks at the child: a requested stop kills
/// it within this time (the CPU budget is judged on CPU time, never on it).
constexpr double kStopPollSeconds = 0.2;

/// The child's CPU time (user + system, all threads) in seconds; NaN when it
/// cannot be read.
double cpu_seconds_of(const clockid_t* clock) {
  timespec ts{};
  if (clock == nullptr || clock_gettime(*clock, &ts) != 0) return std::numeric_limits<double>::quiet_NaN();
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The parent's side: what it has heard from the child, in CPU seconds.
struct Heartbeat {
  bool heard = false;
  double at_last = 0;   ///< the child's CPU time at its last output
  double costliest = 0;  ///< max(CPU time to the first output, the most between two outputs)

  double budget(const WatchdogOptions& o) const { return std::max(o.min_stall_cpu_seconds, o.stall_factor * costliest); }
  void output(double cpu) {
    if (!std::isfinite(cpu)) return;
    costliest = std::max(costliest, cpu - (heard ? at_last : 0.0));
    at_last = cpu;
    heard = true;
  }
};

/// How long poll() may wait: at most a second, less when the CPU budget or
/// the deadline is nearer (the child's CPU time grows at most as fast as the
/// wall clock per thread, so the budget left is a safe wait).
int poll_milliseconds(const Heartbeat& h, const WatchdogOptions& o, double cpu_now) {
  double wait = 1.0;
  if (h.heard && std::isfinite(cpu_now)) wait = std::min(wait, h.budget(o) - (cpu_now - h.at_last));
  wait = std::min(wait, seconds_to_deadline());
  // at most kStopPollSeconds: a requested stop (core/stop_request.h) is seen that soon
  return static_cast<int>(std::clamp(wait, 0.01, kStopPollSeconds) * 1000.0);
}

void run_child(const std::function<void(std::FILE* result)>& work, std::FILE* result, int fds[2], pid_t parent) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // the parent interrupted or timed out: no solver left running
  if (getppid() != parent) _exit(4);  // it ended before the line above
  close(fds[0]);
  dup2(fds[1], STDOUT_FILENO);
  close(fds[1]);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  work(result);
  std::fflush(result);
  std::fflush(stdout);
  _exit(0);
}

/// Reads the child's output until EOF, a spent CPU budget or the deadline.
void watch(pid_t pid, int fd, const WatchdogOptions& options, WatchdogOutcome& out) {
  clockid_t clock{};
  const clockid_t* cpu_clock = clock_getcpuclockid(pid, &clock) == 0 ? &clock : nullptr;
  Heartbeat beat;
  char buf[4096];
  for (;;) {
    pollfd pfd{fd, POLLIN, 0};
    const int ready = poll(&pfd, 1, poll_milliseconds(beat, options, cpu_seconds_of(cpu_clock)));
    if (ready < 0 && errno == EINTR) continue;
    const double cpu = cpu_seconds_of(cpu_clock);
    if (deadline_passed() || stop_requested()) {  // the caller's check_deadline throws TimedOut or Interrupted
      kill(pid, SIGKILL);
      out.timed_out = true;
      return;
    }
    if (ready == 0) {
      if (!beat.heard || !std::isfinite(cpu) || cpu - beat.at_last < beat.budget(options)) continue;
      kill(pid, SIGKILL);
      out.stalled = true;
      out.stall_cpu_seconds = cpu - beat.at_last;
      out.budget_cpu_seconds = beat.budget(options);
      return;
    }
    const ssize_t got = read(fd, buf, sizeof buf);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return;  // EOF: the child closed stdout (exited)
    if (options.echo) std::fwrite(buf, 1, static_cast<size_t>(got), stdout);
    beat.output(cpu);
  }
}

}  // namespace

WatchdogOutcome run_in_watched_child(const std::function<void(std::FILE* result)>& work, std::FILE* result,
                                     const WatchdogOptions& options) {
  WatchdogOutcome out;
  int fds[2];
  if (pipe(fds) != 0) {
    out.error = std::string("pipe failed: ") + std::strerror(errno);
    return out;
  }
  std::fflush(nullptr);  // nothing buffered may be written twice
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    out.error = std::string("fork failed: ") + std::strerror(errno);
    return out;
  }
  if (pid == 0) run_child(work, result, fds, parent);
  close(fds[1]);
  watch(pid, fds[0], options, out);
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (out.stalled || out.timed_out) return out;
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
