#pragma once
/// CSDP (Borchers; Debian libsdp-dev, version 6.2) as an SdpSolver.
///
/// The program is converted to CSDP's structures in csdp_backend.cc, where
/// the sign convention and the return-code mapping are written down once.
/// Quirks handled there:
///  - easy_sdp() reads "param.csdp" from the working directory (a partial
///    file leaves parameters uninitialised) and exit()s on malformed input:
///    we set up and call sdp() directly with our own parameters, and only
///    ever give it valid input (no empty constraint, no zero-size block,
///    sorted upper-triangle entries without duplicates);
///  - it prints only at printlevel ≥ 1 (we use 0 unless verbose);
///  - it is not re-entrant (static work arrays in op_o): solves are
///    serialised (sdp_detail::solve_with_presolve);
///  - it gets "stuck" (codes 3, 5) on a few percent of small well-posed
///    problems, depending on its perturbobj / affine settings: we retry with
///    the other settings (kAttempts) and keep the best run;
///  - its library interface does not report the iteration count
///    (SolveResult::iterations = -1);
///  - blocks whose matrices are all diagonal are passed as DIAG blocks, as
///    CSDP's own file reader does.

#include "solvers/sdp_solver.h"

namespace lpvid {

/// CSDP's return code (the library's sdp() return value, which is also the
/// exit status of the `csdp` command) as a SolveStatus; `words` (if given)
/// gets CSDP's meaning of the code. The one mapping of CSDP codes.
SolveStatus csdp_status(int return_code, std::string* words = nullptr);

class CsdpSolver final : public SdpSolver {
 public:
  std::string name() const override { return "csdp"; }
  SolveResult solve(const LmiProgram& program, const SolverOptions& options) override;
};

}  // namespace lpvid
