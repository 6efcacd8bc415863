#pragma once
/// Running the outside implementation a case is judged on: a shell command
/// template with the placeholders {data}, {model}, {task}, {out} (and {dir},
/// the case folder) replaced by shell-quoted absolute paths, run by /bin/sh
/// in a session of its own with stdout and stderr to a log file, killed
/// (its whole process group) when it runs past its time limit. Its process
/// tree ends with it: lpvid is a child subreaper (process_tree.h), and once
/// the shell has ended every process of the command still running — a
/// background job, a detached one (setsid, a double fork) — is killed and
/// named in the result.

#include <map>
#include <string>
#include <vector>

namespace lpvid {

/// `text` as one word for /bin/sh: in single quotes, each ' written '\''.
std::string shell_quote(const std::string& text);

/// The template with every {name} of `values` replaced by shell_quote(value).
/// Throws InputError for an unknown {placeholder} (a typo would otherwise
/// reach the shell as text).
std::string substitute_placeholders(const std::string& command, const std::map<std::string, std::string>& values);

struct CommandRun {
  bool started = false;   ///< false: fork/exec failed (see error)
  bool timed_out = false;
  int exit_code = -1;     ///< the shell's exit code; 128 + signal when killed by a signal
  double seconds = 0;
  std::string error;
  /// The command's processes still running after its shell ended (or was
  /// killed at the time limit), each killed: "pid (name)".
  std::vector<std::string> survivors;
};

/// Runs `/bin/sh -c command`, waiting at most `timeout_seconds` (≤ 0: no
/// limit). stdout and stderr go to `log_path`. Makes this process a child
/// subreaper for the rest of its life; not started when the kernel refuses.
CommandRun run_shell_command(const std::string& command, double timeout_seconds, const std::string& log_path);

}  // namespace lpvid
