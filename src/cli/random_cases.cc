#include "cli/random_cases.h"

#include <filesystem>
#include <sstream>

#include "core/file_io.h"
#include "core/input_error.h"
#include "data/csv_writer.h"
#include "model/model_file.h"

namespace lpvid::cli {

void add_random_case_flags(CLI::App& cmd, RandomCaseFlags& f) {
  cmd.add_flag("--siso", f.siso, "random cases: one input and one output (default: 1-2 of each)");
  cmd.add_flag("--lti", f.lti, "random cases: every basis function constant (an LTI model)");
  cmd.add_option("--min-n", f.min_n, "random cases: fewest samples (20)");
  cmd.add_option("--max-n", f.max_n, "random cases: most samples (200)");
  cmd.add_option("--leading-zeros", f.leading_zeros,
                 "random cases: up to this many leading samples with every input 0, so z starts with zeros (0)");
  cmd.add_option("--max-delay", f.max_delay, "random cases: the generating Delta's first 0..K taps are zero (0)");
  cmd.add_flag("--static-blocks", f.static_blocks, "random cases: sometimes a known static input or output map");
  cmd.add_option("--kinds", f.kinds, "task kinds to draw from, comma separated: min_dmax, min_delta, weighted, decide, identify (default: the first four)");
  cmd.add_option("--tolerance", f.tolerance, "relative slack on the objective before an answer is 'suboptimal' (0.01)");
}

RandomTaskOptions random_task_options(const RandomCaseFlags& f) {
  if (f.min_n < 2 || f.max_n < f.min_n)
    throw InputError("--min-n/--max-n: need 2 <= min-n <= max-n (got " + std::to_string(f.min_n) + ", " + std::to_string(f.max_n) + ")");
  if (f.max_n > 2000) throw InputError("--max-n: at most 2000 samples per random case");
  if (f.leading_zeros < 0 || f.leading_zeros >= f.min_n)
    throw InputError("--leading-zeros: must be in [0, min-n) (got " + std::to_string(f.leading_zeros) + ")");
  if (f.max_delay < 0 || f.max_delay > 10) throw InputError("--max-delay: must be in [0, 10]");
  if (!(f.tolerance >= 0)) throw InputError("--tolerance: must be >= 0");
  RandomTaskOptions o;
  o.cases.min_n = f.min_n;
  o.cases.max_n = f.max_n;
  o.cases.model.lti = f.lti;
  o.cases.model.allow_general = true;  // all three uncertainty structures
  if (f.siso) o.cases.model.max_nu = o.cases.model.max_ny = 1;
  o.cases.leading_zero_inputs = f.leading_zeros;
  o.cases.max_delay = f.max_delay;
  o.cases.static_blocks = f.static_blocks;
  o.tolerance = f.tolerance;
  o.kinds.clear();
  std::stringstream list(f.kinds);
  for (std::string k; std::getline(list, k, ',');)
    if (!k.empty()) o.kinds.push_back(task_kind_from_string(k, "--kinds"));
  if (o.kinds.empty()) throw InputError("--kinds: give at least one task kind");
  return o;
}

std::map<std::string, std::string> case_folder_files(const GeneratedCase& c) {
  return {{c.task.data, csv_text(experiment_columns(c.random.model.columns, c.random.exp))},
          {c.task.model, write_model_json(c.random.model)},
          {"truth.json", write_model_json(c.random.truth)},
          {"task.json", task_json(c.task)}};
}

void write_case_folder(const std::string& folder, const GeneratedCase& c) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw IoError("cannot create the case folder '" + folder + "': " + ec.message());
  for (const auto& [name, text] : case_folder_files(c)) write_text_file((fs::path(folder) / name).string(), text, "case file");
}

}  // namespace lpvid::cli
