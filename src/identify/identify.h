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
#include "data/experiment.h"
#include "toeplitz/affine_residual.h"
#include "lmi/bound_objective.h"
#include "lmi/relaxed_bmi_lmi.h"
#include "model/lpv_model.h"
#include "solvers/sdp_solver.h"
#include "toeplitz/uncertainty_toeplitz.h"

namespace lpvid {

/// How Theorem 3.1 is solved.
enum class IdentifyMethod {
  kRelaxation,   ///< the paper's linearised BMI in the w form (lmi/relaxed_bmi_lmi.h), optionally iterated
  kAlternating,  ///< block-coordinate descent in the Δ form (identify/alternating_identify.h)
};

struct IdentifyOptions {
  BoundObjective objective;
  IdentifyMethod method = IdentifyMethod::kRelaxation;
  long taps = 16;              ///< kAlternating: FIR taps K of Δ
  bool iterate = false;        ///< re-linearise until the objective stalls
  int max_iterations = 25;     ///< solves, the first included
  double rel_tol = 1e-4;       ///< stop when the objective improves by less (relative)
  Unknowns unknowns;
  SolverOptions solver;
};

/// One solve of the relaxation.
struct IterateRecord {
  int index = 0;
  double delta2 = 0, dmax2 = 0, objective = 0;
  SolveStatus status = SolveStatus::kBackendError;
  double seconds = 0;
  Vec<double> p;  ///< parameters after this solve
  Mat<double> taps;  ///< kAlternating: the Δ of this iterate (K × ny·nz); empty for kRelaxation
  Vec<double> p_delta_step;  ///< kAlternating: the p at which this iterate's Δ step was solved (the previous
                             ///< accepted iterate's p, or the least-squares start); empty for kRelaxation
};

struct IdentifyResult {
  ParameterLayout layout;
  std::vector<std::string> names;
  Vec<double> p;                      ///< final parameters (layout above)
  Mat<double> taps;                   ///< kAlternating: the Δ that goes with p (certify_with_taps)
  std::vector<IterateRecord> iterates;
  Eigen::Index pinned_samples = 0;    ///< m: z_k = 0 for k < m is kept by the relaxation (several records: Σ_k m_k)
  Eigen::Index free_directions = 0;   ///< unknowns left after pinning
  std::string relaxation;             ///< "linearised at initial model", "iterated (N solves)", "none (exact LMI)"
  SolveStatus status = SolveStatus::kBackendError;  ///< of the last solve
  std::string message;
};

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
