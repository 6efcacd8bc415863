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
// barrier objects are alive for the differences: 3·L²/2 doubles).
// Table 2: the exploratory Newton–CG path (explore/long_horizon_newton_cg.h)
// on the SISO delayed-Δ case (siso_delay_case.h) at the sizes of the third
// argument: wall time, the process's peak memory, the work counts, the d_max²
// of its taps and its floating lower estimate; at the sizes of the fourth
// also the dense path's certified interval (certify_fixed_model, both ends
// checked exactly); at the sizes of the fifth both ends certified: the path
// ends with the final centering (exact Newton steps preconditioned by the
// Hessian's factor, explore/long_horizon_newton_cg.h), the upper end is its
// taps (certify_with_taps: rounded to 12 digits, shrunk into the ball if
// needed, (C1) and (C2) checked exactly in memory), the lower end its
// central point as a compact dual certificate (certify_dual with g from
// explore/long_horizon_dual.h), each with its time; with out_dir, the data
// and both certificates are written there for `lpvid-verify`. Not a test.
// Usage: long_horizon_bench [sizes=3200,6400,10000] [delta=0.45] [newton_cg_sizes=none] [dense_sizes=none]
//                           [certify_sizes=none] [out_dir=none]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "certify/dual_certify.h"
#include "data/data_reference.h"
#include "explore/long_horizon_dual.h"
#include "explore/long_horizon_newton_cg.h"
#include "solvers/solver_factory.h"
#include "toeplitz/displacement_cholesky.h"
#include "toeplitz/tap_norm_barrier.h"
#include "bench_measure.h"
#include "case_data_file.h"
#include "siso_delay_case.h"

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

struct DenseInterval {
  double lower = NAN, upper = NAN, seconds = 0;
};

DenseInterval dense_interval(const LpvModel<Rational>& model, const Experiment<Rational>& exp, double delta) {
  DenseInterval d;
  auto solver = make_solver("csdp");
  CertifyOptions co;
  co.objective.kind = BoundObjective::Kind::kMinDmax;
  co.objective.delta = delta;
  bench::StageClock clock;
  const CertifiedBounds b = certify_fixed_model(model, exp, co, *solver);
  d.seconds = clock.wall();
  if (b.verified()) d.upper = nearest_double(b.upper);
  if (b.lower.verified()) d.lower = nearest_double(b.lower.value);
  return d;
}

/// The upper end of the structured taps, certified exactly: (d_max², seconds), NaN when not certified.
/// With `out_dir`, the data and the certificate are written there
/// (siso_<n>.csv, siso_<n>.upper.json) for `lpvid-verify`.
std::pair<double, double> certified_upper(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                                          const Eigen::VectorXd& taps, double delta, const std::string& out_dir) {
  CertifyOptions co;
  const std::string stem = out_dir.empty() ? "" : out_dir + "/siso_" + std::to_string(exp.n());
  if (!stem.empty()) {
    bench::write_case_data(stem + ".csv", model, exp);
    co.records = {read_data_table(stem + ".csv").reference};
  }
  co.objective.kind = BoundObjective::Kind::kMinDmax;
  co.objective.delta = delta;
  co.lower_end = false;
  bench::StageClock clock;
  const CertifiedBounds b = certify_with_taps(model, exp, Mat<double>(taps), co, "structured Newton-CG (exploration)");
  if (!b.verified()) std::fprintf(stderr, "  upper end not certified: %s\n", b.reason.c_str());
  if (b.verified() && !stem.empty()) write_certificates(b, stem + ".upper.json");
  return {b.verified() ? nearest_double(b.upper) : NAN, clock.wall()};
}

/// The lower end from the path's last point, certified exactly: the compact
/// dual certificate (certify_dual, form "dual_delta_path") of the central
/// point (taps, δ², μ) with g = −(r − Z h)/N, the dual of the epigraph form's
/// (C2) on the same path: the claimed lower end of d_max² and the seconds (NaN when not certified).
struct CertifiedLower {
  double value = NAN, seconds = 0;
  std::string reason;
};

CertifiedLower certified_lower(const LpvModel<Rational>& model, const Experiment<Rational>& exp,
                               const Simulation<Rational>& sim, const LongHorizonAnswer& a, double delta,
                               const std::string& out_dir) {
  const Eigen::Index n = exp.n(), L = a.horizon;
  DeltaFormSolution s;
  s.taps = Mat<double>(a.taps);
  s.horizon = L;
  s.leading_zeros = n - L;
  s.delta2 = delta * delta;
  s.dmax2 = a.dmax2;
  s.path_mu = a.mu;
  // Only Y2's first column is read by the compact builder: (1/N, g).
  const Eigen::VectorXd z = nearest_double(sim.z).col(0), r = nearest_double(Mat<Rational>(exp.y - sim.output)).col(0);
  const LongHorizonDualSignal g = long_horizon_dual_signal(z, r, a.taps, delta * delta, a.mu);
  std::fprintf(stderr, "  [n = %ld] dual signal: relative residual of the dual equality %.2e\n", static_cast<long>(n),
               g.relative_residual);
  CertifiedLower out;
  if (!g.ok) return out.reason = "no dual signal", out;
  s.dual_c2 = Mat<double>(n + 1, 1);
  s.dual_c2(0, 0) = 1.0 / static_cast<double>(n);
  s.dual_c2.col(0).tail(n) = g.g;
  CertifyOptions co;
  co.objective.kind = BoundObjective::Kind::kMinDmax;
  co.objective.delta = delta;
  if (!out_dir.empty()) co.records = {read_data_table(out_dir + "/siso_" + std::to_string(n) + ".csv").reference};
  bench::StageClock clock;
  const DualOutcome d = certify_dual(model, exp, sim, s, co);
  out.seconds = clock.wall();
  if (d.verified()) {
    out.value = nearest_double(d.bound);
    if (!out_dir.empty() && d.certificate) write_certificate_at(*d.certificate, out_dir + "/siso_" + std::to_string(n) + ".lower.json");
  } else {
    out.reason = d.reason;
    std::fprintf(stderr, "  lower end not certified: %s\n", d.reason.c_str());
  }
  return out;
}

