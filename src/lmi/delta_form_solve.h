#pragma once
/// The one entry to Theorem 2.1's Δ form in floating point (eq. 11–12 with
/// w = Δ ∗ z, docs/design.md §7.5): which solver runs, and the fall-back between them.
///
///  - kStructured: on the full horizon (taps = 0) and where the structured
///    barrier applies (lmi/delta_form_barrier.h: ny = nz = 1), the barrier;
///    on its numerical failure the SDP backend solves the same program (the
///    message says so). Otherwise as kSdp.
///  - kSdp: the K-tap (or full-horizon, taps = 0) SDP of lmi/delta_form_lmi.h.
///  - kKyp: ‖Δ‖_∞ by the bounded real lemma (lmi/delta_kyp_lmi.h), K taps;
///    ‖Δ‖_∞ ≥ ‖T_Δ‖ on any horizon, so its taps give the same certificate.
/// Every answer is a DeltaFormSolution in original units.

#include <functional>
#include <string>
#include <utility>

#include "core/scalar.h"
#include "lmi/bound_objective.h"
#include "lmi/delta_form_lmi.h"
#include "solvers/sdp_solver.h"
#include "toeplitz/record_segments.h"

namespace lpvid {

enum class DeltaFormMethod { kStructured, kSdp, kKyp };

/// z (n × nz) and r = y − ŷ − Φ (n × ny) as doubles, converted once from
/// the exact signals.
struct DeltaFormSignals {
  DeltaFormSignals() = default;
  DeltaFormSignals(Mat<double> z_in, Mat<double> r_in, RecordLengths records_in = {})
      : z(std::move(z_in)), r(std::move(r_in)), records(std::move(records_in)) {}
  Mat<double> z, r;
  /// The lengths of the records stacked in z and r (toeplitz/record_segments.h;
  /// each from rest for Δ, Δ∗z record by record); empty: one record of all
  /// rows. Several records are not available with kKyp (std::invalid_argument).
  RecordLengths records;
};

struct DeltaFormRequest {
  DeltaFormMethod method = DeltaFormMethod::kStructured;
  long taps = 0;  ///< K; 0: the full horizon L = n − (leading zero samples of z); records: records_horizon
  SolverOptions solver;
  std::function<void(const std::string&)> progress;  ///< one line per solve and fall-back; unset: silent
  /// Free regressors G ((n·ny) × P, stacked like r; lmi/free_regressors.h):
  /// d = r − Δ∗z − G q with q free. 0 columns: none. Not for kKyp
  /// (std::invalid_argument).
  Mat<double> free_regressors;
};

DeltaFormSolution solve_delta_form(const DeltaFormSignals& signals, const BoundObjective& objective,
                                   const DeltaFormRequest& request, SdpSolver& solver);

}  // namespace lpvid
