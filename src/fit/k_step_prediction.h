#pragma once
/// k-step-ahead prediction of an LPV state-space model without an observer
/// (`lpvid compare --predict K`).
///
/// For each predicted sample t (t >= K) the state is re-fitted on a window of
/// measured outputs that ends K samples earlier, then the model runs K steps
/// on the measured inputs and scheduling:
///
///   p = t − K,  s = max(0, p − m + 1)
///   x̂_s  = argmin_x Σ_{k=s..p} ‖y_k − ŷ_k(x)‖²   (fit_initial_state: least
///          squares on the outputs of rows s..p, the model run from x at s)
///   ŷ(t | p) = the model's output at t, run from x̂_s at row s.
///
/// So ŷ(t | p) uses outputs up to row p = t − K only, and inputs up to t.
/// m (the window) defaults to the model's order nx (at least 1): the
/// shortest window that determines the state of an observable model. No
/// Kalman filter, no noise model: on a noise-free record of the model itself
/// every K predicts exactly; for y_{k+1} = a·y_k + b·u_k (C = 1, D = 0) and
/// m = 1 the 1-step prediction is a·y_{t−1} + b·u_{t−1}. Rows t < K have no
/// measured output K samples before them: their prediction is the free run
/// from the model's x0. The input delay and static input map are applied to
/// the whole record first, so a window sees the delayed inputs of the rows
/// before it.

#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

/// n × ny: ŷ(t | t − k) for t >= first (rows before `first`: the free run from
/// model.x0). Throws std::invalid_argument unless k >= 1 and window >= 1.
Mat<double> k_step_prediction(const LpvModel<double>& model, const Experiment<double>& exp, Eigen::Index k,
                              Eigen::Index window, Eigen::Index first = 0);

}  // namespace lpvid
