#include "model/state_scheduling.h"

#include <cmath>
#include <stdexcept>

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
  return std::ldexp(std::floor(std::ldexp(v, kSchedulingGridBits) + 0.5), -kSchedulingGridBits);
}

Rational scheduling_grid(const Rational& v) {
  // floor(v·2^b + 1/2) = floor((2·num·2^b + den) / (2·den))
  mpz_t num, den, q;
  mpz_inits(num, den, q, nullptr);
  mpz_mul_2exp(num, mpq_numref(v.mpq()), kSchedulingGridBits + 1);
  mpz_add(num, num, mpq_denref(v.mpq()));
  mpz_mul_2exp(den, mpq_denref(v.mpq()), 1);
  mpz_fdiv_q(q, num, den);
  mpq_t r;
  mpq_init(r);
  mpq_set_z(r, q);
  mpq_div_2exp(r, r, kSchedulingGridBits);
  Rational out(r);
  mpq_clear(r);
  mpz_clears(num, den, q, nullptr);
  return out;
}

double scheduling_grid_sqrt(double v) { return scheduling_grid(std::sqrt(std::abs(v))); }

Rational scheduling_grid_sqrt(const Rational& v_in) {
  // N = |v|·4^b = p/q. a = isqrt(floor(N)) = floor(√N). floor(√N + 1/2) is a + 1
  // iff √N ≥ a + 1/2 iff 4p ≥ (2a + 1)²·q (exact), else a.
  mpz_t p, q, a, lhs, rhs;
  mpz_inits(p, q, a, lhs, rhs, nullptr);
  mpz_abs(p, mpq_numref(v_in.mpq()));
  mpz_mul_2exp(p, p, 2 * kSchedulingGridBits);
  mpz_set(q, mpq_denref(v_in.mpq()));
  mpz_fdiv_q(a, p, q);
  mpz_sqrt(a, a);
  mpz_mul_2exp(lhs, p, 2);
  mpz_mul_2exp(rhs, a, 1);
  mpz_add_ui(rhs, rhs, 1);
  mpz_mul(rhs, rhs, rhs);
  mpz_mul(rhs, rhs, q);
  if (mpz_cmp(lhs, rhs) >= 0) mpz_add_ui(a, a, 1);
  mpq_t r;
  mpq_init(r);
  mpq_set_z(r, a);
  mpq_div_2exp(r, r, kSchedulingGridBits);
  Rational out(r);
  mpq_clear(r);
  mpz_clears(p, q, a, lhs, rhs, nullptr);
  return out;
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
