#pragma once
/// Starting points for output-map (Wiener) candidates when the linear part
/// was fitted THROUGH the map (as fit-linear does on real data): the classical Wiener
/// initialisation (Ljung, System Identification, 2nd ed., §5.5; Schoukens &
/// Tiels, "Identification of block-oriented nonlinear systems starting from
/// linear approximations", 2017): turn the measured y into a target v* for
/// the signal before the map, fit the linear part to v* by output error,
/// then put the map back and re-fit everything jointly.
///
///   polynomial   v*_k solves c_0 + v + c_2 v² + c_3 v³ = y_k, by Newton's
///                method started at the current model's v_k (the root next
///                to the current fit where the map is not monotone)
///   |·|          v*_k = s_k y_k, the sign s_k flipped at every dip of y to
///                near zero (a local minimum below the 15 % quantile, after y
///                has risen above twice that level since the last flip): a
///                signed signal crosses zero where its absolute value dips.
///                Without this start a linear part fitted to |v| (whose best
///                linear approximation is close to zero for an even map) can
///                never become the signed v.

///   quadratic    (even maps, where the best LINEAR approximation is ~0 and
///   kernel       carries no sign information: |·|, strong v²) the best
///                QUADRATIC approximation of y in the inputs, y ≈ c + gᵀφ +
///                φᵀKφ with φ the inputs through Laguerre filters (pole a
///                picked by least squares). For a Wiener system y = f(h∗u)
///                with Gaussian-like v = h∗u, K ∝ E[f''] h hᵀ (Bussgang/Price):
///                the dominant eigenvector e of K gives w = eᵀφ ≈ ±h∗u up to
///                scale, the signal before the map; the scale and sign come
///                from regressing y on the map of w.

#include <vector>

#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

/// v* for a polynomial output map (coefficients c_0, c_1 = 1, c_2, …) from
/// the measured y and the current v (same length).
Vec<double> polynomial_inverse_target(const std::vector<double>& coefficients, const Vec<double>& y,
                                      const Vec<double>& v);

/// v* = s ⊙ y for an absolute-value sensor (see above).
Vec<double> sign_recovered_target(const Vec<double>& y);

struct QuadraticKernel {
  Vec<double> w;    ///< eᵀφ (empty: no signal)
  double rms = 0;   ///< RMS residual of the quadratic regression of y
};

/// w = eᵀφ of the quadratic kernel (above) on the estimation inputs, and the
/// regression's RMS residual; w is empty when the inputs are too few for the
/// regression (fewer than three rows per regressor) or the fit is not finite.
QuadraticKernel quadratic_kernel_signal(const Experiment<double>& est);

/// `start` with its output map set to `map` after its linear part (A, B, C,
/// D, offset, x0; output map identity) was fitted to the target v* on the
/// estimation inputs. Single output; returns `start` unchanged if the fit
/// does not stay finite.
LpvModel<double> fitted_to_target(const LpvModel<double>& start, const Experiment<double>& est,
                                  const Vec<double>& target);

}  // namespace lpvid
