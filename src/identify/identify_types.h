#pragma once
/// The options and the result of identification (Theorem 3.1, identify.h):
/// shared by the relaxation (identify.h) and the alternating method
/// (alternating_identify.h), so that each depends on these types and not on
/// the other.

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

}  // namespace lpvid
