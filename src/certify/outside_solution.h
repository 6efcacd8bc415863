#pragma once
/// Theorem 2.1 for a fixed model, solved by an outside SDP solver.
/// The round trip, from the README:
///
///     lpvid invalidate … --write-sdpa P.dat-s      export_theorem21_program: P.dat-s and P.dat-s.json
///     csdp P.dat-s P.sol                           any solver that reads SDPA sparse files
///     lpvid certify … --program P.dat-s --solution P.sol
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
#include "certify/certify.h"
#include "lmi/delta_form_lmi.h"
#include "model/lpv_model.h"

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

/// Writes theorem21_program to `sdpa_path` with its sidecar (solvers/sdpa_sidecar.h).
void export_theorem21_program(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                              const CertifyOptions& options, const std::string& sdpa_path);

enum class SolutionFormat {
  kCsdp,  ///< the `csdp` program's solution file (sdpa_file.h: read_csdp_solution)
  kSdpa,  ///< the `sdpa` program's result file (read_sdpa_result; ask it for 17 digits)
};

/// Reads `program_path` (must be the program theorem21_program builds for
/// these inputs — else InputError naming what differs) and the outside
/// solver's `solution_path`, and certifies its taps (certify_with_taps).
/// `exit_code` is the outside solver's exit status (CSDP's tells optimal,
/// infeasible, …). Never throws for a solution that does not verify
/// (verified = false with the reason); throws InputError for unreadable or
/// mismatched files.
CertifiedBounds certify_outside_solution(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                         const CertifyOptions& options, const std::string& program_path,
                                         const std::string& solution_path, SolutionFormat format, int exit_code = 0);

}  // namespace lpvid
