#include "toeplitz/tap_norm_barrier.h"

#include <stdexcept>

namespace lpvid {

namespace {

using Vecd = Eigen::VectorXd;

/// R u: u_s·(s + 1).
Vecd ramp_weighted(const Vecd& u) {
  Vecd out(u.size());
  for (Eigen::Index a = 0; a < u.size(); ++a) out(a) = static_cast<double>(a + 1) * u(a);
  return out;
}

/// Sᵀ p: p moved up by one (the last entry 0).
Vecd shift_up(const Vecd& p) {
  Vecd y = Vecd::Zero(p.size());
  if (p.size() > 1) y.head(p.size() - 1) = p.tail(p.size() - 1);
  return y;
}

}  // namespace

bool TapNormBarrier::set_point(const Vecd& h, double t) {
  const Eigen::Index L = conv_.length();
  if (h.size() != L) throw std::invalid_argument("TapNormBarrier: taps of another length");
  if (!chol_.factor(h, t, true)) return false;
  h_ = h;
  x_ = chol_.solve(Vecd::Unit(L, L - 1));
  p_ = chol_.solve(h);
  alpha_ = 1 / x_(L - 1);
  beta_ = 1 / (1 + h.dot(p_));
  h_hat_ = conv_.spectrum(h);
  x_hat_ = conv_.spectrum(x_);
  y_hat_ = conv_.spectrum(shift_up(p_));
  // T_hᵀ u = corr(h, u); H(u) w = corr(w, u).
  xw_hat_ = conv_.spectrum(ramp_weighted(conv_.samples(spectrum_conj_product(h_hat_, x_hat_))));
  yw_hat_ = conv_.spectrum(ramp_weighted(conv_.samples(spectrum_conj_product(h_hat_, y_hat_))));
  Spectrum g = spectrum_conj_product(xw_hat_, x_hat_);
  for (auto& s : g) s *= 2 * alpha_;
  spectrum_add(g, -2 * beta_, spectrum_conj_product(yw_hat_, y_hat_));
  gradient_ = conv_.samples(g);
  return true;
}

Vecd TapNormBarrier::inverse_times_spectrum(const Spectrum& w_hat) const {
  const Vecd hx = conv_.samples(spectrum_conj_product(w_hat, x_hat_));
  const Vecd hy = conv_.samples(spectrum_conj_product(w_hat, y_hat_));
  Spectrum out = spectrum_conj_product(conv_.spectrum(hx), x_hat_);
  for (auto& s : out) s *= alpha_;
  spectrum_add(out, -beta_, spectrum_conj_product(conv_.spectrum(hy), y_hat_));
  return conv_.samples(out);
}

Vecd TapNormBarrier::inverse_times(const Vecd& w) const { return inverse_times_spectrum(conv_.spectrum(w)); }

Vecd TapNormBarrier::uncertainty_times(const Spectrum& v_hat, const Spectrum& w_hat) const {
  // M_v w = T_v (T_hᵀ w) + T_h (T_vᵀ w); T_aᵀ w = corr(a, w).
  const Vecd hw = conv_.samples(spectrum_conj_product(h_hat_, w_hat));
  const Vecd vw = conv_.samples(spectrum_conj_product(v_hat, w_hat));
  Spectrum out = spectrum_product(v_hat, conv_.spectrum(hw));
  spectrum_add(out, 1.0, spectrum_product(h_hat_, conv_.spectrum(vw)));
  return conv_.samples(out);
}

FftConvolver::Spectrum TapNormBarrier::generator_derivative(double kappa, double dkappa, const Spectrum& u_hat,
                                                            const Spectrum& w_hat, const Spectrum& v_hat,
                                                            const Vecd& du) const {
  const Spectrum du_hat = conv_.spectrum(du);
  Spectrum inner = spectrum_conj_product(v_hat, u_hat);  // T_vᵀ u + T_hᵀ du
  spectrum_add(inner, 1.0, spectrum_conj_product(h_hat_, du_hat));
  const Spectrum w2_hat = conv_.spectrum(ramp_weighted(conv_.samples(inner)));
  Spectrum out = spectrum_conj_product(w_hat, u_hat);
  for (auto& s : out) s *= dkappa;
  spectrum_add(out, kappa, spectrum_conj_product(w_hat, du_hat));
  spectrum_add(out, kappa, spectrum_conj_product(w2_hat, u_hat));
  return out;
}

Vecd TapNormBarrier::hessian_times(const Vecd& v) const {
  const Eigen::Index L = conv_.length();
  const Spectrum v_hat = conv_.spectrum(v);
  const Vecd dx = inverse_times(uncertainty_times(v_hat, x_hat_));
  const Vecd dp = inverse_times(uncertainty_times(v_hat, conv_.spectrum(p_)) + v);
  const double dalpha = -alpha_ * alpha_ * dx(L - 1);
  const double dbeta = -beta_ * beta_ * (v.dot(p_) + h_.dot(dp));
  Spectrum out = generator_derivative(alpha_, dalpha, x_hat_, xw_hat_, v_hat, dx);
  spectrum_add(out, -1.0, generator_derivative(beta_, dbeta, y_hat_, yw_hat_, v_hat, shift_up(dp)));
  return 2 * conv_.samples(out);
}

}  // namespace lpvid
