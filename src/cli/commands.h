#pragma once
/// The lpvid subcommands (docs/design.md §11.2). Each registers itself on the app and
/// returns a runner; main() dispatches to the one that was parsed.

#include <functional>

#include <CLI/CLI.hpp>

namespace lpvid::cli {

using Runner = std::function<int()>;

Runner add_identify_command(CLI::App& app);
Runner add_invalidate_command(CLI::App& app);
Runner add_simulate_command(CLI::App& app);
Runner add_generate_command(CLI::App& app);
Runner add_select_basis_command(CLI::App& app);
Runner add_tradeoff_command(CLI::App& app);
Runner add_diagnose_command(CLI::App& app);
Runner add_fit_linear_command(CLI::App& app);
Runner add_certify_command(CLI::App& app);
Runner add_jobs_command(CLI::App& app);
Runner add_compare_command(CLI::App& app);
Runner add_oracle_command(CLI::App& app);

}  // namespace lpvid::cli
