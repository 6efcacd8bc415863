#pragma once
/// Exploration, not part of the product (bench/README.md, "The full horizon
/// at 10 000 samples"): the signal g of a compact dual certificate
/// (verify/certificate/path_dual.h) for a point of the long-horizon path
/// (explore/long_horizon_newton_cg.h).
///
/// The compact dual point is fixed by the taps h, t = δ² and μ through
/// U = μ·(t·I − T_h T_hᵀ)⁻¹; its dual equality asks Zᵀg = −Ω(U T_h) (Z the
/// n × L convolution with z, Ω_l the l-th subdiagonal sum), and whatever is
/// left, R = Zᵀg + Ω(U T_h), the verifier absorbs in a correction E whose
/// cost grows with ‖R‖². At a centred point of q/μ − log det(t·I − T_hT_hᵀ)
/// (q = ‖r − Z h‖²/N) stationarity reads Zᵀ(r − Z h)/N = μ·Ω((t·I − T_hT_hᵀ)⁻¹T_h),
/// so g = −(r − Z h)/N meets it. How well it does is measured here with
/// Ω(U T_h) = μ·∇B/2 from the barrier's gradient (toeplitz/tap_norm_barrier.h):
/// a point centred to a Newton decrement² of 0.05 leaves ‖R‖/‖Ω‖ ≈ 2e-3,
/// which the certificate cannot absorb; after the final centering with exact
/// Newton steps (LongHorizonOptions::final_dense) it is about 1e-9.

#include "core/scalar.h"

namespace lpvid {

struct LongHorizonDualSignal {
  Eigen::VectorXd g;                ///< n: −(r − Z h)/N
  double relative_residual = NAN;  ///< ‖Zᵀg + Ω(U T_h)‖ / ‖Ω(U T_h)‖ in floating point
  bool ok = false;                  ///< false when (t, h) is not interior or the sizes do not fit
};

/// z, r: n-vectors; h: the L taps (L ≤ n); t > ‖T_h‖²; μ > 0 (original units).
LongHorizonDualSignal long_horizon_dual_signal(const Eigen::VectorXd& z, const Eigen::VectorXd& r,
                                               const Eigen::VectorXd& h, double t, double mu);

}  // namespace lpvid
