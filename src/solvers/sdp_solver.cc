#include "solvers/sdp_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <sstream>
#include <stdexcept>


// OpenBLAS's own thread control (the library is linked by CMake).
extern "C" {
void openblas_set_num_threads(int num_threads);
int openblas_get_num_threads(void);
}

namespace lpvid {

const char* to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::kOptimal: return "optimal";
    case SolveStatus::kOptimalInaccurate: return "optimal_inaccurate";
    case SolveStatus::kPrimalInfeasible: return "primal_infeasible";
    case SolveStatus::kDualInfeasible: return "dual_infeasible";
    case SolveStatus::kIterationLimit: return "iteration_limit";
    case SolveStatus::kBackendError: return "backend_error";
  }
  return "backend_error";
}

bool has_solution(SolveStatus status) {
  return status == SolveStatus::kOptimal || status == SolveStatus::kOptimalInaccurate;
}

void validate_options(const SolverOptions& o) {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  std::ostringstream bad;
  if (!positive(o.gap_tol)) bad << " gap_tol = " << o.gap_tol << " (must be finite and > 0);";
  if (!positive(o.feas_tol)) bad << " feas_tol = " << o.feas_tol << " (must be finite and > 0);";
  if (!positive(o.divergence_bound)) bad << " divergence_bound = " << o.divergence_bound << " (must be finite and > 0);";
  if (o.max_iterations < 1) bad << " max_iterations = " << o.max_iterations << " (must be >= 1);";
  if (o.threads < 1) bad << " threads = " << o.threads << " (must be >= 1);";
  if (o.print_level < 0) bad << " print_level = " << o.print_level << " (must be >= 0);";
  if (!bad.str().empty()) throw std::invalid_argument("SolverOptions:" + bad.str());
}

namespace sdp_detail {
namespace {

/// One SDP solve at a time in this process: CSDP is not re-entrant (static
/// work arrays in op_o), SDPA's re-entrancy is undocumented, and the
/// OpenBLAS thread count is process state.
std::mutex& solve_mutex() {
  static std::mutex m;
  return m;
}

/// Sets the OpenBLAS thread count for the lifetime of the object.
class ScopedBlasThreads {
 public:
  explicit ScopedBlasThreads(int threads) : previous_(openblas_get_num_threads()) {
    openblas_set_num_threads(threads);
  }
  ~ScopedBlasThreads() { openblas_set_num_threads(previous_); }
  ScopedBlasThreads(const ScopedBlasThreads&) = delete;
  ScopedBlasThreads& operator=(const ScopedBlasThreads&) = delete;

