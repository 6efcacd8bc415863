#include "explore/long_horizon_newton_cg.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

#include "toeplitz/displacement_cholesky.h"
#include "toeplitz/fft_convolver.h"
#include "toeplitz/tap_norm_barrier.h"

namespace lpvid {

namespace {

using Vecd = Eigen::VectorXd;
using Spectrum = FftConvolver::Spectrum;

/// q̄(h) = (‖r̄_head‖² + ‖r̄_tail − A h‖²) / N in the solver's units: r̄ = r/σ_r,
/// h̄ = h/δ, A = (δ/σ_r)·Z (the tail's lower-triangular Toeplitz matrix of z),
/// so that the norm ball is ‖T_h̄‖ ≤ 1.
struct DataTerm {
  explicit DataTerm(Eigen::Index L) : conv(L) {}
  FftConvolver conv;
  Spectrum a_hat;
  Vecd r_tail;
  double head2 = 0, N = 1;

  Vecd times(const Vecd& h) const { return conv.samples(spectrum_product(a_hat, conv.spectrum(h))); }
  Vecd transpose_times(const Vecd& w) const { return conv.samples(spectrum_conj_product(a_hat, conv.spectrum(w))); }
  double value(const Vecd& h) const { return (head2 + (r_tail - times(h)).squaredNorm()) / N; }
  Vecd gradient(const Vecd& h) const { return -(2 / N) * transpose_times(r_tail - times(h)); }
  Vecd hessian_times(const Vecd& v) const { return (2 / N) * transpose_times(times(v)); }
};

/// CG on H x = b from x = 0 (the stopping rules of the header); its iterations in *its.
template <typename Apply>
Vecd conjugate_gradients(const Apply& H, const Vecd& b, const LongHorizonOptions& o, int* its, bool* converged) {
  Vecd x = Vecd::Zero(b.size()), r = b, p = b;
  double rr = r.squaredNorm();
  const double stop = o.cg_tolerance * o.cg_tolerance * rr;
  double best = rr;
  int best_at = 0;
  *converged = false;
  for (*its = 0; *its < o.max_cg; ++*its) {
    if (rr <= stop) {
      *converged = true;
      break;
    }
    const Vecd Hp = H(p);
    const double pHp = p.dot(Hp);
    if (!(pHp > 0)) break;
    const double a = rr / pHp;
    x += a * p;
    r -= a * Hp;
    // Stagnation: the residual has not reached a new minimum for 50 iterations.
    const double rr_now = r.squaredNorm();
    if (rr_now < best) {
      best = rr_now;
      best_at = *its;
    } else if (*its - best_at >= 50) {
      *converged = true;
      ++*its;
      break;
    }
    const double rr_new = r.squaredNorm();
    p = r + (rr_new / rr) * p;
    rr = rr_new;
  }
  return x;
}

struct Path {
  Vecd h;
  double mu = 0, q = 0, f = 0;  ///< f = q/μ − log det
  double factor = 8;
  int centering_steps = 0;
};

/// h + α·step for the largest α = α₀·2⁻ᵏ (k < 40) inside the ball whose f is
/// below f − c·α·slope (c = 10⁻⁴; slope 0: any decrease).
bool move_along(const DataTerm& data, Path& path, const Vecd& step, double alpha, double slope, LongHorizonAnswer& out) {
  for (int k = 0; k < 40; ++k, alpha *= 0.5) {
    const Vecd trial = path.h + alpha * step;
    double log_det = 0;
    ++out.factorisations;
    if (!displacement_log_det(trial, 1.0, &log_det)) continue;
    const double q = data.value(trial);
    const double f = q / path.mu - log_det;
    if (f < path.f - 1e-4 * alpha * slope) {
      path.h = trial;
      path.q = q;
      path.f = f;
      return true;
    }
  }
  return false;
}

std::unique_ptr<DataTerm> set_up(const Vecd& z, const Vecd& r, double delta, double* sigma_r) {
  const Eigen::Index n = z.size();
  Eigen::Index m = 0;
  while (m < n && z(m) == 0) ++m;
  const Eigen::Index L = n - m;
  *sigma_r = std::sqrt(r.squaredNorm() / static_cast<double>(n));
  if (L == 0 || !(*sigma_r > 0)) return nullptr;
  auto data = std::make_unique<DataTerm>(L);
  data->N = static_cast<double>(n);
  data->r_tail = r.tail(L) / *sigma_r;
  data->head2 = (r.head(m) / *sigma_r).squaredNorm();
  data->a_hat = data->conv.spectrum(z.tail(L) * (delta / *sigma_r));
  return data;
}

/// The Hessian formed column by column from its products (L products and
/// L² doubles, symmetrised) and factored by Cholesky in place: the
/// preconditioner of the final centering, where plain CG stagnates.
template <typename Apply>
std::unique_ptr<Eigen::MatrixXd> dense_factor(const Apply& H, Eigen::Index L) {
  auto M = std::make_unique<Eigen::MatrixXd>(L, L);
  Vecd e = Vecd::Zero(L);
  for (Eigen::Index j = 0; j < L; ++j) {
    e(j) = 1;
    M->col(j) = H(e);
    e(j) = 0;
  }
  for (Eigen::Index j = 0; j < L; ++j)
    for (Eigen::Index i = j + 1; i < L; ++i) (*M)(i, j) = (*M)(j, i) = 0.5 * ((*M)(i, j) + (*M)(j, i));
  Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(*M);  // in place: one L × L buffer
  if (llt.info() != Eigen::Success) return nullptr;
  return M;
}

/// Preconditioned CG on H x = b with the Cholesky factor of an earlier
/// Hessian (lower triangle of `factor`); stops at the relative residual
/// `tolerance` or after max_its.
template <typename Apply>
Vecd preconditioned_cg(const Apply& H, const Eigen::MatrixXd& factor, const Vecd& b, double tolerance, int max_its, int* its) {
  const auto Lf = factor.triangularView<Eigen::Lower>();
  const auto precondition = [&](const Vecd& v) -> Vecd { return Lf.transpose().solve(Lf.solve(v)); };
  Vecd x = Vecd::Zero(b.size()), r = b, zr = precondition(r), p = zr;
  double rz = r.dot(zr);
  const double stop = tolerance * tolerance * b.squaredNorm();
  for (*its = 0; *its < max_its && r.squaredNorm() > stop; ++*its) {
    const Vecd Hp = H(p);
    const double a = rz / p.dot(Hp);
    x += a * p;
    r -= a * Hp;
    zr = precondition(r);
    const double rz_new = r.dot(zr);
    p = zr + (rz_new / rz) * p;
    rz = rz_new;
  }
  return x;
}

class PathFollower {
 public:
  PathFollower(const DataTerm& data, double sigma_r, const LongHorizonOptions& o, LongHorizonAnswer& out)
      : data_(data), barrier_(data.conv.length()), sigma_r_(sigma_r), o_(o), out_(out) {}

