// lpvid generate: data sets with a known answer (fixtures), e.g. the paper's
// Example 1 (eq. 17). Every fixture in fixtures/ names the command that made it.
#include <iostream>
#include <memory>
#include <optional>

#include "core/file_io.h"
#include "cli/commands.h"
#include "cli/refused_alias.h"
#include "cli/random_cases.h"
#include "core/input_error.h"
#include "data/csv_writer.h"
#include "examples/effect_cases.h"
#include "examples/paper_example1.h"
#include "examples/paper_example2.h"
#include "model/model_file.h"
#include "cli/help_text.h"

namespace lpvid::cli {
namespace {

/// effect-case's output noise when --noise-std is not given.
constexpr double kEffectCaseNoiseStd = 0.02;

struct GenerateArgs {
  std::string which = "example1";
  int n = 60;
  double noise_variance = 0.0;  ///< example1/example2: --noise-std squared (default noise-free)
  uint64_t seed = 1;
  std::string out, model_out, truth_out;
  std::string effect = "none", validation_out;
  std::optional<double> noise_std;  ///< --noise-std; effect-case default 0.02
  RandomCaseFlags random;
};

std::vector<TextColumn> effect_case_columns(const Experiment<Rational>& e) {
  return {{"u1", column_text(e.u, 0)}, {"y1", column_text(e.y, 0)}, {"rho1", column_text(e.rho, 0)}};
}

int run_generate_effect_case(const GenerateArgs& a) {
  if (a.validation_out.empty()) throw InputError("generate effect-case: --validation-out is required");
  const EffectCase c = make_effect_case(a.effect, a.n, a.seed, a.noise_std.value_or(kEffectCaseNoiseStd));
  write_csv(a.out, effect_case_columns(c.estimation));
  write_csv(a.validation_out, effect_case_columns(c.validation));
  std::cout << "wrote " << a.out << " and " << a.validation_out << " (" << a.n << " samples each, effect '" << a.effect
            << "', noise std " << a.noise_std.value_or(kEffectCaseNoiseStd) << ", seed " << a.seed << ")\n";
  if (!a.model_out.empty()) {
    write_model_file(a.model_out, c.declared);
    std::cout << "wrote " << a.model_out << " (declared model: the LPV system without the effect)\n";
  }
  if (!a.truth_out.empty()) {
    write_model_file(a.truth_out, c.truth);
    std::cout << "wrote " << a.truth_out << " (the true system, with the effect)\n";
  }
  return 0;
}

int run_generate_example2(const GenerateArgs& a) {
  Example2Options o;
  o.n = a.n;
  o.noise_variance = a.noise_variance;
  o.seed = a.seed;
  const Experiment<Rational> e = example2_experiment(o);
  write_csv(a.out, {{"u1", column_text(e.u, 0)}, {"y1", column_text(e.y, 0)}, {"rho1", column_text(e.rho, 0)}});
  std::cout << "wrote " << a.out << " (" << a.n << " samples, noise variance " << a.noise_variance << ", seed " << a.seed
            << ")\n";
  if (!a.model_out.empty()) {
    write_model_file(a.model_out, example2_initial_model());
    std::cout << "wrote " << a.model_out << " (initial model: the LPV part, offset basis 1, rho1, rho1^2 unknown)\n";
  }
  if (!a.truth_out.empty()) {
    write_model_file(a.truth_out, example2_true_model());
    std::cout << "wrote " << a.truth_out << " (the true system, offset 0.5 + 0.8 rho1 - 0.3 rho1^2)\n";
  }
  return 0;
}

/// `generate random`: one case of the property tests' generator, from the seed.
int run_generate_random(const GenerateArgs& a) {
  const GeneratedCase c = random_oracle_case(a.seed, random_task_options(a.random));
  write_case_folder(a.out, c);
  const RandomCase& r = c.random;
  std::cout << "wrote " << a.out << "/{data.csv, model.json, truth.json, task.json}: seed " << a.seed << ", " << r.exp.n()
            << " samples, " << r.model.ny << " output(s), " << r.model.nu << " input(s), " << r.model.nx << " state(s), "
            << r.model.n_rho() << " scheduling variable(s); task " << to_string(c.task.kind) << "; generated with delta "
            << r.delta << ", dmax " << r.dmax << " (the truth satisfies Theorem 2.1 there)\n";
  return 0;
}

int run_generate(const GenerateArgs& a) {
  if (a.which == "random") return run_generate_random(a);
  check_output_file(a.out, "data");
  check_output_file(a.validation_out, "validation data");
  check_output_file(a.model_out, "model");
  check_output_file(a.truth_out, "true model");
  if (a.which != "example1" && a.which != "example2" && a.which != "effect-case")
    throw InputError("generate: unknown data set '" + a.which + "' (known: example1, example2, effect-case, random)");
  if (a.n < 2) throw InputError("generate: --n must be at least 2");
  if (a.which == "effect-case") return run_generate_effect_case(a);
  if (a.which == "example2") return run_generate_example2(a);
  Example1Options o;
  o.n = a.n;
  o.noise_variance = a.noise_variance;
  o.seed = a.seed;
  const Experiment<Rational> e = example1_experiment(o);
  std::vector<TextColumn> cols = {{"u1", column_text(e.u, 0)},     {"u2", column_text(e.u, 1)},
                                  {"y1", column_text(e.y, 0)},     {"y2", column_text(e.y, 1)},
                                  {"rho1", column_text(e.rho, 0)}, {"rho2", column_text(e.rho, 1)}};
  write_csv(a.out, cols);
  std::cout << "wrote " << a.out << " (" << a.n << " samples, noise variance " << a.noise_variance << ", seed " << a.seed
            << ")\n";
  if (!a.model_out.empty()) {
    write_model_file(a.model_out, example1_initial_model());
    std::cout << "wrote " << a.model_out << " (initial model: eq. 17 without the rho2^2 output factor)\n";
  }
  if (!a.truth_out.empty()) {
    write_model_file(a.truth_out, example1_true_model());
    std::cout << "wrote " << a.truth_out << " (the true system, eq. 17)\n";
  }
  return 0;
}

}  // namespace

Runner add_generate_command(CLI::App& app) {
  auto a = std::make_shared<GenerateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "generate", "Write a data set with a known answer (the paper's Example 1, or an Example 2 flavour with an offset)");
  cmd->add_option("which", a->which, "data set: example1, example2 (eq. 20: output offset Phi(rho)), effect-case (an effect the written model does not declare) or random (a random case of the property tests' generator with an oracle task; --out is then a folder)");
  cmd->add_option("--n", a->n, with_default("samples", a->n));
  cmd->add_option("--noise-std", a->noise_std,
                                    "standard deviation of the white output noise (example1/example2: default 0, paper "
                                    "Table II: variance 0.1; effect-case: default 0.02)")
                        ->check(CLI::NonNegativeNumber);
  add_renamed_option(*cmd, "--noise-variance", "--noise-std",
                     "one name per idea: give the standard deviation, e.g. --noise-std 0.316 for variance 0.1");
  cmd->add_option("--seed", a->seed, with_default("random seed", a->seed));
  cmd->add_option("--out", a->out, "data CSV to write (effect-case: the estimation record; random: the case folder)")->required();
  add_random_case_flags(*cmd, a->random);
  std::string kinds;
  for (const auto& k : effect_case_kinds()) kinds += (kinds.empty() ? "" : ", ") + k;
  auto* effect = cmd->add_option("--effect", a->effect, "effect-case: the undeclared effect (" + kinds + ")");
  auto* validation = cmd->add_option("--validation-out", a->validation_out, "effect-case: the validation record to write");
  // Options of one data set are refused for the others (never silently ignored).
  cmd->callback([cmd, a, effect, validation] {
    const std::vector<std::string> random_only = {"--siso", "--lti", "--min-n", "--max-n", "--leading-zeros",
                                                  "--max-delay", "--static-blocks", "--kinds", "--tolerance"};
    if (a->which == "random") {
      for (const char* other : {"--model-out", "--truth-out", "--effect", "--validation-out", "--noise-std"})
        if (cmd->count(other) > 0) throw CLI::ValidationError(other, "is not for random (it writes data, model, truth and task into --out)");
      if (cmd->count("--n") > 0) a->random.min_n = a->random.max_n = a->n;
      return;
    }
    for (const std::string& name : random_only)
      if (cmd->count(name) > 0) throw CLI::ValidationError(name, "is only for random (the data set here is " + a->which + ")");
    if (a->which == "effect-case") return;
    if (a->noise_std) a->noise_variance = *a->noise_std * *a->noise_std;
    for (const CLI::Option* o : {effect, validation})
      if (o->count() > 0)
        throw CLI::ValidationError(o->get_name(), "is only for effect-case (the data set here is " + a->which + ")");
  });
  cmd->add_option("--model-out", a->model_out, "also write the initial model (JSON)");
  cmd->add_option("--truth-out", a->truth_out, "also write the true model (JSON)");
  return [cmd, a] { return cmd->parsed() ? run_generate(*a) : -1; };
}

}  // namespace lpvid::cli
