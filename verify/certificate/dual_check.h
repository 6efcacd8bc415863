#pragma once
/// Exact check of a dual certificate (claims "invalidated" and "lower_bound";
/// toeplitz/delta_form_dual.h, docs/dual_certificates.md). Called by
/// check_certificate after it has rebuilt the data and z, r exactly
/// (steps 1–3 of certificate_check.h); then:
///  4. the horizon is L = n − m, m = the leading zero samples of the exact z
///     (so the dual covers every tap that acts on the data);
///  5. σ > 0; Y2 = (1/σ)[σ; g][σ; g]ᵀ is then PSD by construction;
///  6. the dual equality Ω_l(W) = C_l(g) holds exactly for l = 0 … L−1;
///  7. the bound is computed exactly (dual_bound) and must be > 0 for
///     "invalidated", ≥ the claimed lower_bound for "lower_bound";
///  8. Y1 ⪰ 0, decided exactly (verify/psd/exact_psd.h: filter, then exact).
/// No floating point decides anything; any failure is "invalid" with the
/// constraint and the numbers.

#include "core/scalar.h"
#include "data/experiment.h"
#include "model/simulate.h"
#include "toeplitz/record_segments.h"
#include "verify/certificate/certificate.h"
#include "verify/certificate/certificate_verdict.h"

namespace lpvid {

/// Steps 6–8 of the compact form (verify/certificate/path_dual.h) on the grid
/// matrix Ũ (U = Ũ·2^e) rebuilt from c.dual.path: check_dual_claim passes
/// path_dual_grid's; a test passes another rebuild (a U with other last
/// bits, as a verifier compiled elsewhere would make). `r` = y − ŷ − Φ;
/// `records` the lengths of stacked records (empty: one record).
CertificateVerdict check_path_dual_on_grid(const Certificate& c, const Simulation<Rational>& sim, const Mat<Rational>& r,
                                           const Mat<double>& U_grid, std::string details,
                                           const RecordLengths& records = {});

CertificateVerdict check_dual_claim(const Certificate& c, const Experiment<Rational>& exp, const Simulation<Rational>& sim,
                                    std::string details);

}  // namespace lpvid