void newton_cg_row(int n, double delta, const std::vector<int>& dense, const std::vector<int>& certify,
                   const std::string& out_dir) {
  LpvModel<Rational> model;
  Experiment<Rational> exp;
  bench::siso_delay_case(n, &model, &exp);
  const Simulation<Rational> s = simulate(model, exp);
  const Eigen::VectorXd z = nearest_double(s.z).col(0);
  const Eigen::VectorXd r = nearest_double(Mat<Rational>(exp.y - s.output)).col(0);
  LongHorizonOptions o;
  o.max_newton = 800;
  // A certified lower end needs a well centred last point: exact Newton steps at the end.
  const bool certified = std::find(certify.begin(), certify.end(), n) != certify.end();
  o.final_centering = certified ? 40 : 0;
  o.final_dense = certified;
  o.progress = [n](const std::string& line) { std::fprintf(stderr, "  [n = %d] %s\n", n, line.c_str()); };
  bench::StageClock clock;
  const LongHorizonAnswer a = solve_long_horizon(z, r, delta, o);
  const double wall = clock.wall(), peak = bench::peak_mb();
  if (!a.converged) std::fprintf(stderr, "  [n = %d] not converged: %s\n", n, a.message.c_str());
  DenseInterval d;
  if (std::find(dense.begin(), dense.end(), n) != dense.end()) d = dense_interval(model, exp, delta);
  std::pair<double, double> upper{NAN, 0.0};
  CertifiedLower lower;
  double peak_certified = NAN;
  if (certified) {
    upper = certified_upper(model, exp, a.taps, delta, out_dir);
    lower = certified_lower(model, exp, s, a, delta, out_dir);
    peak_certified = bench::peak_mb();
  }
  char dense_text[64] = "-                               ";  // the dense interval, when it was run
  if (!std::isnan(d.lower)) std::snprintf(dense_text, sizeof dense_text, "%.6e %.6e %7.1f", d.lower, d.upper, d.seconds);
  std::printf("%5d %5ld | %8.1f %7.0f %-4s | %6d %7ld %6ld | %.6e %.6e %8.1e %-6s | %s | %.9e %7.1f | "
              "%.9e %7.1f %8.1e %7.0f\n",
              n, static_cast<long>(a.horizon), wall, peak, a.converged ? "yes" : "no", a.newton_steps, a.cg_iterations,
              a.factorisations, a.dmax2, a.lower_estimate, (a.dmax2 - a.lower_estimate) / a.dmax2, a.inside ? "yes" : "NO",
              dense_text, upper.first, upper.second, lower.value, lower.seconds, (upper.first - lower.value) / upper.first,
              peak_certified);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<int> sizes = bench::int_list(argc > 1 ? argv[1] : "3200,6400,10000");
  const double delta = argc > 2 ? std::atof(argv[2]) : 0.45;
  std::printf("The structured pieces of -log det(delta^2 I - T_h T_h^T), delta = %g, taps at 0.999 of the ball's edge\n", delta);
  std::printf("    n     L | inside  sweep.s  setup.s  Hv.s     | grad.err  Hv.err    | peak.MB\n");
  for (int n : sizes) piece_row(n, delta);
  const std::vector<int> newton_cg = bench::int_list(argc > 3 ? argv[3] : "");
  const std::vector<int> dense = bench::int_list(argc > 4 ? argv[4] : "");
  const std::vector<int> certify = bench::int_list(argc > 5 ? argv[5] : "");
  const std::string out_dir = argc > 6 ? argv[6] : "";
  if (newton_cg.empty()) return 0;
  std::error_code made;
  if (!out_dir.empty() && !std::filesystem::create_directories(out_dir, made) && made) {
    std::fprintf(stderr, "long_horizon_bench: cannot create out_dir '%s' (%s)\n", out_dir.c_str(), made.message().c_str());
    return 2;
  }
  std::printf("\nExploratory Newton-CG path, min dmax^2 at delta = %g (SISO delayed-Delta case)\n", delta);
  std::printf("    n     L |   wall.s peak.MB conv | newton      CG sweeps | dmax2(h)     lower.est    gap.est  inside | "
              "dense lower  dense upper  dense.s | certified upper  cert.s | certified lower  cert.s  rel.gap peak.MB\n");
  for (int n : newton_cg) newton_cg_row(n, delta, dense, certify, out_dir);
  return 0;
}
