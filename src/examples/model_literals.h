#pragma once
/// Writing the known example systems in code: exact decimal literals, small
/// matrices of them, and the SISO one-scheduling-variable skeleton shared by
/// the Example 2 flavour (eq. 20) and the effect cases (examples/effect_cases.h).

#include <initializer_list>

#include "core/number_text.h"
#include "core/scalar.h"
#include "model/lpv_model.h"

namespace lpvid::literals {

/// The exact rational of a decimal text such as "-0.24".
inline Rational dec(const char* text) { return rational_from_text(text); }

/// rows × cols matrix of decimal texts, row-major.
inline Mat<Rational> mat(int rows, int cols, std::initializer_list<const char*> values) {
  Mat<Rational> m(rows, cols);
  auto it = values.begin();
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) m(i, j) = dec(*it++);
  return m;
}

/// The monomials 1, ρ1 and ρ1² of one scheduling variable.
inline const Monomial kOne{{0}}, kRho{{1}}, kRho2{{2}};

/// An empty model with 2 states, input u1, output y1 and scheduling rho1
/// (columns of the same names); A, B, C, D sized and without terms.
inline LpvModel<Rational> siso_rho1_skeleton() {
  LpvModel<Rational> m;
  m.nx = 2;
  m.nu = m.ny = 1;
  m.scheduling = {"rho1"};
  m.columns = {{"u1"}, {"y1"}, {"rho1"}};
  m.A = ParamMatrix<Rational>(2, 2);
  m.B = ParamMatrix<Rational>(2, 1);
  m.C = ParamMatrix<Rational>(1, 2);
  m.D = ParamMatrix<Rational>(1, 1);
  m.x0 = Vec<Rational>::Zero(2);
  return m;
}

}  // namespace lpvid::literals
