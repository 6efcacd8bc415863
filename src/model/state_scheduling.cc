#include "model/state_scheduling.h"

#include <cmath>
#include <stdexcept>

namespace lpvid {

std::vector<std::pair<int, int>> state_scheduled(const std::vector<std::string>& rho_columns, int nx) {
  std::vector<std::pair<int, int>> out;
  for (size_t j = 0; j < rho_columns.size(); ++j) {
    const int i = state_scheduling_index(rho_columns[j]);
    if (i < 0) continue;
    if (i >= nx)
      throw std::invalid_argument("scheduling column '" + rho_columns[j] + "' names state " + std::to_string(i + 1) +
                                  " but the model has nx = " + std::to_string(nx));
    out.emplace_back(static_cast<int>(j), i);
  }
  return out;
}

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

}  // namespace lpvid
