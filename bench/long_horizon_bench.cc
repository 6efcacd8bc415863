// The full horizon at record lengths the dense barrier cannot reach: the
// structured pieces of the SISO barrier −log det(δ²·I − T_h T_hᵀ) (Theorem
// 2.1's (C1) by a Schur complement) at the taps of edge_taps below, which sit
// at 0.999 of the norm ball's edge (F nearly singular, as at the end of a
// central path): the O(L²) displacement Cholesky sweep alone (interior test
// and log det, O(L) memory; toeplitz/displacement_cholesky.h), the barrier's
// set-up with the factor kept (factor, two solves, the generators of P = F⁻¹
// and the gradient; toeplitz/tap_norm_barrier.h), one Hessian–vector
// product, and their relative errors against central differences (step 1e-6)
// of the log det and of the gradient. Peak memory is the process's (three
// barrier objects are alive for the differences: 3·L²/2 doubles). Not a test.
// Usage: long_horizon_bench [sizes=3200,6400,10000] [delta=0.45]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "toeplitz/displacement_cholesky.h"
#include "toeplitz/tap_norm_barrier.h"
#include "bench_measure.h"

using namespace lpvid;

namespace {

/// Taps with ‖T_h‖ just inside δ: a delay of 0.48 at d plus a decaying
/// cosine, scaled by bisection on the Schur test to the ball's edge, times 0.999.
Eigen::VectorXd edge_taps(Eigen::Index L, int d, double delta) {
  Eigen::VectorXd h(L);
  for (Eigen::Index l = 0; l < L; ++l) h(l) = 0.1 * std::pow(0.99, static_cast<double>(l)) * std::cos(0.3 * static_cast<double>(l));
  if (d < L) h(d) += 0.48;
  double lo = 0, hi = 4, ld = 0;
  for (int k = 0; k < 30; ++k) {
    const double mid = 0.5 * (lo + hi);
    (displacement_log_det(mid * h, delta * delta, &ld) ? lo : hi) = mid;
  }
  return 0.999 * lo * h;
}

void piece_row(int n, double delta) {
  const Eigen::Index L = n;
  const Eigen::VectorXd h = edge_taps(L, std::min(70, n / 2), delta);
  const double t = delta * delta;
  double ld = 0;
  bench::StageClock c0;
  const bool inside = displacement_log_det(h, t, &ld);
  const double sweep = c0.wall();
  TapNormBarrier barrier(L);
  bench::StageClock c1;
  barrier.set_point(h, t);
  const double setup = c1.wall();
  Eigen::VectorXd v(L);
  for (Eigen::Index l = 0; l < L; ++l) v(l) = std::sin(0.37 * static_cast<double>(l) + 1.0) / std::sqrt(static_cast<double>(L));
  bench::StageClock c2;
  const Eigen::VectorXd Hv = barrier.hessian_times(v);
  const double hv = c2.wall();
  const double eps = 1e-6;
  double lp = 0, lm = 0;
  displacement_log_det(h + eps * v, t, &lp);
  displacement_log_det(h - eps * v, t, &lm);
  const double fd_grad = -(lp - lm) / (2 * eps), grad_v = barrier.gradient().dot(v);
  TapNormBarrier bp(L), bm(L);
  bp.set_point(h + eps * v, t);
  bm.set_point(h - eps * v, t);
  const Eigen::VectorXd fd_hv = (bp.gradient() - bm.gradient()) / (2 * eps);
  std::printf("%5d %5ld | %-6s %9.3f %9.3f %9.4f | %9.2e %9.2e | %8.0f\n", n, static_cast<long>(L), inside ? "yes" : "NO",
              sweep, setup, hv, std::fabs(grad_v - fd_grad) / std::fabs(fd_grad), (Hv - fd_hv).norm() / fd_hv.norm(),
              bench::peak_mb());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<int> sizes = bench::int_list(argc > 1 ? argv[1] : "3200,6400,10000");
  const double delta = argc > 2 ? std::atof(argv[2]) : 0.45;
  std::printf("The structured pieces of -log det(delta^2 I - T_h T_h^T), delta = %g, taps at 0.999 of the ball's edge\n", delta);
  std::printf("    n     L | inside  sweep.s  setup.s  Hv.s     | grad.err  Hv.err    | peak.MB\n");
  for (int n : sizes) piece_row(n, delta);
  return 0;
}
