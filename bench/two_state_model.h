#pragma once
// The stable 2-state LPV system of the identification benches: ny = nu = m,
// scheduling rho1, A(ρ) = A0 + ρ1·A1, B, C constant, D = 0, x0 = 0, no
// correction basis (the caller adds one and, for the truth, its terms).
#include <string>

#include "core/decimal_rounding.h"
#include "model/lpv_model.h"

namespace lpvid::bench {

inline LpvModel<Rational> two_state_model(int m) {
  const auto dec = [](double x) { return round_to_digits(x, 6); };
  LpvModel<Rational> t;
  t.nx = 2;
  t.nu = t.ny = m;
  t.scheduling = {"rho1"};
  for (int i = 0; i < m; ++i) {
    t.columns.u.push_back("u" + std::to_string(i + 1));
    t.columns.y.push_back("y" + std::to_string(i + 1));
  }
  t.columns.rho = {"rho1"};
  Mat<Rational> A(2, 2), A1(2, 2), B(2, m), C(m, 2);
  A << dec(0), dec(1), dec(-0.5), dec(1.2);
  A1 << dec(0), dec(0), dec(0.1), dec(0);
  for (int i = 0; i < m; ++i) {
    B(0, i) = dec(i == 0 ? 0.0 : 0.5);
    B(1, i) = dec(1.0);
    C(i, 0) = dec(1.0);
    C(i, 1) = dec(0.5 * (i + 1));
  }
  t.A = ParamMatrix<Rational>(2, 2);
  t.A.add(Monomial{{0}}, A);
  t.A.add(Monomial{{1}}, A1);
  t.B = ParamMatrix<Rational>(2, m);
  t.B.add(Monomial{{0}}, B);
  t.C = ParamMatrix<Rational>(m, 2);
  t.C.add(Monomial{{0}}, C);
  t.D = ParamMatrix<Rational>(m, m);
  t.x0 = Vec<Rational>::Zero(2);
  return t;
}

}  // namespace lpvid::bench
