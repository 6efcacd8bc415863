#include "diagnose/cascade_form.h"

#include <cmath>

#include "fit/model_parameters.h"
#include "model/state_scheduling.h"

namespace lpvid {

LpvModel<double> similarity_transform(const LpvModel<double>& m, const Mat<double>& T) {
  const Mat<double> Ti = T.inverse();
  LpvModel<double> r = m;
  for (auto& t : r.A.terms) t.value = T * t.value * Ti;
  for (auto& t : r.B.terms) t.value = T * t.value;
  for (auto& t : r.C.terms) t.value = t.value * Ti;
  for (auto& a : r.correction.A)
    if (a.size() != 0) a = T * a * Ti;
  for (auto& b : r.correction.B)
    if (b.size() != 0) b = T * b;
  if (r.x0.size() == m.nx) r.x0 = T * m.x0;
  for (auto& x : r.later_x0)
    if (x.size() == m.nx) x = T * x;
  return r;
}

std::vector<LpvModel<double>> cascade_realisations(const LpvModel<double>& m) {
  if (m.nx != 2 || m.A.terms.size() != 1 || !m.A.terms[0].basis.is_constant()) return {};
  for (const auto& t : m.B.terms)
    if (!t.basis.is_constant()) return {};
  if (!state_scheduled(m.columns.rho, m.nx).empty() || !m.state_offset.empty()) return {};
  if (m.uncertainty.structure == UncertaintyStructure::kGeneral) return {};
  const Mat<double>& A = m.A.terms[0].value;
  if (!observer_shaped(A)) return {};
  const double a1 = -A(0, 0), a2 = -A(1, 0);
  const double disc = a1 * a1 - 4 * a2;
  if (!(disc >= 0)) return {};
  const double s = std::sqrt(disc);
  const double p[2] = {(-a1 + s) / 2, (-a1 - s) / 2};
  std::vector<LpvModel<double>> out;
  for (int k = 0; k < 2; ++k) {
    const double pu = p[k], pd = p[1 - k];
    if (!(std::abs(1 - pd) > 1e-9)) continue;
    Mat<double> T(2, 2);  // z1 = (x2 + p_u x1)/(1 − p_d), z2 = x1
    T << pu / (1 - pd), 1 / (1 - pd), 1, 0;
    out.push_back(similarity_transform(m, T));
  }
  return out;
}

}  // namespace lpvid
