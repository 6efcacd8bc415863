#include "model/state_scheduling.h"

#include <cmath>
#include <stdexcept>

#include "core/gmp_raii.h"
#include "core/number_text.h"

namespace lpvid {

std::vector<std::pair<int, int>> state_scheduled(const std::vector<std::string>& rho_columns, int nx) {
  std::vector<std::pair<int, int>> out;
  for (const auto& f : state_functions<Rational>(rho_columns, nx)) out.emplace_back(f.j, f.i);
  return out;
}

template <typename T>
std::vector<StateScheduled<T>> state_functions(const std::vector<std::string>& rho_columns, int nx) {
  std::vector<StateScheduled<T>> out;
  for (size_t j = 0; j < rho_columns.size(); ++j) {
    const StateColumn c = parse_state_column(rho_columns[j]);
    if (c.state < 0) continue;
    if (c.state >= nx)
      throw std::invalid_argument("scheduling column '" + rho_columns[j] + "' names state " + std::to_string(c.state + 1) +
                                  " but the model has nx = " + std::to_string(nx));
    out.push_back({static_cast<int>(j), c.state, c.function, number_from_text<T>(c.shift)});
  }
  return out;
}

template std::vector<StateScheduled<double>> state_functions<double>(const std::vector<std::string>&, int);
template std::vector<StateScheduled<Rational>> state_functions<Rational>(const std::vector<std::string>&, int);

double scheduling_grid(double v) {
  // Multiplying by an exact power of two is correctly rounded like std::ldexp
  // (x·2^b exactly, or the overflow to ±inf; x·2^−b rounded once where it is
  // subnormal), so these are ldexp's numbers without its call (a free-run
  // simulation schedules every sample on its state).
  static_assert(kSchedulingGridBits == 32, "the two constants below are 2^b and 2^-b");
  constexpr double kUp = 0x1p32, kDown = 0x1p-32;
  return std::floor(v * kUp + 0.5) * kDown;
}

Rational scheduling_grid(const Rational& v) {
  // floor(v·2^b + 1/2) = floor((2·num·2^b + den) / (2·den))
  Mpz num, den, q;
  mpz_mul_2exp(num.z, mpq_numref(v.mpq()), kSchedulingGridBits + 1);
  mpz_add(num.z, num.z, mpq_denref(v.mpq()));
  mpz_mul_2exp(den.z, mpq_denref(v.mpq()), 1);
  mpz_fdiv_q(q.z, num.z, den.z);
  Mpq r;
  mpq_set_z(r.q, q.z);
  mpq_div_2exp(r.q, r.q, kSchedulingGridBits);
  return Rational(r.q);
}

double scheduling_grid_sqrt(double v) { return scheduling_grid(std::sqrt(std::abs(v))); }

Rational scheduling_grid_sqrt(const Rational& v_in) {
  // N = |v|·4^b = p/q. a = isqrt(floor(N)) = floor(√N). floor(√N + 1/2) is a + 1
  // iff √N ≥ a + 1/2 iff 4p ≥ (2a + 1)²·q (exact), else a.
  Mpz p, q, a, lhs, rhs;
  mpz_abs(p.z, mpq_numref(v_in.mpq()));
  mpz_mul_2exp(p.z, p.z, 2 * kSchedulingGridBits);
  mpz_set(q.z, mpq_denref(v_in.mpq()));
  mpz_fdiv_q(a.z, p.z, q.z);
  mpz_sqrt(a.z, a.z);
  mpz_mul_2exp(lhs.z, p.z, 2);
  mpz_mul_2exp(rhs.z, a.z, 1);
  mpz_add_ui(rhs.z, rhs.z, 1);
  mpz_mul(rhs.z, rhs.z, rhs.z);
  mpz_mul(rhs.z, rhs.z, q.z);
  if (mpz_cmp(lhs.z, rhs.z) >= 0) mpz_add_ui(a.z, a.z, 1);
  Mpq r;
  mpq_set_z(r.q, a.z);
  mpq_div_2exp(r.q, r.q, kSchedulingGridBits);
  return Rational(r.q);
}

namespace {

template <typename T>
T state_function_value_t(StateFunction f, const T& x, const T& shift) {
  const T d = x - shift;
  switch (f) {
    case StateFunction::kState: return scheduling_grid(x);
    case StateFunction::kAbs: return scheduling_grid(d < T(0) ? T(-d) : d);
    case StateFunction::kSqrt: return scheduling_grid_sqrt(d);
    case StateFunction::kHinge: return scheduling_grid(d > T(0) ? d : T(0));
    case StateFunction::kSqrtPos: return scheduling_grid_sqrt(d > T(0) ? d : T(0));
  }
  throw std::invalid_argument("unknown state function");
}

}  // namespace

double state_function_value(StateFunction f, double x, double shift) { return state_function_value_t(f, x, shift); }
Rational state_function_value(StateFunction f, const Rational& x, const Rational& shift) {
  return state_function_value_t(f, x, shift);
}

std::string state_column_text(StateFunction f, int state, double shift) {
  const std::string x = "x" + std::to_string(state + 1);
  if (f == StateFunction::kState) {
    if (shift != 0) throw std::invalid_argument("state_column_text: '@" + x + "' has no shift");
    return "@" + x;
  }
  if (!std::isfinite(shift)) throw std::invalid_argument("state_column_text: the shift is not finite");
  const std::string c = double_to_text(std::abs(shift));
  return "@" + std::string(to_string(f)) + "(" + x + (shift < 0 ? "+" : "-") + c + ")";
}

}  // namespace lpvid
