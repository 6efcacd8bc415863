#pragma once
// The closed-form gradient and Hessian of the structured barrier's F_μ
// (lmi/delta_form_barrier.h) against central finite differences of its value,
// at a random objective, μ and interior point; shared by the barrier's tests
// without and with free regressors, and with several records (`records`: the
// lengths of the stacked records, empty: one). Call inside a rapidcheck property.
#include <rapidcheck.h>

#include <cmath>

#include "lmi/delta_form_barrier.h"
#include "toeplitz/fir.h"

namespace lpvid {

inline void check_barrier_finite_differences(const Mat<double>& z, const Mat<double>& r, const Mat<double>& G = {},
                                             const RecordLengths& records = {}) {
  const int which = *rc::gen::inRange(0, 3);
  const bool weighted = which != 0;  // t is a variable
  BoundObjective obj;
  obj.kind = which == 0 ? BoundObjective::Kind::kMinDmax : which == 1 ? BoundObjective::Kind::kWeighted : BoundObjective::Kind::kMinDelta;
  obj.delta = r.norm() / z.norm();
  // min δ: d_max above the residual's RMS, so that small taps keep (C2) strict
  obj.dmax = 2.0 * r.norm() / std::sqrt(static_cast<double>(r.rows()));
  const double mu = std::pow(10.0, *rc::gen::inRange(-3, 1));
  const Eigen::Index L = records_horizon(z, records), nt = L * r.cols() * z.cols();
  const Eigen::Index D = nt + (weighted ? 1 : 0);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(D);
  for (Eigen::Index i = 0; i < nt; ++i) x(i) = *rc::gen::inRange(-100, 101) / (1000.0 * static_cast<double>(L));
  if (weighted) x(nt) = 1.0 + *rc::gen::inRange(0, 100) / 100.0;
  const BarrierDerivatives b = barrier_derivatives(z, r, obj, x, mu, G, records);
  RC_PRE(std::isfinite(b.value));
  // free regressors change the function: the same point without them has another value
  if (G.cols() > 0) RC_ASSERT(barrier_derivatives(z, r, obj, x, mu).value != b.value);
  const double step = 1e-4;
  for (Eigen::Index i = 0; i < D; ++i) {
    Eigen::VectorXd xp = x, xm = x;
    xp(i) += step;
    xm(i) -= step;
    const BarrierDerivatives bp = barrier_derivatives(z, r, obj, xp, mu, G, records),
                             bm = barrier_derivatives(z, r, obj, xm, mu, G, records);
    RC_PRE(std::isfinite(bp.value) && std::isfinite(bm.value));
    const double fd = (bp.value - bm.value) / (2 * step);
    // Truncation O(step²) plus round-off of F_μ's value (the t/μ term can be 1e9).
    RC_ASSERT(std::abs(fd - b.gradient(i)) <= 1e-4 * (1 + std::abs(fd)) + 1e-14 * std::abs(b.value) / step);
    const Eigen::VectorXd fdh = (bp.gradient - bm.gradient) / (2 * step);
    RC_ASSERT((fdh - b.hessian.col(i)).cwiseAbs().maxCoeff() <=
              1e-3 * (1 + fdh.cwiseAbs().maxCoeff()) + 1e-14 * b.gradient.cwiseAbs().maxCoeff() / step);
  }
}

}  // namespace lpvid
