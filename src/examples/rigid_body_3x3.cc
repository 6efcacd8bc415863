#include "examples/rigid_body_3x3.h"

#include <cmath>

#include "examples/decimal_rounding.h"
#include "examples/random_stream.h"

namespace lpvid {
namespace {

constexpr double kH = kRigidBodyStep;
constexpr double kDamping = 0.4;
const double kG[3] = {6.0, 4.0, 3.0};
/// The couplings N(θ, ω) = (kN1 θ2θ3, kN2 ω1ω3, kN3 θ1θ2).
constexpr double kN1 = 5.0, kN2 = 0.8, kN3 = 4.0;

Mat<double> gravity() {
  Mat<double> g = Mat<double>::Zero(3, 3);
  for (int i = 0; i < 3; ++i) g(i, i) = kG[i];
  return g;
}

Mat<double> mixing() {
  Mat<double> m(3, 3);
  m << 1, 0.2, 0, 0, 1, 0.2, 0.2, 0, 1;
  return m;
}

/// The Euler-discretised plant linearised at the origin (6 × 6, 6 × 3).
void origin_linearisation(Mat<double>& a, Mat<double>& b) {
  a = Mat<double>::Identity(6, 6);
  a.block(0, 3, 3, 3) = kH * Mat<double>::Identity(3, 3);
  for (int i = 0; i < 3; ++i) {
    a(3 + i, i) = kH * kG[i];
    a(3 + i, 3 + i) -= kH * kDamping;
  }
  b = Mat<double>::Zero(6, 3);
  b.block(3, 0, 3, 3) = kH * mixing();
}

/// Discrete LQR: iterate P ← Q + AᵀPA − AᵀPB (R + BᵀPB)⁻¹ BᵀPA to a fixed
/// point, K = (R + BᵀPB)⁻¹ BᵀPA.
Mat<double> compute_lqr_gain() {
  Mat<double> a, b;
  origin_linearisation(a, b);
  Mat<double> q = Mat<double>::Zero(6, 6);
  q.diagonal() << 10000, 10000, 10000, 100, 100, 100;
  const Mat<double> r = Mat<double>::Identity(3, 3);
  Mat<double> p = q;
  Mat<double> k;
  for (int it = 0; it < 100000; ++it) {
    k = (r + b.transpose() * p * b).ldlt().solve(b.transpose() * p * a);
    const Mat<double> next = q + a.transpose() * p * (a - b * k);
    const double change = (next - p).cwiseAbs().maxCoeff();
    p = 0.5 * (next + next.transpose());
    if (change <= 1e-12 * p.cwiseAbs().maxCoeff()) break;
  }
  return (r + b.transpose() * p * b).ldlt().solve(b.transpose() * p * a);
}

/// τ = −K_θ (θ − r) − K_ω ω − M⁻¹ diag(g) r.
Vec<double> control(const Vec<double>& theta, const Vec<double>& omega, const Vec<double>& r) {
  static const Mat<double> feed_forward = mixing().inverse() * gravity();
  const Mat<double>& k = rigid_body_lqr_gain();
  return -k.leftCols(3) * (theta - r) - k.rightCols(3) * omega - feed_forward * r;
}

/// The bracket of the ω update: g ⊙ sin θ − c ω + N(θ, ω) + diag(cos θ) M τ.
Vec<double> acceleration(const Vec<double>& theta, const Vec<double>& omega, const Vec<double>& r) {
  static const Mat<double> m = mixing();
  const Vec<double> torque = m * control(theta, omega, r);
  Vec<double> acc(3);
  for (int i = 0; i < 3; ++i) acc(i) = kG[i] * std::sin(theta(i)) - kDamping * omega(i) + std::cos(theta(i)) * torque(i);
  acc(0) += kN1 * theta(1) * theta(2);
  acc(1) += kN2 * omega(0) * omega(2);
  acc(2) += kN3 * theta(0) * theta(1);
  return acc;
}

Mat<Rational> exact_decimals(const Mat<double>& m, int digits) {
  return m.unaryExpr([digits](double x) { return round_decimal(x, digits); });
}

Experiment<Rational> rows_of(const Mat<Rational>& u, const Mat<Rational>& y, const Mat<Rational>& rho, long begin,
                             long end, const char* source) {
  Experiment<Rational> e;
  e.source = source;
  e.u = u.middleRows(begin, end - begin);
  e.y = y.middleRows(begin, end - begin);
  e.rho = rho.middleRows(begin, end - begin);
  return e;
}

}  // namespace

const Mat<double>& rigid_body_lqr_gain() {
  static const Mat<double> k = compute_lqr_gain();
  return k;
}

Vec<double> rigid_body_step(const Vec<double>& x, const Vec<double>& r) {
  const Vec<double> theta = x.head(3), omega = x.tail(3);
  Vec<double> next(6);
  next.head(3) = theta + kH * omega;
  next.tail(3) = omega + kH * acceleration(theta, omega, r);
  return next;
}

Mat<double> rigid_body_simulate(const Mat<double>& r, const Vec<double>& x0) {
  Mat<double> theta(r.rows(), 3);
  Vec<double> x = x0;
  for (Eigen::Index k = 0; k < r.rows(); ++k) {
    theta.row(k) = x.head(3).transpose();
    x = rigid_body_step(x, r.row(k).transpose());
  }
  return theta;
}

RigidBodyJacobians rigid_body_linearisation(const Vec<double>& theta, const Vec<double>& r) {
  const Mat<double> m = mixing();
  const Mat<double>& k = rigid_body_lqr_gain();
  const Vec<double> torque = m * control(theta, Vec<double>::Zero(3), r);
  Mat<double> cos_theta = Mat<double>::Zero(3, 3);
  for (int i = 0; i < 3; ++i) cos_theta(i, i) = std::cos(theta(i));
  RigidBodyJacobians j;
  j.theta = -cos_theta * m * k.leftCols(3);
  for (int i = 0; i < 3; ++i) j.theta(i, i) += kG[i] * std::cos(theta(i)) - std::sin(theta(i)) * torque(i);
  j.theta(0, 1) += kN1 * theta(2);
  j.theta(0, 2) += kN1 * theta(1);
  j.theta(2, 0) += kN3 * theta(1);
  j.theta(2, 1) += kN3 * theta(0);
  j.omega = -kDamping * Mat<double>::Identity(3, 3) - cos_theta * m * k.rightCols(3);  // ∂N/∂ω = 0 at ω = 0
  j.ref = cos_theta * (m * k.leftCols(3) - gravity());
  return j;
}

Mat<double> rigid_body_corner_points() {
  // The origin, then the corners in Gray-code order (one sign flips per step).
  const int gray[8] = {0, 1, 3, 2, 6, 7, 5, 4};
  Mat<double> p = Mat<double>::Zero(9, 3);
  for (int c = 0; c < 8; ++c)
    for (int i = 0; i < 3; ++i) p(1 + c, i) = (gray[c] >> i & 1) ? kRigidBodyRange : -kRigidBodyRange;
  return p;
}

RigidBodyParts rigid_body_experiment(const RigidBodyOptions& o) {
  RandomStream rng(o.seed);
  const Mat<double> corners = rigid_body_corner_points();
  const long n1 = corners.rows() * (o.settle + o.pulses_per_point);
  const long n2 = static_cast<long>(o.ramps) * (o.ramp + o.hold);
  const long total = n1 + n2 + o.n;
  Mat<double> star = Mat<double>::Zero(total, 3), hat = Mat<double>::Zero(total, 3);
  // Part 1: square wave of u* through the operating points, pulses in û.
  for (Eigen::Index c = 0; c < corners.rows(); ++c) {
    const long begin = c * (o.settle + o.pulses_per_point);
    for (long k = begin; k < begin + o.settle + o.pulses_per_point; ++k) star.row(k) = corners.row(c);
    for (int ch = 0; ch < 3; ++ch)
      random_pulse_train(rng, begin + o.settle, begin + o.settle + o.pulses_per_point,
                         [&](long k, bool high) { hat(k, ch) = high ? o.pulse_amplitude : -o.pulse_amplitude; });
  }
  // Part 3's u*: slowly varying (Figure 4's last section), three sinusoids.
  const long n3 = o.n;
  Mat<double> slow(n3, 3);
  const double period[3] = {720, 600, 840}, phase[3] = {-1.5707963267948966, 0, 1.5707963267948966};
  for (long k = 0; k < n3; ++k)
    for (int i = 0; i < 3; ++i)
      slow(k, i) = 0.9 * kRigidBodyRange * std::sin(6.283185307179586 * static_cast<double>(k) / period[i] + phase[i]);
  // Part 2: slow ramps of u* (û = 0) between random points, the last to part 3's start.
  Vec<double> from = corners.row(corners.rows() - 1).transpose();
  for (int j = 0; j < o.ramps; ++j) {
    Vec<double> to = slow.row(0).transpose();
    if (j + 1 < o.ramps)
      for (int i = 0; i < 3; ++i) to(i) = kRigidBodyRange * (2 * rng.uniform() - 1);
    const long begin = n1 + static_cast<long>(j) * (o.ramp + o.hold);
    for (int s = 0; s < o.ramp + o.hold; ++s) {
      const double t = s < o.ramp ? static_cast<double>(s + 1) / o.ramp : 1.0;
      star.row(begin + s) = ((1 - t) * from + t * to).transpose();
    }
    from = to;
  }
  star.bottomRows(n3) = slow;
  for (int ch = 0; ch < 3; ++ch)
    random_pulse_train(rng, n1 + n2, total,
                       [&](long k, bool high) { hat(k, ch) = high ? o.random_amplitude : -o.random_amplitude; });

  const Mat<Rational> rho = exact_decimals(star, 4), u = exact_decimals(hat, 4);
  const Mat<double> reference = nearest_double(rho) + nearest_double(u);
  const Mat<double> theta = rigid_body_simulate(reference, Vec<double>::Zero(6));
  // The noise has its own stream so that parts 1–2 do not depend on part 3's length.
  RandomStream noise(o.seed + 0x6E6F697365ULL);
  const double sigma = std::sqrt(o.noise_variance);
  Mat<Rational> y(total, 3);
  for (long k = 0; k < total; ++k)
    for (int i = 0; i < 3; ++i) {
      y(k, i) = round_decimal(theta(k, i), 10);
      if (sigma > 0) y(k, i) += round_decimal(sigma * noise.normal(), 6);
    }
  RigidBodyParts parts;
  parts.local = rows_of(u, y, rho, 0, n1, "rigid_body_3x3 part 1");
  parts.gain = rows_of(u, y, rho, n1, n1 + n2, "rigid_body_3x3 part 2");
  parts.validation = rows_of(u, y, rho, n1 + n2, total, "rigid_body_3x3 part 3");
  return parts;
}

}  // namespace lpvid
