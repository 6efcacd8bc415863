#pragma once
/// Theorem 2.1 for a fixed model, solved by an outside SDP solver.
/// The round trip (docs/certificates.md, "Solving Theorem 2.1 with an outside SDP solver"):
///
///     lpvid invalidate … --write-sdpa P.dat-s      theorem21_program, written with its sidecar
///                                                  (solvers/sdpa_sidecar.h): P.dat-s and P.dat-s.json
///     csdp P.dat-s P.sol                           any solver that reads SDPA sparse files
///     lpvid certify … --program P.dat-s --solution P.sol
///                                                  read_outside_solution, then
///                                                  certify_outside_solution: a checked certificate
///
/// The program is the Δ form of lmi/delta_form_lmi.h, exactly as
/// certify_fixed_model states it to its own solver (same signals, scaling,
/// tightened fixed bounds, --max-taps K; the structured SISO solver is not an
/// SDP, so the export always writes the SDP). The outside answer is only a
/// hint: its taps go through steps 3–6 of certify/certify.h (rounded; w, d,
/// δ², d_max² computed exactly; the certificate checked again by the
/// verifier), so a wrong or foreign solution can at worst fail to verify.

#include <string>

#include "core/scalar.h"
#include "data/experiment.h"
#include "certify/certify_types.h"
#include "lmi/delta_form_lmi.h"
#include "model/lpv_model.h"
#include "solvers/lmi_program.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

/// The Δ-form program of Theorem 2.1 for a fixed model and where its
/// variables are; `objective` is the one stated to the solver.
struct Theorem21Program {
  DeltaFormProgram delta;
  BoundObjective objective;
  CertifyOptions options;  ///< the options in original units (in_original_units)
};

/// Builds it (signal mode only). K = options.max_taps when 0 < K < L, else the
/// full horizon. Throws InputError for data that does not excite z.
Theorem21Program theorem21_program(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                   const CertifyOptions& options);

enum class SolutionFormat {
  kCsdp,  ///< the `csdp` program's solution file (sdpa_file.h: read_csdp_solution)
  kSdpa,  ///< the `sdpa` program's result file (read_sdpa_result; ask it for 17 digits)
};

/// An outside solver's answer as read from its files: the program it was
/// given (as written) and the text of its solution file.
struct OutsideSolution {
  LmiProgram program;
  std::string program_name, solution_name;  ///< for messages
  std::string solution_text;
  SolutionFormat format = SolutionFormat::kCsdp;
  int exit_code = 0;  ///< the outside solver's exit status (CSDP's tells optimal, infeasible, …)
};

/// Reads the program file and the outside solver's solution file for it.
/// Throws InputError for unreadable files.
OutsideSolution read_outside_solution(const std::string& program_path, const std::string& solution_path,
                                      SolutionFormat format, int exit_code);

/// Certifies the outside solution's taps (certify_with_taps). The program
/// must be the one theorem21_program builds for these inputs — else
/// InputError naming what differs; then the solution is parsed for it
/// (InputError naming file:line when it does not fit). Never throws for a
/// solution that does not verify (verified = false with the reason).
CertifiedBounds certify_outside_solution(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                         const CertifyOptions& options, const OutsideSolution& outside);

}  // namespace lpvid
