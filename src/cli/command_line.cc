#include "cli/command_line.h"

#include <iostream>
#include <new>
#include <stdexcept>

#include "cli/commands.h"
#include "cli/report.h"
#include "core/argv_words.h"
#include "core/deadline.h"
#include "core/eigen_blocking.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/limit_options.h"
#include "core/option_suggestion.h"

namespace lpvid::cli {

namespace {

/// The whole command line: the app with every subcommand and the top-level
/// options, and one runner per subcommand (the one parsed runs). Built in
/// place: the options hold pointers to its members.
struct LpvidCommandLine {
  CLI::App app{"lpvid: robust LPV identification/invalidation with exactly verified bounds"};
  std::vector<Runner> runners;
  double timeout = 0;

  LpvidCommandLine() {
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("lpvid ") + LPVID_VERSION);
    lpvid::add_limit_options(app);
    app.add_option("--timeout", timeout,
                   "stop after SECONDS of wall-clock time: the run ends 'timed out' (exit 124) and removes its outputs "
                   "(default: none; nothing else depends on the wall clock, so a loaded machine only takes longer)")
        ->check(CLI::PositiveNumber);
    runners = {add_invalidate_command(app), add_identify_command(app), add_simulate_command(app),
               add_generate_command(app)};
    runners.push_back(add_select_basis_command(app));
    runners.push_back(add_tradeoff_command(app));
    runners.push_back(add_diagnose_command(app));
    runners.push_back(add_fit_linear_command(app));
    runners.push_back(add_certify_command(app));
    runners.push_back(add_jobs_command(app));
    runners.push_back(add_compare_command(app));
    runners.push_back(add_oracle_command(app));
  }
  LpvidCommandLine(const LpvidCommandLine&) = delete;
  LpvidCommandLine& operator=(const LpvidCommandLine&) = delete;
};

}  // namespace

OptionTable lpvid_option_table() {
  const LpvidCommandLine line;
  OptionTable table;
  add_option_table(line.app, "", table);
  return table;
}

int run_lpvid(const std::vector<std::string>& args, const std::string& program) {
  pin_eigen_blocking();  // before any job thread (core/eigen_blocking.h)
  // A previous call in the same process may have changed the limits or left
  // its outputs recorded; this call must neither inherit the one nor delete
  // the other when it fails.
  lpvid::input_limits() = lpvid::InputLimits{};
  lpvid::keep_outputs_of_this_run();

  LpvidCommandLine line;
  CLI::App& app = line.app;
  ArgvWords argv(program, args);  // parsed as main()'s argv is
  try {
    app.parse(argv.argc(), argv.argv());
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr)  // a misspelt option: "did you mean --x?"
      print_option_suggestions(app, lpvid_option_table(), "", args, std::cerr);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  lpvid::set_deadline(line.timeout);  // 0: none
  struct ClearDeadline {
    ~ClearDeadline() { lpvid::clear_deadline(); }  // in-process callers (the Python module) run again without it
  } clear_at_return;
  // A command that fails with an exception leaves none of its outputs behind
  // (a certificate without its report would look like a finished run).
  const auto fail = [](const std::string& message, int code) {
    std::cerr << "lpvid: " << message << "\n";
    if (const int n = lpvid::discard_outputs_of_this_run(); n > 0)
      std::cerr << "lpvid: removed the " << n << " file(s) this run had written\n";
    return code;
  };
  try {
    for (auto& run : line.runners) {
      const int code = run();
      if (code >= 0) return code;
    }
  } catch (const lpvid::Interrupted& e) {
    return fail(e.what(), kExitInterrupted);  // a requested stop (core/stop_request.h)
  } catch (const lpvid::TimedOut& e) {
    return fail(e.what(), kExitTimedOut);
  } catch (const lpvid::InputError& e) {
    return fail(e.what(), kExitBadInput);
  } catch (const lpvid::IoError& e) {
    return fail(e.what(), kExitIo);
  } catch (const std::invalid_argument& e) {
    return fail(e.what(), kExitBadInput);
  } catch (const std::bad_alloc&) {
    return fail("out of memory", kExitSolver);
  } catch (const std::exception& e) {
    return fail(e.what(), kExitSolver);
  }
  std::cerr << "lpvid: no command\n";
  return kExitBadInput;
}

}  // namespace lpvid::cli
