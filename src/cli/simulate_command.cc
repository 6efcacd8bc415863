// lpvid simulate: the model output along the data's u and rho, as CSV (docs/design.md §11.2).
#include <iostream>
#include <memory>

#include "core/file_io.h"
#include "cli/commands.h"
#include "core/input_error.h"
#include "data/csv_reader.h"
#include "data/csv_writer.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"
#include "model/simulate.h"

namespace lpvid::cli {
namespace {

struct SimulateArgs {
  std::string data, model, out;
  std::vector<std::string> names;
};

int run_simulate(const SimulateArgs& a) {
  check_output_file(a.out, "output");
  const LpvModel<double> model = read_model_file<double>(a.model);
  const TextTable table = a.names.empty() ? read_table(a.data) : read_table(a.data, a.names);
  // Simulation needs u and rho only; y columns are optional here.
  ColumnMap cols = model.columns;
  bool have_y = true;
  for (const auto& y : cols.y)
    if (!find_column(table, y)) have_y = false;
  if (!have_y) cols.y.clear();
  Experiment<double> exp = make_experiment<double>(table, cols);
  if (!have_y) exp.y = Mat<double>::Zero(exp.n(), model.ny);
  const Simulation<double> sim = simulate(model, exp);
  std::vector<TextColumn> out;
  for (int i = 0; i < model.ny; ++i) {
    out.push_back({model.columns.y[static_cast<size_t>(i)] + "_hat", column_text(sim.output, i)});
  }
  for (Eigen::Index j = 0; j < sim.z.cols(); ++j) out.push_back({"z" + std::to_string(j + 1), column_text(sim.z, j)});
  if (a.out.empty() || a.out == "-")
    std::cout << csv_text(out);
  else
    write_csv(a.out, out);
  return 0;
}

}  // namespace

Runner add_simulate_command(CLI::App& app) {
  auto a = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand("simulate", "Model output (y_hat + offset) and z along the data, as CSV");
  cmd->add_option("--data", a->data, "data file")->required();
  cmd->add_option("--model", a->model, "model file")->required();
  cmd->add_option("--names", a->names, "column names for a headerless data file")->delimiter(',');
  cmd->add_option("--out", a->out, "output CSV (default: standard output)");
  return [cmd, a] { return cmd->parsed() ? run_simulate(*a) : -1; };
}

}  // namespace lpvid::cli
