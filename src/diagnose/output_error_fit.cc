#include "diagnose/output_error_fit.h"

#include <cmath>
#include <limits>

#include "model/simulate.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {

namespace {

struct Window {
  Eigen::Index first = 0, last = 0;
};

Window window_of(const Experiment<double>& exp, Eigen::Index first, Eigen::Index last) {
  Window w{first, last < 0 ? exp.n() : last};
  if (w.first < 0 || w.first >= w.last || w.last > exp.n())
    throw std::invalid_argument("fit window [" + std::to_string(first) + ", " + std::to_string(last) +
                                ") is empty or outside the " + std::to_string(exp.n()) + " samples");
  return w;
}

/// Stacked residual y − ŷ over the window; empty when not finite.
Vec<double> residual(const LpvModel<double>& m, const Experiment<double>& exp, const Window& w) {
  const Simulation<double> sim = simulate(m, exp);
  const Eigen::Index rows = w.last - w.first;
  const Mat<double> r = exp.y.middleRows(w.first, rows) - sim.output.middleRows(w.first, rows);
  if (!r.allFinite()) return {};
  return stack_rows(r);
}

}  // namespace

double prediction_rms(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index first,
                      Eigen::Index last) {
  const Vec<double> r = residual(model, exp, window_of(exp, first, last));
  if (r.size() == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt(r.squaredNorm() / static_cast<double>(r.size()));
}

FitResult fit_slots(const LpvModel<double>& model, const std::vector<ParameterSlot>& slots,
                    const Experiment<double>& exp, const FitOptions& o) {
  const Window w = window_of(exp, o.first_sample, o.last_sample);
  FitResult res;
  res.model = model;
  Vec<double> p = slot_values(model, slots);
  Vec<double> r = residual(model, exp, w);
  if (r.size() == 0) {
    res.finite = false;
    res.rms = std::numeric_limits<double>::infinity();
    return res;
  }
  double cost = r.squaredNorm();
  double mu = 1e-3;  // LM damping relative to the Gauss–Newton diagonal
  const Eigen::Index P = p.size();
  for (int it = 0; it < o.max_iterations && P > 0; ++it) {
    res.iterations = it + 1;
    // forward-difference Jacobian of the residual
    Mat<double> J(r.size(), P);
    bool ok = true;
    for (Eigen::Index j = 0; j < P && ok; ++j) {
      const double h = 1e-7 * std::max(1.0, std::abs(p(j)));
      Vec<double> q = p;
      q(j) += h;
      const Vec<double> rj = residual(with_slot_values(model, slots, q), exp, w);
      if (rj.size() == 0) {
        ok = false;
        break;
      }
      J.col(j) = (rj - r) / h;
    }
    if (!ok) break;
    const Mat<double> JtJ = J.transpose() * J;
    const Vec<double> g = J.transpose() * r;
    Vec<double> diag = JtJ.diagonal();
    for (Eigen::Index j = 0; j < P; ++j) diag(j) = std::max(diag(j), 1e-12 * (1.0 + JtJ.diagonal().maxCoeff()));
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Mat<double> H = JtJ;
      H.diagonal() += mu * diag;
      const Vec<double> step = H.ldlt().solve(-g);
      if (!step.allFinite()) {
        mu *= 10;
        continue;
      }
      const Vec<double> q = p + step;
      const LpvModel<double> mq = with_slot_values(model, slots, q);
      const Vec<double> rq = residual(mq, exp, w);
      if (rq.size() != 0 && rq.squaredNorm() < cost) {
        const double rel = (cost - rq.squaredNorm()) / std::max(cost, 1e-300);
        p = slot_values(mq, slots);  // limits may have been re-ordered
        r = rq;
        cost = rq.squaredNorm();
        mu = std::max(mu / 10, 1e-12);
        improved = true;
        if (rel < o.rel_tol) it = o.max_iterations;  // converged
      } else {
        mu *= 10;
      }
    }
    if (!improved) break;
  }
  res.model = with_slot_values(model, slots, p);
  res.rms = std::sqrt(cost / static_cast<double>(r.size()));
  return res;
}

}  // namespace lpvid