 private:
  int previous_;
};

/// Is a block that does not depend on x PSD? Empty string if yes, else why not.
std::string constant_block_problem(const LmiBlock& blk, double feas_tol) {
  std::ostringstream why;
  if (blk.diagonal) {
    // Exact: F0 is diagonal, entries not stored are 0.
    for (const SymEntry& e : blk.F0.entries)
      if (e.value < 0.0) {
        why << "diagonal entry " << e.i << " is " << e.value << " < 0";
        return why.str();
      }
    return "";
  }
  if (blk.F0.empty()) return "";
  const Eigen::MatrixXd F0 = blk.F0.to_dense(blk.size);
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(F0, Eigen::EigenvaluesOnly).eigenvalues();
  const double scale = std::max(1.0, lambda.cwiseAbs().maxCoeff());
  if (lambda(0) < -feas_tol * scale) {
    why << "smallest eigenvalue is " << lambda(0) << " < -" << feas_tol << " * " << scale;
    return why.str();
  }
  return "";
}

std::string block_label(const LmiBlock& blk, std::size_t b) {
  return "block " + std::to_string(b) + (blk.name.empty() ? "" : " '" + blk.name + "'");
}

/// A program after presolve: the blocks that depend on x (constant blocks
/// decided), the variables that appear in one of them, and the way back.
struct PresolvedProgram {
  LmiProgram reduced;
  std::vector<int> kept_blocks;  // reduced block -> original block
  std::vector<int> kept_vars;    // reduced var -> original var
  std::string notes;
  std::string unbounded_var;  // a variable with a cost that appears in no block
  std::string infeasible;     // why a constant block makes the program infeasible ("" if none)
};

/// Steps 2 and 3: the canonical form; constant blocks decided and dropped;
/// the variables that appear in no kept block removed.
PresolvedProgram presolve_program(const LmiProgram& program, double feas_tol) {
  PresolvedProgram p;
  LmiProgram full = program.compressed();
  for (std::size_t b = 0; b < full.blocks.size(); ++b) {
    const LmiBlock& blk = full.blocks[b];
    if (!blk.Fi.empty()) {
      p.kept_blocks.push_back(static_cast<int>(b));
      continue;
    }
    const std::string problem = constant_block_problem(blk, feas_tol);
    if (!problem.empty()) {
      p.infeasible = "presolve: " + block_label(blk, b) + " does not depend on x and is not PSD: " + problem;
      return p;
    }
    p.notes += "presolve: " + block_label(blk, b) + " does not depend on x and is PSD; dropped. ";
  }
  std::vector<int> reduced_of(static_cast<std::size_t>(full.num_vars), -1);  // original var -> reduced var
  for (int b : p.kept_blocks)
    for (const auto& [var, F] : full.blocks[static_cast<std::size_t>(b)].Fi) reduced_of[static_cast<std::size_t>(var)] = 0;
  for (int k = 0; k < full.num_vars; ++k) {
    if (reduced_of[static_cast<std::size_t>(k)] == 0) {
      reduced_of[static_cast<std::size_t>(k)] = static_cast<int>(p.kept_vars.size());
      p.kept_vars.push_back(k);
    } else if (full.cost[static_cast<std::size_t>(k)] != 0.0 && p.unbounded_var.empty()) {
      p.unbounded_var = full.var_name(k);
    }
  }
  if (p.kept_vars.size() < static_cast<std::size_t>(full.num_vars))
    p.notes += "presolve: " + std::to_string(static_cast<std::size_t>(full.num_vars) - p.kept_vars.size()) +
               " variable(s) appear in no block; set to 0. ";
  p.reduced.num_vars = static_cast<int>(p.kept_vars.size());
  for (int k : p.kept_vars) p.reduced.cost.push_back(full.cost[static_cast<std::size_t>(k)]);
  for (int b : p.kept_blocks) {
    LmiBlock blk = std::move(full.blocks[static_cast<std::size_t>(b)]);
    for (auto& [var, F] : blk.Fi) var = reduced_of[static_cast<std::size_t>(var)];  // order preserved
    p.reduced.blocks.push_back(std::move(blk));
  }
  return p;
}

/// Zero dual blocks of the original program's shapes (when duals are wanted).
void zero_dual_blocks(const LmiProgram& program, const SolverOptions& options, SolveResult& r) {
  if (!options.want_dual) return;
  r.dual_blocks.clear();
  for (const LmiBlock& blk : program.blocks)
    r.dual_blocks.push_back(Eigen::MatrixXd::Zero(blk.size, blk.diagonal ? 1 : blk.size));
}

/// Step 5: the reduced solve `r` back in the original numbering, into `result`.
void restore_numbering(const LmiProgram& program, const SolverOptions& options, const PresolvedProgram& p,
                       SolveResult& r, SolveResult& result) {
  result.status = r.status;
  result.dual_objective = r.dual_objective;
  result.iterations = r.iterations;
  result.message = p.notes + r.message;
  for (std::size_t k = 0; k < p.kept_vars.size() && k < r.x.size(); ++k)
    result.x[static_cast<std::size_t>(p.kept_vars[k])] = r.x[k];
  if (options.want_dual) {
    zero_dual_blocks(program, options, result);
    for (std::size_t rb = 0; rb < p.kept_blocks.size() && rb < r.dual_blocks.size(); ++rb)
      result.dual_blocks[static_cast<std::size_t>(p.kept_blocks[rb])] = std::move(r.dual_blocks[rb]);
  }
  if (!p.unbounded_var.empty() && has_solution(result.status)) {
    result.status = SolveStatus::kDualInfeasible;
    result.message += "; variable '" + p.unbounded_var + "' has a cost but appears in no block: unbounded below";
  }
}

}  // namespace

bool acts_diagonally(const LmiBlock& block) {
  if (block.diagonal) return true;
  auto diagonal_only = [](const SymSparse& m) {
    for (const SymEntry& e : m.entries)
      if (e.i != e.j) return false;
    return true;
  };
  if (!diagonal_only(block.F0)) return false;
  for (const auto& [var, F] : block.Fi)
    if (!diagonal_only(F)) return false;
  return true;
}

SolveResult solve_with_presolve(const LmiProgram& program, const SolverOptions& options, const std::string& backend_name,
                                ReducedSolve backend) {
  const auto start = std::chrono::steady_clock::now();
  program.validate();
  validate_options(options);

  SolveResult result;
  result.backend = backend_name;
  result.x.assign(static_cast<std::size_t>(program.num_vars), 0.0);
  auto finish = [&](SolveResult& r) -> SolveResult& {
    r.objective = program.objective(r.x);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  };

  // 2-3. Canonical form, constant blocks decided, free variables dropped.
  PresolvedProgram p = presolve_program(program, options.feas_tol);
  if (!p.infeasible.empty()) {
    result.status = SolveStatus::kPrimalInfeasible;
    result.message = p.infeasible;
    zero_dual_blocks(program, options, result);
    return finish(result);
  }
  if (p.kept_vars.empty()) {
    // Every block is constant and PSD: every x is feasible.
    zero_dual_blocks(program, options, result);
    if (!p.unbounded_var.empty()) {
      result.status = SolveStatus::kDualInfeasible;
      result.message = p.notes + "variable '" + p.unbounded_var + "' has a cost but appears in no block: unbounded below";
    } else {
      result.status = SolveStatus::kOptimal;
      result.message = p.notes + "nothing left to solve";
    }
    return finish(result);
  }

  // 4. The backend, one solve at a time.
  SolveResult r;
  {
    std::lock_guard<std::mutex> lock(solve_mutex());
    ScopedBlasThreads blas(options.threads);
    r = backend(p.reduced, options);
  }
  restore_numbering(program, options, p, r, result);
  return finish(result);
}

}  // namespace sdp_detail
}  // namespace lpvid
