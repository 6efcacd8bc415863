#pragma once
/// From a solver's dual matrices to an exactly checked dual certificate
/// (the mathematics in toeplitz/delta_form_dual.h and
/// docs/dual_certificates.md), in the spirit of Peyrl & Parrilo (2008):
///  1. take Y1, Y2 of the Δ-form solve in original units (any positive
///     scale; a restricted K-tap solve gives a Y1 of the full size too);
///  2. normalise the scale, round g and Y1 to a decimal grid (`digits`
///     significant digits of the largest entry);
///  3. project onto the dual equality Ω_l(W) = C_l(g) exactly: the residual
///     E_l is spread evenly over the L − l blocks of the l-th block
///     subdiagonal of W (the least-squares correction). For a restricted
///     solve the taps l ≥ K had no equality at all: the same projection
///     lifts the point to the full horizon;
///  4. add ε·I to Y1, ε growing ×10 from the floating estimate of
///     max(0, −λ_min) plus the rigorous filter's shift until the filter of
///     verify/psd/psd_filter.h proves Y1 ≻ 0;
///  5. choose σ (Y2 = (1/σ)[σ; g][σ; g]ᵀ) to maximise the bound;
///  6. compute the bound exactly; build the certificate and check it again
///     with the verifier after a round trip through its JSON text (in
///     memory; no file is written).

#include <optional>
#include <string>

#include "core/scalar.h"
#include "data/experiment.h"
#include "certify/certify_types.h"
#include "certify/path_dual_build.h"
#include "lmi/delta_form_lmi.h"
#include "model/lpv_model.h"
#include "model/simulate.h"

namespace lpvid {

/// A dual certificate's outcome.
struct DualOutcome {
  /// Set once, by the exact check of the built certificate; undecided until then.
  enum class Status { kNotChecked, kHolds, kFails };
  Status status = Status::kNotChecked;
  bool verified() const { return status == Status::kHolds; }  ///< the certificate was checked exactly and holds
  std::string reason;            ///< why not
  Rational bound;                ///< the claimed number: invalidation margin (> 0) or the lower end on the objective
  double seconds = 0;            ///< building + checking
  double check_seconds = 0;      ///< of that, the exact checks
  std::string verifier_details;
  std::optional<Certificate> certificate;  ///< only when verified
  std::string note;              ///< why the compact form was not used (when it was tried)
};

/// Steps 2–6 for the dual matrices of a Δ-form solve (s.dual_c1: L·(ny+nz)
/// square, s.dual_c2: (n·ny+1) square, original units). When they come from
/// the structured barrier's central path (s.path_mu > 0) the compact form
/// "dual_delta_path" (verify/certificate/path_dual.h: size linear in n) is tried first,
/// the dense form "dual_delta" when it fails or `o.dense_dual`.
/// `objective` says which claim: kFeasibility → "invalidated" (the fixed δ,
/// d_max are the exact texts of `o`), the others → "lower_bound" on the
/// objective (δ², d_max² or λδ² + (1−λ)d_max²). Nothing is written (the
/// certificate is returned). Never throws for a failed construction (verified =
/// false with the reason).
DualOutcome certify_dual(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                         const Simulation<Rational>& sim, const DeltaFormSolution& s, const CertifyOptions& o);

}  // namespace lpvid
