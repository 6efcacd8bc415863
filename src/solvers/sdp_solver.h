#pragma once
/// The solver interface (docs/design.md §13.1, §13.2, §13.7): an LmiProgram goes in, a
/// SolveResult with one SolveStatus comes out. Backends: "csdp"
/// (csdp_backend.h), "sdpa" (sdpa_backend.h); sdpa_file.h writes any program
/// for an outside solver and reads its answer back.
///
/// Our problem is
///     (P)  minimise cᵀx  s.t.  F(x) = F0 + Σ_i x_i F_i ⪰ 0      (every block)
/// and its Lagrange dual is
///     (D)  maximise −⟨F0, Y⟩  s.t.  ⟨F_i, Y⟩ = c_i,  Y ⪰ 0.
/// Each backend states once, in its .cc, how its own standard form maps to
/// (P) and (D), and maps its own outcome codes to SolveStatus in one switch.

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "solvers/lmi_program.h"

namespace lpvid {

/// The outcome of a solve, in the sense of (P) above.
enum class SolveStatus {
  /// (P) and (D) solved to the requested tolerances; x is a solution.
  kOptimal,
  /// A solution was found but not to full accuracy: the infeasibilities or
  /// the relative gap are above the tolerances by a factor < 1000 (CSDP's
  /// "partial success"; SDPA's pdFEAS with a gap in that range). x is usable
  /// with care.
  kOptimalInaccurate,
  /// Our LMI F(x) ⪰ 0 has no solution (the backend found a certificate:
  /// Y ⪰ 0 with ⟨F_i, Y⟩ = 0 and ⟨F0, Y⟩ < 0), or a block that does not
  /// depend on x is not PSD.
  kPrimalInfeasible,
  /// Our objective cᵀx is unbounded below on the LMI (the backend found a
  /// direction d with cᵀd < 0 and Σ d_i F_i ⪰ 0, or (D) is infeasible).
  kDualInfeasible,
  /// Stopped at SolverOptions::max_iterations.
  kIterationLimit,
  /// Anything else: numerical trouble, lack of progress, a backend failure.
  /// SolveResult::message holds the backend's own words.
  kBackendError,
};

/// "optimal", "optimal_inaccurate", "primal_infeasible", "dual_infeasible",
/// "iteration_limit", "backend_error" (stable words for reports).
const char* to_string(SolveStatus status);

/// True for kOptimal and kOptimalInaccurate (x holds a solution).
bool has_solution(SolveStatus status);

/// Options common to all backends. These initialisers are THE defaults
/// (docs/design.md §13.7); the CLI prints the values it ran with.
struct SolverOptions {
  /// Relative duality gap |cᵀx − dual| / (1 + |cᵀx| + |dual|) to stop at.
  /// CSDP: objtol. SDPA: epsilonStar. 1e-7 is SDPA's default and about
  /// what SDPA reaches in double precision (sdpa_backend.cc); CSDP's own
  /// default is 1e-8.
  double gap_tol = 1e-7;
  /// Relative primal and dual infeasibility to stop at.
  /// CSDP: axtol and atytol. SDPA: epsilonDash.
  double feas_tol = 1e-8;
  /// Iteration limit. CSDP: maxiter. SDPA: maxIteration.
  int max_iterations = 100;
  /// Objective magnitude (SDPA: ±lowerBound/upperBound) or certificate ratio
  /// (CSDP: pinftol, dinftol) beyond which the backend declares
  /// infeasibility / unboundedness. Raise it for badly scaled problems.
  double divergence_bound = 1e8;
  /// Let the backend print its progress to stdout. Off by default: the
  /// library is silent.
  bool verbose = false;
  /// Backend print level when verbose (CSDP: printlevel 1–4; SDPA prints
  /// its iteration table for any value ≥ 1).
  int print_level = 1;
  /// Threads for OpenBLAS and for SDPA's Schur complement during a solve.
  /// 1 gives reproducible results and avoids oversubscription.
  int threads = 1;
  /// Fill SolveResult::dual_blocks (dense; size² doubles per block).
  bool want_dual = false;
};

/// The answer to one solve.
struct SolveResult {
  SolveStatus status = SolveStatus::kBackendError;
  /// x ∈ R^num_vars. A solution if has_solution(status); for other statuses
  /// whatever the backend left there (for CSDP's kDualInfeasible, a
  /// direction of unboundedness). Variables that appear in no block are 0.
  std::vector<double> x;
  /// cᵀx, computed by us from x.
  double objective = 0.0;
  /// The backend's value of (D), −⟨F0, Y⟩: a lower bound on (P) at optimum.
  double dual_objective = 0.0;
  /// Interior-point iterations; -1 when the backend does not report them
  /// (CSDP's library interface does not).
  int iterations = -1;
  /// Wall-clock seconds of the whole solve (conversion included).
  double seconds = 0.0;
  /// "csdp", "sdpa", or the name of an outside solver.
  std::string backend;
  /// The backend's own status words, and notes from the presolve.
  std::string message;
  /// Only with SolverOptions::want_dual: Y per block, in block order (a
  /// size × size matrix; a size × 1 column for a diagonal block). Blocks
  /// that do not depend on x get Y = 0. For kPrimalInfeasible from CSDP this
  /// is the infeasibility certificate.
  std::vector<Eigen::MatrixXd> dual_blocks;
};

/// A backend. Implementations are stateless; solve() may be called any
/// number of times. Solves are serialised process-wide (see
/// solve_with_presolve), so calling from several threads is safe but not
/// parallel.
class SdpSolver {
 public:
  virtual ~SdpSolver() = default;
  /// The name make_solver() knows it by.
  virtual std::string name() const = 0;
  /// Solves `program`. Throws std::invalid_argument for an invalid program
  /// (LmiProgram::validate) or invalid options; every solver outcome,
  /// including backend failure, is a SolveStatus.
  virtual SolveResult solve(const LmiProgram& program, const SolverOptions& options) = 0;
};


/// Throws std::invalid_argument for nonsense options (non-positive or
/// non-finite tolerances, max_iterations < 1, threads < 1, …).
void validate_options(const SolverOptions& options);

namespace sdp_detail {

/// What a backend receives from solve_with_presolve: a compressed program in
/// which every block depends on some variable, every variable appears in
/// some block (so no F_i is empty), and there is at least one of each. The
/// backend returns x and dual_blocks of THIS program (reduced indices),
/// status, dual_objective, iterations and message.
using ReducedSolve = SolveResult (*)(const LmiProgram& reduced, const SolverOptions& options);

/// True if the block is diagonal or every stored entry of F0 and of all F_i
/// is on the diagonal: then it is a set of scalar inequalities and backends
/// pass it as a diagonal (LP) block, as CSDP's own file reader does. Its Y
/// is still returned in the block's layout (size × size if not diagonal).
bool acts_diagonally(const LmiBlock& block);

/// The part every backend shares, written once:
///  1. validate the program and the options (throws);
///  2. compress; decide blocks that do not depend on x (PSD or not: a
///     diagonal block exactly, a matrix block by its smallest eigenvalue ≥
///     −feas_tol · max(1, max |eigenvalue|)) and drop them;
///  3. drop variables that appear in no block (x = 0 for them; if one has a
///     nonzero cost and the rest is feasible, the objective is unbounded:
///     kDualInfeasible);
///  4. under a process-wide mutex, with OpenBLAS set to options.threads,
///     call `backend` on what is left (if anything is);
///  5. map x and Y back, compute cᵀx and the time.
SolveResult solve_with_presolve(const LmiProgram& program, const SolverOptions& options, const std::string& backend_name,
                                ReducedSolve backend);

}  // namespace sdp_detail

}  // namespace lpvid
