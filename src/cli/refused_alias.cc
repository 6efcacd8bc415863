#include "cli/refused_alias.h"

namespace lpvid::cli {

namespace {

/// "lpvid jobs plan": the command path as typed.
std::string command_path(const CLI::App& cmd) {
  std::string path;
  for (const CLI::App* a = &cmd; a != nullptr; a = a->get_parent())
    path = a->get_parent() == nullptr ? "lpvid" + path : " " + a->get_name() + path;
  return path;
}

/// Throws the refusal as a parse error (run_lpvid: exit 2, usage message).
[[noreturn]] void refuse(const CLI::App& cmd, const std::string& text) {
  throw CLI::ValidationError(command_path(cmd) + ": " + text);
}

}  // namespace

void add_refused_option(CLI::App& cmd, const std::string& name, const std::string& reason) {
  const CLI::App* app = &cmd;
  const CLI::callback_t refuse_it = [app, name, reason](const CLI::results_t&) -> bool {
    refuse(*app, name + " " + reason);
  };
  cmd.add_option(name, refuse_it, "")
      ->expected(0, 1)
      ->group("");  // hidden: it does nothing but refuse
}

void add_renamed_option(CLI::App& cmd, const std::string& old_name, const std::string& new_name,
                        const std::string& why) {
  add_refused_option(cmd, old_name, "was renamed to " + new_name + " (" + why + ")");
}

void refuse_shared_option(CLI::App& cmd, const std::string& name, const std::string& reason) {
  cmd.remove_option(cmd.get_option(name));
  add_refused_option(cmd, name, reason);
}

}  // namespace lpvid::cli
