#pragma once
/// The options and the result of certifying Theorem 2.1 for a fixed model
/// (certify/certify.h runs it): what the certifying stages (upper end, lower
/// end, invalidation, outside solutions) share, so that each of them depends
/// on these types and not on the dispatcher.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/scalar.h"
#include "data/data_reference.h"
#include "data/experiment.h"
#include "certify/bound_scaling.h"
#include "lmi/bound_objective.h"
#include "solvers/sdp_solver.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {

/// How step 2 bounds ‖T_Δ‖ (the certificate is the same either way).
enum class DeltaNorm {
  kToeplitz,  ///< (C1'): the L·(ny+nz) block of delta_form_lmi.h (exact for K = L)
  kKyp,       ///< (KYP): ‖Δ‖_∞ by the bounded real lemma, delta_kyp_lmi.h (small, needs K > 0)
};

struct CertifyOptions {
  BoundObjective objective;
  SolverOptions solver;
  int digits = 12;                       ///< significant digits of rounded taps
  long max_taps = 64;                    ///< K (0: the full horizon); see solve_delta_form
  DeltaNorm delta_norm = DeltaNorm::kToeplitz;
  /// Where each record of the experiment came from (file, sha256, names,
  /// rows), one per record in the order of Experiment::records, made where
  /// the data was read and copied into every certificate. Empty: an
  /// experiment made in memory, whose certificates name no data.
  std::vector<DataReference> records;
  /// Also certify the lower end of the optimum (a dual certificate of the
  /// full-horizon problem: CertifiedBounds::lower), and for fixed bounds,
  /// when no primal certificate exists, try to certify "invalidated"
  /// (CertifiedBounds::certificate). Signal mode only.
  bool lower_end = true;
  /// If the certified interval's relative gap is above this after the
  /// K-tap solve and the horizon is at most full_horizon_limit, the
  /// full-horizon program is solved too (its primal may lower the upper end,
  /// its dual raises the lower end). A restricted solve never decides a verdict.
  double gap_target = 0.01;
  /// SISO models: solve the full horizon with the structured barrier
  /// (lmi/delta_form_barrier.h) instead of the K-tap SDP first (max_taps is
  /// then unused); if the barrier fails numerically, the SDP backend solves
  /// the full horizon.
  bool structured = true;
  /// Write lower-end / invalidation certificates in the dense form (the full
  /// dual matrix Y1) even when the compact form (verify/certificate/path_dual.h) applies.
  bool dense_dual = false;
  /// Called with a short line at each stage (solve, fallback, upper end,
  /// lower end); the CLI prints them on stderr. Unset: silent.
  std::function<void(const std::string&)> progress;
  long full_horizon_limit = 400;
  /// A weighted objective λδ² + (1−λ)d_max² is meant for z and y scaled by
  /// powers of ten to RMS ~1 (certify/bound_scaling.h); the certificate
  /// stays in original units. Other objectives are unaffected.
  bool scale_signals = false;
};

/// The objective at (δ², d_max²), exactly: δ², d_max², λδ² + (1−λ)d_max² (λ
/// read as the exact decimal of its shortest text), 0 for fixed bounds.
Rational objective_at(const BoundObjective& objective, const Rational& delta2, const Rational& dmax2);

/// How a certification ended (typed, so that callers never compare
/// status strings). Decided in this order:
enum class CertifyOutcome {
  kVerified,      ///< a consistency certificate was made and checked exactly
  kInvalidated,   ///< fixed bounds: an "invalidated" certificate was made and checked exactly
  kUndecided,     ///< no certificate passed the exact check (yet): the initial value;
                  ///< for fixed bounds, the final one when neither certificate passed
  kSolverFailed,  ///< the SDP backend failed (backend error, iteration limit): no bound
  kNotVerified,   ///< the solver answered, but the exact check did not accept its bounds
};
const char* to_string(CertifyOutcome outcome);

/// How the lower end of an optimised bound ended.
enum class LowerEndOutcome {
  kNotTried,      ///< no dual certificate was attempted (fixed bounds, lower_end off, no solve): the initial value
  kCertified,     ///< a dual certificate was made and checked exactly
  kNotCertified,  ///< attempted, none passed: CertifiedBounds::LowerEnd::reason says why
};

