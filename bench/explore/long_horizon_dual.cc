#include "explore/long_horizon_dual.h"

#include <cmath>

#include "toeplitz/fft_convolver.h"
#include "toeplitz/tap_norm_barrier.h"

namespace lpvid {

LongHorizonDualSignal long_horizon_dual_signal(const Eigen::VectorXd& z, const Eigen::VectorXd& r,
                                               const Eigen::VectorXd& h, double t, double mu) {
  LongHorizonDualSignal out;
  const Eigen::Index n = z.size(), L = h.size();
  if (r.size() != n || L == 0 || L > n || !(mu > 0)) return out;
  TapNormBarrier barrier(L);
  if (!barrier.set_point(h, t)) return out;
  const Eigen::VectorXd omega = 0.5 * mu * barrier.gradient();  // Ω(U T_h)
  // Z h (n samples) and Zᵀ g (the first L lags) by transforms of size ≥ 2n.
  const FftConvolver conv(n);
  const FftConvolver::Spectrum z_hat = conv.spectrum(z);
  Eigen::VectorXd padded = Eigen::VectorXd::Zero(n);
  padded.head(L) = h;
  const Eigen::VectorXd zh = conv.samples(spectrum_product(z_hat, conv.spectrum(padded)));
  out.g = -(r - zh) / static_cast<double>(n);
  const Eigen::VectorXd ztg = conv.samples(spectrum_conj_product(z_hat, conv.spectrum(out.g))).head(L);
  out.relative_residual = (ztg + omega).norm() / omega.norm();
  out.ok = true;
  return out;
}

}  // namespace lpvid
