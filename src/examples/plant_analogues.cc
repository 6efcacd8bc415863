#include "examples/plant_analogues.h"

#include <algorithm>
#include <cmath>

#include "core/input_error.h"
#include "examples/random_stream.h"

namespace lpvid {

namespace {

constexpr double kPi = 3.14159265358979323846;

Experiment<double> experiment(const Vec<double>& u, const Vec<double>& y, const std::string& source) {
  Experiment<double> e;
  e.u = u;
  e.y = y;
  e.rho = Mat<double>(u.size(), 0);
  e.source = source;
  return e;
}

/// Random levels held for [hold_min, hold_max] samples, uniform in [lo, hi].
Vec<double> staircase(int n, double lo, double hi, int hold_min, int hold_max, RandomStream& rs) {
  Vec<double> u(n);
  for (int k = 0; k < n;) {
    const double level = lo + (hi - lo) * rs.uniform();
    const int hold = rs.uniform_int(hold_min, hold_max);
    for (int j = 0; j < hold && k < n; ++j) u(k++) = level;
  }
  return u;
}

/// The coupled-drives analogue's linear part, simulated (direct form of
/// (1 − 2r cos θ q⁻¹ + r² q⁻²)(1 − p q⁻¹) v = g q⁻¹ u).
Vec<double> resonant_third_order(const Vec<double>& u) {
  const double r = 0.96, th = 0.35, p = 0.85;
  const double a1 = -2 * r * std::cos(th), a2 = r * r;
  // (1 + a1 q⁻¹ + a2 q⁻²)(1 − p q⁻¹) = 1 + c1 q⁻¹ + c2 q⁻² + c3 q⁻³
  const double c1 = a1 - p, c2 = a2 - p * a1, c3 = -p * a2;
  const double g = (1 + c1 + c2 + c3);  // unit DC gain
  Vec<double> v = Vec<double>::Zero(u.size());
  for (Eigen::Index k = 0; k < u.size(); ++k) {
    double acc = k >= 1 ? g * u(k - 1) : 0.0;
    if (k >= 1) acc -= c1 * v(k - 1);
    if (k >= 2) acc -= c2 * v(k - 2);
    if (k >= 3) acc -= c3 * v(k - 3);
    v(k) = acc;
  }
  return v;
}

Experiment<double> abs_sensor(int n, RandomStream& rs, const std::string& role, double amplitude = 1.0) {
  // levels in [-0.8, 1.8]: about 30 % of them (and of the samples) are negative
  const Vec<double> u = amplitude * staircase(n, -0.8, 1.8, 8, 24, rs);
  const Vec<double> v = resonant_third_order(u);
  Vec<double> y(n);
  for (int k = 0; k < n; ++k) y(k) = std::round(std::abs(v(k)) / 0.005) * 0.005;
  return experiment(u, y, "abs_sensor " + role);
}

Experiment<double> tanks(int n, RandomStream& rs, const std::string& role) {
  // equilibrium h1 = h2 = (k4 u / k1)² = u²/4: 1 … 16 for u in [2, 8], so the
  // overflow at 10 acts for u > 6.3; time constants 2√h/(Ts k) = 10–40 samples
  const double ts = 1.0, k1 = 0.2, k2 = 0.2, k3 = 0.2, k4 = 0.1, top = 10.0;
  const Vec<double> u = staircase(n, 2.0, 8.0, 30, 90, rs);
  Vec<double> y(n);
  double h1 = 4.0, h2 = 4.0;
  for (int k = 0; k < n; ++k) {
    y(k) = h2 + 0.01 * rs.normal();
    const double h1n = h1 + ts * (-k1 * std::sqrt(std::max(h1, 0.0)) + k4 * u(k));
    const double h2n = h2 + ts * (k2 * std::sqrt(std::max(h1, 0.0)) - k3 * std::sqrt(std::max(h2, 0.0)));
    h1 = std::clamp(h1n, 0.0, top);  // the overflow: the upper tank cannot hold more
    h2 = std::max(h2n, 0.0);
  }
  return experiment(u, y, "tanks " + role);
}

Experiment<double> oscillator(int n, double k3, RandomStream& rs, const std::string& role) {
  const double w = 1.0, zeta = 0.1, h = 0.1, amp = 1.2;
  // random-phase multisine, 12 lines from 0.02 to 0.4 rad/sample of the 0.1 s grid... in rad/s: 0.2..4
  std::vector<double> phase(12);
  for (double& p : phase) p = 2 * kPi * rs.uniform();
  Vec<double> u(n);
  for (int k = 0; k < n; ++k) {
    double s = 0;
    for (int l = 0; l < 12; ++l) s += std::sin((0.2 + 0.3 * l) * h * k + phase[static_cast<size_t>(l)]);
    u(k) = amp * s / std::sqrt(6.0);
  }
  const auto f = [&](double x, double xd, double uk) { return uk - 2 * zeta * w * xd - w * w * x - k3 * x * x * x; };
  Vec<double> y(n);
  double x = 0, xd = 0;
  for (int k = 0; k < n; ++k) {
    y(k) = x + 0.002 * rs.normal();
    // RK4 with u held over the step
    const double a1 = xd, b1 = f(x, xd, u(k));
    const double a2 = xd + 0.5 * h * b1, b2 = f(x + 0.5 * h * a1, xd + 0.5 * h * b1, u(k));
    const double a3 = xd + 0.5 * h * b2, b3 = f(x + 0.5 * h * a2, xd + 0.5 * h * b2, u(k));
    const double a4 = xd + h * b3, b4 = f(x + h * a3, xd + h * b3, u(k));
    x += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    xd += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
  }
  return experiment(u, y, "oscillator " + role);
}

}  // namespace

const std::vector<std::string>& plant_analogue_names() {
  static const std::vector<std::string> names{"abs_sensor", "tanks", "duffing", "linear"};
  return names;
}

std::vector<Experiment<double>> abs_sensor_records(int n, const std::vector<double>& amplitudes, uint64_t seed) {
  if (n < 100) throw InputError("plant analogue: n must be at least 100 (got " + std::to_string(n) + ")");
  RandomStream rs(seed);
  std::vector<Experiment<double>> out;
  for (const double a : amplitudes) out.push_back(abs_sensor(n, rs, "record at amplitude " + std::to_string(a), a));
  return out;
}

PlantAnalogue make_plant_analogue(const std::string& name, int n, uint64_t seed) {
  if (n < 100) throw InputError("plant analogue: n must be at least 100 (got " + std::to_string(n) + ")");
  RandomStream rs(seed);
  PlantAnalogue p;
  if (name == "abs_sensor") {
    p.estimation = abs_sensor(n, rs, "estimation");
    p.test = abs_sensor(n, rs, "test");
    p.right_kinds = {"abs_value"};
  } else if (name == "tanks") {
    p.estimation = tanks(n, rs, "estimation");
    p.test = tanks(n, rs, "test");
    p.right_kinds = {"state_nonlinearity"};
  } else if (name == "duffing" || name == "linear") {
    const double k3 = name == "duffing" ? 0.6 : 0.0;
    p.estimation = oscillator(n, k3, rs, "estimation");
    p.test = oscillator(n, k3, rs, "test");
    p.right_kinds = name == "duffing" ? std::vector<std::string>{"basis_term"} : std::vector<std::string>{"none"};
  } else {
    throw InputError("plant analogue '" + name + "' is not known (abs_sensor, tanks, duffing, linear)");
  }
  return p;
}

}  // namespace lpvid
