#pragma once
/// Identification, Theorem 3.1 (docs/design.md §8): the correction S_C(ρ) (eq. 10),
/// the offset φ (eq. 20) and optionally x0, with the smallest consistent
/// bounds, by the paper's relaxation (one linearisation at the initial
/// model, after eq. 16) or, with `iterate`, by re-linearising at each
/// solution (convex–concave procedure; beyond the paper).
///
/// Every iterate is feasible for the true BMI (Lin ⪯ T_zᵀT_z), and the
/// objective never increases: the previous solution is feasible for the next
/// relaxation. The bounds reported here are the SOLVER's; the certified
/// bounds come from certify.h, which re-solves the fixed final model in the
/// Δ form and checks it exactly.

#include <string>
#include <vector>

#include "core/scalar.h"
#include "identify/identify_types.h"
#include "data/experiment.h"
#include "toeplitz/affine_residual.h"
#include "lmi/bound_objective.h"
#include "lmi/relaxed_bmi_lmi.h"
#include "model/lpv_model.h"
#include "solvers/sdp_solver.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid {

/// Runs the identification (options.method picks the algorithm; several
/// records (exp.records): always the alternating method, whose Δ steps run
/// over the records, the relaxation text saying so). Throws InputError for ill-posed data (z ≡ 0),
/// paper mode (not supported for identification) or no unknowns.
IdentifyResult identify(const LpvModel<double>& model, const Experiment<double>& exp, const IdentifyOptions& options,
                        SdpSolver& solver);

/// The affine signals in q-coordinates (p = N q) that identify() solves with:
/// exposed for --write-sdpa and for tests.
struct ReducedProblem {
  AffineResidual<double> residual;
  Mat<double> N;  ///< P × Q basis of the directions that keep pinned samples at zero
  Eigen::Index pinned = 0;  ///< pinned samples: each record's leading zero samples of z0, summed
  AffineSignals signals;
};
ReducedProblem reduce_problem(const LpvModel<double>& model, const Experiment<double>& exp, const Unknowns& unknowns);

}  // namespace lpvid
