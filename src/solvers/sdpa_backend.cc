#include "solvers/sdpa_backend.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>

#include <sdpa_call.h>

namespace lpvid {

// ============================================================================
// Sign convention (written once).
//
// SDPA 7 solves the pair
//   primal:  min Σ_k c_k x_k   s.t. X = Σ_k F_k x_k − F_0 ⪰ 0
//   dual:    max ⟨F_0, Y⟩      s.t. ⟨F_k, Y⟩ = c_k,  Y ⪰ 0.
// Our (P) "min cᵀx s.t. F0 + Σ x_i F_i ⪰ 0" is SDPA's PRIMAL with
//   x = x,   F_k = F_i (ours),   F_0 (SDPA) = −F0 (ours),   X = F(x),
// and our (D) is SDPA's dual with the same Y. SDPA's "primal infeasible /
// unbounded" are therefore ours: an infeasible LMI ends in pINF_dFEAS (or
// dUNBD when the dual objective passes upperBound first), an unbounded
// objective in pFEAS_dINF (or pUNBD).
//
// Phase WORDS, not SDPA::PhaseType values: in Debian's SDPA 7.3.16,
// getPhaseValue() returns the library's internal enum, whose order differs
// from the PhaseType declared in sdpa_call.h (pFEAS_dINF/pINF_dFEAS and
// pUNBD/dUNBD are swapped), while getPhaseString() and the `sdpa` command
// print the right words. So we read the word.
// ============================================================================

namespace {

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

/// SDPA's phases, as words (our own enum, see above).
enum class Phase { noINFO, pFEAS, dFEAS, pdFEAS, pdINF, pFEAS_dINF, pINF_dFEAS, pdOPT, pUNBD, dUNBD, unknown };

constexpr std::pair<const char*, Phase> kPhaseWords[] = {
    {"noINFO", Phase::noINFO},         {"pFEAS", Phase::pFEAS},           {"dFEAS", Phase::dFEAS},
    {"pdFEAS", Phase::pdFEAS},         {"pdINF", Phase::pdINF},           {"pFEAS_dINF", Phase::pFEAS_dINF},
    {"pINF_dFEAS", Phase::pINF_dFEAS}, {"pdOPT", Phase::pdOPT},           {"pUNBD", Phase::pUNBD},
    {"dUNBD", Phase::dUNBD}};

Phase phase_of_word(const std::string& word) {
  for (const auto& [w, phase] : kPhaseWords)
    if (word == w) return phase;
  return Phase::unknown;
}

/// SDPA's phase → SolveStatus. The one place where SDPA's phases are
/// interpreted.
///
/// pdFEAS means "primal and dual feasible to epsilonDash, gap not (yet)
/// below epsilonStar". SDPA 7.3 often ends there one iteration short of
/// pdOPT: its main loop (sdpa_solve.cpp) stops as soon as, in phase pdFEAS,
/// the objectives cross numerically or the corrector's beta exceeds 5
/// ("Strange behavior : primal < dual"). We found no parameter setting that
/// avoids this (PARAMETER_STABLE_BUT_SLOW, other betaStar / betaBar /
/// gammaStar / lambdaStar, a smaller epsilonStar, a warm restart from the
/// last point: all still stop at pdFEAS on min t s.t. [[t,1],[1,1]] ⪰ 0 and
/// on small λ_max problems, with a relative gap of 1e-8 … 3e-7). So a pdFEAS
/// point is judged by the same measure as everywhere else: the relative gap
/// |p − d| / (1 + |p| + |d|) against gap_tol (kOptimal), or 1000·gap_tol
/// (kOptimalInaccurate, like CSDP's code 3).
SolveStatus status_from_sdpa(Phase phase, double relative_gap, bool at_limit, double gap_tol, std::string& words) {
  switch (phase) {
    case Phase::pdOPT:
      words = "SDPA pdOPT: optimal";
      return SolveStatus::kOptimal;
    case Phase::pdFEAS:
      words = "SDPA pdFEAS: primal and dual feasible, relative gap " + format_number(relative_gap);
      if (relative_gap <= gap_tol) return SolveStatus::kOptimal;
      if (relative_gap <= 1000.0 * gap_tol) return SolveStatus::kOptimalInaccurate;
      return at_limit ? SolveStatus::kIterationLimit : SolveStatus::kBackendError;
    case Phase::pINF_dFEAS:
      words = "SDPA pINF_dFEAS: SDPA's primal (our LMI) is infeasible";
      return SolveStatus::kPrimalInfeasible;
    case Phase::dUNBD:
      words = "SDPA dUNBD: the dual objective passed upperBound, so our LMI is infeasible";
      return SolveStatus::kPrimalInfeasible;
    case Phase::pdINF:
      words = "SDPA pdINF: primal and dual infeasible; our LMI has no solution";
      return SolveStatus::kPrimalInfeasible;
    case Phase::pFEAS_dINF:
      words = "SDPA pFEAS_dINF: SDPA's dual is infeasible, so our objective is unbounded below";
      return SolveStatus::kDualInfeasible;
    case Phase::pUNBD:
      words = "SDPA pUNBD: the primal objective passed lowerBound: unbounded below";
      return SolveStatus::kDualInfeasible;
    case Phase::pFEAS:
      words = "SDPA pFEAS: only primal feasibility reached";
      return at_limit ? SolveStatus::kIterationLimit : SolveStatus::kBackendError;
    case Phase::dFEAS:
      words = "SDPA dFEAS: only dual feasibility reached";
      return at_limit ? SolveStatus::kIterationLimit : SolveStatus::kBackendError;
    case Phase::noINFO:
      words = "SDPA noINFO: stopped without a conclusion";
      return at_limit ? SolveStatus::kIterationLimit : SolveStatus::kBackendError;
    case Phase::unknown:
      break;
  }
  words = "SDPA: unknown phase";
  return SolveStatus::kBackendError;
}

/// |primal − dual| / (1 + |primal| + |dual|), the gap as SolverOptions means it.
double relative_gap(double primal, double dual) {
  return std::fabs(primal - dual) / (1.0 + std::fabs(primal) + std::fabs(dual));
}

/// Parameters. Everything not taken from SolverOptions is SDPA's
/// PARAMETER_DEFAULT (lambdaStar 1e2, omegaStar 2, betaStar 0.1, betaBar 0.2,
/// gammaStar 0.9).
void set_parameters(SDPA& s, const SolverOptions& o) {
  s.setParameterType(SDPA::PARAMETER_DEFAULT);
  s.setParameterMaxIteration(o.max_iterations);
  s.setParameterEpsilonStar(o.gap_tol);
  s.setParameterEpsilonDash(o.feas_tol);
  s.setParameterLowerBound(-o.divergence_bound);
  s.setParameterUpperBound(o.divergence_bound);
  s.setDisplay(o.verbose ? stdout : nullptr);
  s.setResultFile(nullptr);  // no result file
  s.setNumThreads(o.threads);  // else SDPA consults OMP_NUM_THREADS
}

/// SDPA writes its warnings ("Strange behavior : primal < dual :: line …")
/// to std::cout whatever the display setting. Unless verbose, we catch them
/// for SolveResult::message instead.
class CoutCapture {
 public:
  explicit CoutCapture(bool active) : active_(active) {
    if (active_) previous_ = std::cout.rdbuf(buffer_.rdbuf());
  }
  ~CoutCapture() { release(); }
  CoutCapture(const CoutCapture&) = delete;
  CoutCapture& operator=(const CoutCapture&) = delete;
  /// Restores std::cout; returns what was caught, one line per "; ".
  std::string release() {
    if (!active_) return "";
    std::cout.rdbuf(previous_);
    active_ = false;
    std::string text, line;
    std::istringstream lines(buffer_.str());
    while (std::getline(lines, line))
      if (!line.empty()) text += (text.empty() ? "" : "; ") + line;
    return text;
  }

