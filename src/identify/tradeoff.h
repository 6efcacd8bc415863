#pragma once
/// The trade-off curve between the uncertainty bound δ and the noise bound
/// d_max (docs/design.md §7.6: sweeping λ gives the curve).
///
/// For each λ of a grid: identify with BoundObjective kWeighted(λ), i.e.
/// minimise λ·δ² + (1−λ)·d_max² (Theorem 3.1, relaxation at S_I or iterated),
/// round θ/φ/x0 to 12 significant digits, and certify the fixed model with the
/// same objective (Theorem 2.1, Δ form, exact check; certify.h). The curve's
/// points are the CERTIFIED (δ, d_max); a point whose certificate did not pass
/// has no bounds (verified = false) and is left out of the plot.
/// A model without unknowns (no correction basis, no unknown offset, fixed
/// x0) gives the trade-off curve of Theorem 2.1 for that fixed model.
///
/// Monotonicity. For one convex problem the minimisers of λδ² + (1−λ)d²
/// have δ non-increasing and d_max non-decreasing as λ grows (exchange
/// argument). Without `iterate` the relaxation is one convex problem, so its
/// solver values are monotone up to the solver's relative gap (1e-7). The
/// certified values re-optimise w for each rounded model; they follow the
/// same order up to the certification slack (12-digit rounding, the δ²
/// margin 1e-9…1e-1 relative, d_max² rounded up at 15 digits, the solver gap)
/// and to the fact that the models differ between λ's: the certified
/// re-optimisation can only improve on the relaxation's pair. check_monotone
/// takes the slack as a parameter; the tests use 1e-3 relative + 1e-6
/// absolute (tests/identify/tradeoff_test.cc). With `iterate` (non-convex
/// procedure) nothing is guaranteed; the CLI reports violations as notes.

#include <functional>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/experiment.h"
#include "toeplitz/affine_residual.h"
#include "certify/certify.h"
#include "identify/identify.h"
#include "model/lpv_model.h"
#include "model/problem.h"
#include "solvers/sdp_solver.h"

namespace lpvid {

/// The default grid: 11 values 0.02, 0.116, …, 0.5, …, 0.98 (step 0.096).
std::vector<double> default_lambda_grid();

struct TradeoffPoint {
  double lambda = 0;
  SolveStatus status = SolveStatus::kBackendError;  ///< of the identification (kOptimal for a fixed model)
  std::string relaxation;
  int solves = 0;                                  ///< identification solves (certification not counted)
  double delta_solver = -1, dmax_solver = -1;      ///< the relaxation's values (< 0: none)
  CertifiedBounds bounds;                          ///< verified ⇒ delta, dmax are certified
  std::string certificate;                         ///< the file the front end wrote it to (verified only)
  double seconds = 0;
  ParameterLayout layout;
  Vec<double> p;                                   ///< the rounded parameters that were certified
};

struct TradeoffOptions {
  std::vector<double> lambdas;       ///< empty: default_lambda_grid()
  bool iterate = false;
  int max_iterations = IdentifyOptions{}.max_iterations;
  double rel_tol = IdentifyOptions{}.rel_tol;
  Unknowns unknowns;
  SolverOptions solver;
  CertifyOptions certify;            ///< data reference etc.; the objective is set per point
  std::function<void(const TradeoffPoint&)> on_point;
};

/// Sweeps λ. Throws InputError for a λ outside [0, 1]. The certificates are
/// in each point's bounds; nothing is written.
std::vector<TradeoffPoint> tradeoff_curve(const Problem& problem, const TradeoffOptions& options, SdpSolver& solver);

/// λ as the CSV and the plot labels write it (shortest stream text: 0.25).
std::string lambda_text(double lambda);

/// CSV text: lambda,verified,delta,dmax,delta2_exact,dmax2_exact,delta_solver,
/// dmax_solver,status,certificate (empty cells where there is no value).
std::string tradeoff_csv(const std::vector<TradeoffPoint>& points);

/// "" if, over the verified points in order of λ, δ is non-increasing and
/// d_max non-decreasing up to rel·value + abs; else the first violation.
std::string tradeoff_monotonicity_violation(const std::vector<TradeoffPoint>& points, double rel, double abs);

}  // namespace lpvid