  Path run() {
    const Eigen::Index L = data_.conv.length();
    path_.h = Vecd::Zero(L);
    path_.factor = o_.mu_factor;
    path_.q = data_.value(path_.h);
    path_.mu = std::max(data_.gradient(path_.h).norm() / static_cast<double>(L), 1e-300);
    barrier_.set_point(path_.h, 1.0);
    ++out_.factorisations;
    path_.f = path_.q / path_.mu + barrier_.value();
    follow();
    return path_;
  }

 private:
  Vecd solve(const Vecd& b, bool* converged) {
    const double mu = path_.mu;
    int its = 0;
    const Vecd x = conjugate_gradients(
        [&](const Vecd& v) -> Vecd { return data_.hessian_times(v) / mu + barrier_.hessian_times(v); }, b, o_, &its,
        converged);
    out_.cg_iterations += its;
    last_cg_ = its;
    return x;
  }

  void follow() {
    const double nu = 2.0 * static_cast<double>(data_.conv.length());
    const auto t0 = std::chrono::steady_clock::now();
    while (out_.newton_steps < o_.max_newton) {
      const Vecd g = data_.gradient(path_.h) / path_.mu + barrier_.gradient();
      bool converged = false;
      const Vecd step = solve(-g, &converged);
      const double decrement2 = -g.dot(step);
      if (converged && decrement2 <= o_.centred) {
        if (nu * path_.mu <= o_.rel_gap * path_.q) {
          out_.converged = true;
          tighten();
          return;
        }
        reduce_mu();
        continue;
      }
      ++out_.newton_steps;
      ++path_.centering_steps;
      const double alpha = decrement2 > 0.25 ? 1 / (1 + std::sqrt(decrement2)) : 1.0;
      if (!move_along(data_, path_, step, alpha, decrement2, out_)) {
        out_.message = "the line search found no decrease (Newton step " + std::to_string(out_.newton_steps) + ")";
        return;
      }
      barrier_.set_point(path_.h, 1.0);
      ++out_.factorisations;
      report(t0);
    }
    out_.message = "Newton step limit reached (" + std::to_string(o_.max_newton) + ")";
  }