struct CertifiedBounds {
  /// How it ended: the one stored status. Undecided until a certificate
  /// passes (kVerified, kInvalidated); the certifying function then decides
  /// the rest (outcome_of). Front ends map it to their exit codes.
  CertifyOutcome outcome = CertifyOutcome::kUndecided;
  /// A consistency certificate was made and checked exactly.
  bool verified() const { return outcome == CertifyOutcome::kVerified; }
  /// Fixed bounds only: an "invalidated" certificate was made and checked
  /// exactly (then it is `certificate`).
  bool invalidated() const { return outcome == CertifyOutcome::kInvalidated; }
  std::string reason;           ///< why not verified
  Rational delta2, dmax2;       ///< the certificate's values
  double delta = 0, dmax = 0;   ///< √ of the above, rounded up (for display)
  double delta2_solver = 0;     ///< the Δ-form solver's δ² before the margin
  double margin = 0;            ///< relative inflation of δ² that passed
  long taps = 0, horizon = 0;
  /// The status of the solve whose answer was certified; none when no solve
  /// ran here (given taps: certify_with_taps).
  std::optional<SolveStatus> solve_status;
  /// Not empty when the bounds were found in closed form, with no solve
  /// (certify/closed_form.h), e.g. "closed form (delta = 0)": reports show
  /// it where they name the solver.
  std::string closed_form;
  /// What solved the program whose answer was certified (upper end): the
  /// structured barrier or the SDP backend (DeltaFormSolution::solver_used);
  /// empty when no solve ran here. Reports name it as the solver.
  std::string solver_used;
  /// Why a solve of this certification fell back from the structured
  /// barrier to the SDP backend (DeltaFormSolution::fallback, "; "-joined);
  /// empty when none did. Reports and progress lines show it.
  std::string fallback;
  /// Where the time went (wall-clock seconds, summed over every solve and
  /// certificate of this call, also those not kept): the exact simulation
  /// and residual (step 1), the solves (step 2), building the upper end's
  /// certificate (steps 3–5 without the check) and its exact check (step 6,
  /// once per margin tried). The lower end's are in `lower`.
  double signals_seconds = 0, solve_seconds = 0, upper_build_seconds = 0, verify_seconds = 0;
  std::string verifier_details;

  /// The checked certificate: "consistent" when verified, "invalidated" when
  /// invalidated; none otherwise.
  std::optional<Certificate> certificate;
  /// The certified interval [lower, upper] of the objective (δ², d_max², or
  /// λδ² + (1−λ)d_max²; upper from the primal certificate, lower from the dual one).
  struct LowerEnd {
    /// How the lower end ended: the one stored status (not tried until the
    /// dual stage runs; certify_fixed_model decides it).
    LowerEndOutcome outcome = LowerEndOutcome::kNotTried;
    /// A dual certificate of the lower end was made and checked exactly.
    bool verified() const { return outcome == LowerEndOutcome::kCertified; }
    std::string reason;       ///< why there is no certified lower end
    Rational value;           ///< the certified lower end on the objective
    std::optional<Certificate> certificate;  ///< its checked certificate ("lower_bound")
    /// Building and checking the dual certificates (also an invalidation
    /// certificate's), and of that the exact checks alone.
    double seconds = 0, check_seconds = 0;
    std::string verifier_details;
  } lower;
  Rational upper;             ///< the objective at the primal certificate (when verified)
  bool full_horizon = false;  ///< the certificates come from a full-horizon solve (K = L)
  double total_seconds = 0;   ///< the whole certifying call
  SignalScales scales;        ///< with CertifyOptions::scale_signals: the scales and λ in original units
};

/// Names the data of a certificate made by certification with `o` on `exp`:
/// one reference per record of `exp` (several: each with its own x0); none
/// when `o.records` is empty. Throws std::invalid_argument when the counts differ.
void name_certificate_data(Certificate& c, const CertifyOptions& o, const Experiment<Rational>& exp);

/// Step 2's objective as the solver gets it: fixed bounds tightened by a
/// relative 1e-7, so that rounding the taps does not push the exact values
/// over them.
BoundObjective solver_objective(BoundObjective objective);

/// The outcome of `b` for `objective`, in the order above (every certifying
/// function stores it in CertifiedBounds::outcome).
CertifyOutcome outcome_of(const CertifiedBounds& b, const BoundObjective& objective);
/// The status text of reports and certificates: the solve's status
/// (to_string(SolveStatus)), "given taps (no solve)", or for a closed form
/// "no solve: <how>".
std::string solve_status_text(const CertifiedBounds& b);

/// `into` also counts the time of a certification `from` that it replaces
/// or that ran beside it (signals, solves, upper end, total; not `lower`).
void add_stage_seconds(CertifiedBounds& into, const CertifiedBounds& from);

/// Relative gap (upper − lower)/upper of a certified interval (0 when upper = 0).
double relative_gap(const CertifiedBounds& b);

}  // namespace lpvid
