#pragma once
/// Theorem 3.1 again, after diagnosis (docs/design.md §9.4): on a bound
/// window, the fitted model's output map is identified robustly. The
/// correction S_C (eq. 10) gets the basis {1} ∪ {the basis terms the model
/// has in C, D}, its C_i, D_i are unknowns on top of the least-squares
/// values, x0 is free; the solver is the alternating Δ/θ method
/// (identify/alternating_identify.h), whose iterates are feasible for the
/// true BMI, and the result is certified exactly (certify/certify.h).
///
/// Not applicable with a static output map (the output is then not affine
/// in θ) or a model without states and inputs; `why_not` says so.

#include <string>
#include <vector>

#include "data/experiment_views.h"
#include "diagnose/window_bounds.h"
#include "identify/identify.h"

namespace lpvid {

struct WindowIdentification {
  bool applicable = false;
  std::string why_not;
  /// Set when the stage threw (a solver or numeric failure): the reason, in
  /// words. diagnose() keeps every finished result and reports this one.
  std::string failed;
  std::vector<std::string> basis;  ///< the correction basis (texts)
  /// The window's rows in their file (file empty: data made in memory).
  DataReference rows;
  IdentifyResult result;
  WindowBounds bounds;             ///< the identified model's certified bounds on the window
};

WindowIdentification identify_on_window(const LpvModel<double>& fitted, const ExperimentViews& est, Eigen::Index begin,
                                        Eigen::Index end, const CertifyOptions& options,
                                        SdpSolver& solver);

/// identify_on_window, as an optional stage: an exception (a diverging free
/// run, a solver or numeric failure) becomes `failed` = "the optional Theorem
/// 3.1 stage failed: <reason>" instead of ending the caller's work.
WindowIdentification try_identify_on_window(const LpvModel<double>& fitted, const ExperimentViews& est,
                                            Eigen::Index begin, Eigen::Index end,
                                            const CertifyOptions& options, SdpSolver& solver);

/// Theorem 3.1 starts from the fitted model (θ = 0, x0 its state at the
/// window's first row), which meets the window's own Theorem 2.1 bounds; an
/// identified δ or d_max above kReidentificationWorseFactor times the
/// window's own ends far from that start (a poor alternating run, seen on a
/// measured record at d_max 1e25 for a window bound of 0.07). Such a result
/// is true (it was certified) but says less than the window's bound: the
/// stage is reported as failed, the window's bound stands.
inline constexpr double kReidentificationWorseFactor = 10;

/// Sets `id.failed` (and drops its bounds and certificate) when a verified
/// δ or d_max of `id` exceeds kReidentificationWorseFactor times the verified
/// bound of `own`, the same model's Theorem 2.1 window on the same rows.
void judge_against_window(WindowIdentification& id, const WindowBounds& own);

}  // namespace lpvid