  /// LongHorizonOptions::final_centering: full Newton steps at the last μ,
  /// CG to the final tolerance (no line search: the decrement is already
  /// below the centred level, where full steps converge quadratically).
  void tighten() {
    LongHorizonOptions tight = o_;
    tight.cg_tolerance = o_.final_cg_tolerance;
    tight.max_cg = std::max(o_.max_cg, 20000);
    for (int k = 0; k < o_.final_centering; ++k) {
      const Vecd g = data_.gradient(path_.h) / path_.mu + barrier_.gradient();
      int its = 0;
      bool converged = false;
      const double mu = path_.mu;
      const auto H = [&](const Vecd& v) -> Vecd { return data_.hessian_times(v) / mu + barrier_.hessian_times(v); };
      Vecd step;
      if (o_.final_dense) {
        if (!factor_) factor_ = dense_factor(H, g.size());
        if (!factor_) return;
        step = preconditioned_cg(H, *factor_, -g, o_.final_cg_tolerance, 200, &its);
      } else {
        step = conjugate_gradients(H, -g, tight, &its, &converged);
      }
      out_.cg_iterations += its;
      out_.final_decrement2 = -g.dot(step);
      if (o_.progress) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "long horizon: final centering %d, decrement^2 %.3g, CG %d", k, out_.final_decrement2, its);
        o_.progress(buf);
      }
      if (!(out_.final_decrement2 > 1e-14)) return;
      // Damped where the decrement is large (self-concordance keeps it inside).
      const double alpha = out_.final_decrement2 > 0.25 ? 1 / (1 + std::sqrt(out_.final_decrement2)) : 1.0;
      const Vecd trial = path_.h + alpha * step;
      double log_det = 0;
      ++out_.factorisations;
      if (!displacement_log_det(trial, 1.0, &log_det)) return;
      path_.h = trial;
      path_.q = data_.value(trial);
      path_.f = path_.q / path_.mu - log_det;
      barrier_.set_point(path_.h, 1.0);
      ++out_.factorisations;
      ++out_.newton_steps;
    }
  }

  /// μ ← μ/factor (adapted to the last centering), then the predictor step.
  void reduce_mu() {
    if (path_.centering_steps > o_.slow_centering) path_.factor = std::max(o_.min_mu_factor, std::sqrt(path_.factor));
    else if (path_.centering_steps <= 2) path_.factor = std::min(o_.mu_factor, path_.factor * path_.factor);
    path_.centering_steps = 0;
    bool converged = false;
    const Vecd tangent = solve(data_.gradient(path_.h) / (path_.mu * path_.mu), &converged);  // H ẋ = ∇q/μ²
    const double mu_old = path_.mu;
    path_.mu /= path_.factor;
    path_.f = path_.q / path_.mu + barrier_.value();
    if (move_along(data_, path_, (path_.mu - mu_old) * tangent, 1.0, 0.0, out_)) {
      barrier_.set_point(path_.h, 1.0);
      ++out_.factorisations;
    }
  }

  void report(std::chrono::steady_clock::time_point t0) const {
    if (!o_.progress || out_.newton_steps % 10 != 0) return;
    char buf[200];
    std::snprintf(buf, sizeof buf, "long horizon: Newton step %d, mu %.3g, dmax2 %.6g, CG %d (in all %ld), elapsed %.1f s",
                  out_.newton_steps, path_.mu, path_.q * sigma_r_ * sigma_r_, last_cg_, out_.cg_iterations,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    o_.progress(buf);
  }

  const DataTerm& data_;
  TapNormBarrier barrier_;
  double sigma_r_;
  const LongHorizonOptions& o_;
  LongHorizonAnswer& out_;
  Path path_;
  int last_cg_ = 0;
  std::unique_ptr<Eigen::MatrixXd> factor_;  ///< the final centering's preconditioner
};

/// d_max² of the taps recomputed from the original signals; the floating interior test at δ².
void finish(const Vecd& z, const Vecd& r, double delta, LongHorizonAnswer& out) {
  const Eigen::Index n = z.size();
  FftConvolver conv(n);
  Vecd taps_full = Vecd::Zero(n);
  taps_full.head(out.horizon) = out.taps;
  const Vecd w = conv.samples(spectrum_product(conv.spectrum(z), conv.spectrum(taps_full)));
  out.dmax2 = (r - w).squaredNorm() / static_cast<double>(n);
  double log_det = 0;
  out.inside = out.horizon == 0 || displacement_log_det(out.taps, delta * delta, &log_det);
}

}  // namespace

LongHorizonAnswer solve_long_horizon(const Vecd& z, const Vecd& r, double delta, const LongHorizonOptions& o) {
  if (z.size() != r.size() || z.size() == 0) throw std::invalid_argument("solve_long_horizon: z and r must be n-vectors, n > 0");
  if (!z.allFinite() || !r.allFinite() || !(delta > 0) || !std::isfinite(delta))
    throw std::invalid_argument("solve_long_horizon: non-finite data, or delta not a positive number");
  LongHorizonAnswer out;
  double sigma_r = 0;
  const std::unique_ptr<DataTerm> data = set_up(z, r, delta, &sigma_r);
  out.horizon = data ? data->conv.length() : 0;
  out.taps = Vecd::Zero(out.horizon);
  if (!data) {
    out.converged = true;
    finish(z, r, delta, out);
    out.lower_estimate = out.dmax2;
    return out;
  }
  const Path path = PathFollower(*data, sigma_r, o, out).run();
  out.taps = delta * path.h;
  out.lower_estimate = (path.q - 2.0 * static_cast<double>(out.horizon) * path.mu) * sigma_r * sigma_r;
  out.mu = path.mu * sigma_r * sigma_r;
  finish(z, r, delta, out);
  return out;
}

}  // namespace lpvid
