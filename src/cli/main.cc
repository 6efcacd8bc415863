// lpvid: robust identification and invalidation of LPV systems (SPEC §8).
#include <iostream>
#include <vector>

#include "cli/commands.h"
#include "cli/report.h"
#include "core/input_error.h"

int main(int argc, char** argv) {
  using namespace lpvid::cli;
  CLI::App app{"lpvid: robust LPV identification/invalidation with exactly verified bounds"};
  app.require_subcommand(1);
  std::vector<Runner> runners = {add_invalidate_command(app), add_identify_command(app), add_simulate_command(app),
                                 add_generate_command(app)};
  runners.push_back(add_select_basis_command(app));
  runners.push_back(add_tradeoff_command(app));
  runners.push_back(add_diagnose_command(app));
  runners.push_back(add_fit_linear_command(app));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  try {
    for (auto& run : runners) {
      const int code = run();
      if (code >= 0) return code;
    }
  } catch (const lpvid::InputError& e) {
    std::cerr << "lpvid: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::invalid_argument& e) {
    std::cerr << "lpvid: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "lpvid: out of memory\n";
    return kExitSolver;
  } catch (const std::exception& e) {
    std::cerr << "lpvid: " << e.what() << "\n";
    return kExitSolver;
  }
  std::cerr << "lpvid: no command\n";
  return kExitBadInput;
}