 private:
  bool active_;
  std::ostringstream buffer_;
  std::streambuf* previous_ = nullptr;
};

SolveResult sdpa_solve_reduced(const LmiProgram& p, const SolverOptions& options) {
  CoutCapture capture(!options.verbose);
  SDPA s;
  set_parameters(s, options);
  const int m = p.num_vars;
  const int nb = static_cast<int>(p.blocks.size());
  s.inputConstraintNumber(m);
  s.inputBlockNumber(nb);
  for (int l = 1; l <= nb; ++l) {
    const LmiBlock& blk = p.blocks[static_cast<std::size_t>(l - 1)];
    const bool lp = sdp_detail::acts_diagonally(blk);
    s.inputBlockSize(l, lp ? -blk.size : blk.size);
    s.inputBlockType(l, lp ? SDPA::LP : SDPA::SDP);
  }
  s.initializeUpperTriangleSpace();
  for (int k = 1; k <= m; ++k) s.inputCVec(k, p.cost[static_cast<std::size_t>(k - 1)]);
  for (int l = 1; l <= nb; ++l) {
    const LmiBlock& blk = p.blocks[static_cast<std::size_t>(l - 1)];
    for (const SymEntry& e : blk.F0.entries) s.inputElement(0, l, e.i + 1, e.j + 1, -e.value);  // F_0 = −F0
    for (const auto& [var, F] : blk.Fi)
      for (const SymEntry& e : F.entries) s.inputElement(var + 1, l, e.i + 1, e.j + 1, e.value);
  }
  s.initializeUpperTriangle();
  s.initializeSolve();
  s.solve();
  if (options.verbose) std::fflush(stdout);

  SolveResult r;
  const std::string said = capture.release();
  r.iterations = s.getIteration();
  r.dual_objective = s.getDualObj();  // ⟨F_0, Y⟩ = −⟨F0, Y⟩
  const double gap = relative_gap(s.getPrimalObj(), s.getDualObj());
  char phase_text[64] = {};
  s.getPhaseString(phase_text);
  r.status = sdpa_status(phase_text, gap, r.iterations >= options.max_iterations, options.gap_tol, &r.message);
  if (!said.empty()) r.message += " (SDPA said: " + said + ")";
  const double* x = s.getResultXVec();
  r.x.assign(x, x + m);
  if (options.want_dual) {
    for (int l = 1; l <= nb; ++l) {
      const LmiBlock& blk = p.blocks[static_cast<std::size_t>(l - 1)];
      const double* Y = s.getResultYMat(l);
      if (blk.diagonal)
        r.dual_blocks.push_back(Eigen::Map<const Eigen::MatrixXd>(Y, blk.size, 1));
      else if (sdp_detail::acts_diagonally(blk))  // passed as LP: Y is its diagonal
        r.dual_blocks.push_back(Eigen::Map<const Eigen::VectorXd>(Y, blk.size).asDiagonal().toDenseMatrix());
      else
        r.dual_blocks.push_back(Eigen::Map<const Eigen::MatrixXd>(Y, blk.size, blk.size));
    }
  }
  return r;
}

}  // namespace

SolveStatus sdpa_status(const std::string& phase_word, double relative_gap, bool at_iteration_limit, double gap_tol,
                        std::string* words) {
  // SDPA pads the word with spaces ("pdFEAS    ").
  const std::size_t first = phase_word.find_first_not_of(" \t");
  const std::size_t last = phase_word.find_last_not_of(" \t");
  const std::string word = first == std::string::npos ? "" : phase_word.substr(first, last - first + 1);
  std::string w;
  const SolveStatus status = status_from_sdpa(phase_of_word(word), relative_gap, at_iteration_limit, gap_tol, w);
  if (phase_of_word(word) == Phase::unknown) w += " '" + word + "'";
  if (words != nullptr) *words = w;
  return status;
}

SolveResult SdpaSolver::solve(const LmiProgram& program, const SolverOptions& options) {
  return sdp_detail::solve_with_presolve(program, options, name(), &sdpa_solve_reduced);
}

}  // namespace lpvid
