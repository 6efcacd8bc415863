#include "certify/outside_solution.h"

#include <algorithm>
#include <cmath>

#include "certify/certify.h"
#include "core/file_io.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "model/simulate.h"
#include "solvers/sdpa_file.h"
#include "solvers/sdpa_sidecar.h"
#include "toeplitz/fir.h"

namespace lpvid {
namespace {

std::string about_value(const LmiProgram& p, const std::string& key) {
  for (const auto& [k, v] : p.about)
    if (k == key) return v;
  return "";
}

/// Largest |value| over every stored entry (F0 and all F_i) and the cost.
double largest_entry(const LmiProgram& p) {
  double m = 0.0;
  for (double c : p.cost) m = std::max(m, std::abs(c));
  for (const LmiBlock& b : p.blocks) {
    for (const SymEntry& e : b.F0.entries) m = std::max(m, std::abs(e.value));
    for (const auto& [var, F] : b.Fi)
      for (const SymEntry& e : F.entries) m = std::max(m, std::abs(e.value));
  }
  return m;
}

/// Why `file` is not `expected` (both compressed), or "" when they agree:
/// same structure, and numbers equal up to a relative 1e-9 of the largest
/// entry (a program rebuilt on another machine may differ in the last bits
/// of σ_z, σ_r; the check is a guard against a foreign file, not a part of
/// the certificate, which is checked exactly anyway).
std::string mismatch(const LmiProgram& file, const LmiProgram& expected) {
  for (const char* key : {"samples", "leading_zeros", "horizon", "taps", "ny", "nz", "objective", "delta_fixed",
                          "dmax_fixed", "lambda"}) {
    const std::string a = about_value(file, key), b = about_value(expected, key);
    if (a != b) return std::string(key) + " is '" + a + "' in the file but '" + b + "' for these inputs";
  }
  if (file.num_vars != expected.num_vars || file.blocks.size() != expected.blocks.size())
    return "the number of variables or blocks differs";
  const double tol = 1e-9 * std::max(largest_entry(expected), 1e-300);
  const auto close = [tol](const SymSparse& a, const SymSparse& b) {
    if (a.entries.size() != b.entries.size()) return false;
    for (std::size_t k = 0; k < a.entries.size(); ++k) {
      const SymEntry &x = a.entries[k], &y = b.entries[k];
      if (x.i != y.i || x.j != y.j || !(std::abs(x.value - y.value) <= tol)) return false;
    }
    return true;
  };
  for (std::size_t k = 0; k < file.cost.size(); ++k)
    if (!(std::abs(file.cost[k] - expected.cost[k]) <= tol)) return "the cost of variable " + std::to_string(k + 1) + " differs";
  for (std::size_t b = 0; b < file.blocks.size(); ++b) {
    const LmiBlock &x = file.blocks[b], &y = expected.blocks[b];
    if (x.size != y.size || x.diagonal != y.diagonal || !close(x.F0, y.F0) || x.Fi.size() != y.Fi.size())
      return "block " + std::to_string(b + 1) + " differs (its size or its constant term: other data or model?)";
    for (std::size_t k = 0; k < x.Fi.size(); ++k)
      if (x.Fi[k].first != y.Fi[k].first || !close(x.Fi[k].second, y.Fi[k].second))
        return "block " + std::to_string(b + 1) + ", the matrix of variable " + std::to_string(y.Fi[k].first + 1) +
               " differs";
  }
  return "";
}

}  // namespace

Theorem21Program theorem21_program(const LpvModel<Rational>& model, const Experiment<Rational>& exp_in,
                                   const CertifyOptions& options) {
  if (exp_in.record_count() > 1)
    throw InputError("an outside solver's program (--write-sdpa, --solution) is written for one record; "
                     "certify several records with lpvid's own solvers");
  const Experiment<Rational> exp = with_state_scheduling(model, exp_in);  // "@x<i>" columns
  const Simulation<Rational> sim = simulate(model, exp);
  const Mat<Rational> r = exp.y - sim.output;
  Theorem21Program out;
  out.options = in_original_units(options, model, sim, exp);
  out.objective = solver_objective(out.options.objective);
  const Eigen::Index L = exp.n() - leading_zero_samples(sim.z);
  const long K = options.max_taps > 0 && options.max_taps < L ? options.max_taps : 0;  // 0: the full horizon
  out.delta = delta_form_program(nearest_double(sim.z), nearest_double(r), out.objective, K);
  return out;
}

OutsideSolution read_outside_solution(const std::string& program_path, const std::string& solution_path,
                                      SolutionFormat format, int exit_code) {
  OutsideSolution out;
  out.program = read_sdpa_file(program_path);
  out.program_name = program_path;
  out.solution_name = solution_path;
  out.solution_text = read_text_file(solution_path);
  out.format = format;
  out.exit_code = exit_code;
  return out;
}

CertifiedBounds certify_outside_solution(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                         const CertifyOptions& options, const OutsideSolution& outside) {
  const LmiProgram& file = outside.program;
  if (about_value(file, "kind") != kDeltaFormKind)
    throw InputError(outside.program_name + ": not a Theorem 2.1 program written by lpvid (no '*lpvid-about kind " +
                     std::string(kDeltaFormKind) + "' line); write it with 'lpvid invalidate ... --write-sdpa'");
  const Theorem21Program expected = theorem21_program(model, exp, options);
  const std::string why = mismatch(file, expected.delta.program.compressed());
  if (!why.empty())
    throw InputError(outside.program_name + ": not the Theorem 2.1 program of this model, data and options (" + why +
                     "); give the same --model, --data, --rows, --delta/--dmax/--lambda and --max-taps as when it was written");
  const SolveResult sol =
      outside.format == SolutionFormat::kCsdp
          ? parse_csdp_solution(outside.solution_text, outside.solution_name, file, outside.exit_code)
          : parse_sdpa_result(outside.solution_text, outside.solution_name, file, options.solver);
  CertifiedBounds out;
  if (!has_solution(sol.status)) {
    out.solve_status = sol.status;
    out.reason = outside.solution_name + ": the outside solver's status is " + std::string(to_string(sol.status)) +
                 (sol.message.empty() ? "" : " (" + sol.message + ")") + ": no solution to certify";
    out.outcome = outcome_of(out, options.objective);
    return out;
  }
  Mat<double> taps;
  double delta2 = 0, dmax2 = 0;
  read_delta_solution(sol, expected.delta.variables, expected.objective, taps, delta2, dmax2);
  out = certify_with_taps(model, exp, taps, expected.options, sol.backend);
  out.solve_status = sol.status;
  out.delta2_solver = delta2;
  out.solve_seconds = sol.seconds;
  out.outcome = outcome_of(out, options.objective);
  return out;
}

}  // namespace lpvid
