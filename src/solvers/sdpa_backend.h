#pragma once
/// SDPA 7 (Debian libsdpa-dev 7.3.16, callable library class SDPA from
/// sdpa_call.h) as an SdpSolver.
///
/// The program is converted in sdpa_backend.cc, where the sign convention
/// and the phase mapping are written down once. Quirks handled there:
///  - its display (iteration table) goes to stdout unless set to NULL (we
///    do, unless verbose), and its warnings ("Strange behavior : primal <
///    dual :: line …") go to std::cout whatever the display: we catch them
///    into SolveResult::message;
///  - it exit()s on malformed input ("Some Input Matricies are Empty"):
///    we only give it valid input (every F_i nonempty);
///  - getPhaseValue() disagrees with the PhaseType enum of sdpa_call.h
///    (pFEAS_dINF/pINF_dFEAS and pUNBD/dUNBD swapped): we read the phase
///    word from getPhaseString();
///  - it often stops at pdFEAS just short of its own epsilonStar (a stop
///    rule in its main loop, not a parameter): a pdFEAS point is judged by
///    our relative gap (kOptimal within gap_tol, kOptimalInaccurate within
///    1000·gap_tol);
///  - it reads no parameter file in the library interface (the `sdpa`
///    command reads ./param.sdpa);
///  - blocks whose matrices are all diagonal are passed as LP blocks.

#include "solvers/sdp_solver.h"

namespace lpvid {

/// SDPA's phase word ("pdOPT", "pdFEAS", "pFEAS_dINF", … as SDPA prints it
/// after "phase.value =") as a SolveStatus, given the final relative gap
/// |p − d| / (1 + |p| + |d|) and whether the iteration limit was reached;
/// `words` (if given) gets the meaning. Unknown words are kBackendError.
/// The one mapping of SDPA phases (the library backend uses it too).
SolveStatus sdpa_status(const std::string& phase_word, double relative_gap, bool at_iteration_limit, double gap_tol,
                        std::string* words = nullptr);

class SdpaSolver final : public SdpSolver {
 public:
  std::string name() const override { return "sdpa"; }
  SolveResult solve(const LmiProgram& program, const SolverOptions& options) override;
};

}  // namespace lpvid
