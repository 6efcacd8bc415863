#pragma once
/// A grey-box family for plants that store something (water in tanks, heat,
/// charge) and pass it on: two stores in cascade, each draining through a
/// square-root law and clipped by an overflow level. The physics of the
/// cascaded tanks (Torricelli outflow, a tank that spills over) in the
/// quasi-LPV form of model/state_scheduling.h:
///
///   x1+ = x1 + b1 u − k1·√|x1 − c1| + e1·max(x1 − o1, 0)
///   x2+ = x2 + b2 u + k12·√|x1 − c1| − k2·√|x2 − c2| + e12·max(x1 − o1, 0)
///                                                     + e2·max(x2 − o2, 0)
///   y   = C x + D u + φ
///
/// i.e. A = I (a store keeps what it holds), the four state columns
/// "@sqrt(x1-c1)", "@sqrt(x2-c2)", "@hinge(x1-o1)", "@hinge(x2-o2)" and a state
/// offset E(ρ) with one 2-vector per column (every entry free, so the fit may
/// also find a flow from store 2 to store 1 or an overflow that leaves the
/// plant). It REPLACES the linear part rather than adding to it: the linear
/// model's states are deviations with a leak, the stores' states are levels.
///
/// The fit of this family is not convex and one start is not enough (on the
/// tanks record about one start in ten reaches the best basin), so the
/// family comes with a grid of physical starting points derived from the
/// linear model and the data:
///   - time constants τ (samples) from the linear model's two slowest real
///     poles p (τ = 1/(1 − p)), in both orders and at their geometric mean;
///     the linearised outflow of a store at level h is k/(2√h) = 1/τ;
///   - the level of store 2 at rest = the mean output, of store 1 half, equal
///     and 1.5 times it; the inflow b1 balances the outflow at the mean input;
///   - overflow level of store 1 at 0.8, 1 and 1.2 times the largest output
///     (store 1 is not measured: where it spills is a guess), of store 2 just
///     below the largest output: e1 = −1 (clip), e12 = 1/2 (half of the spill
///     goes on), e2 = −1.
/// 27 starts in all. Measured on the cascaded tanks record (4 blocked folds,
/// starts from each fold's training rows): 9 starts (overflow at the largest
/// output only) won 3 folds, the 27 win 4.
/// The family applies to a SISO LTI model (no ρ-dependent term, static
/// block, state column or state offset; scheduling variables read from data
/// may be declared and are kept) whose output and input are positive on average (levels and
/// inflows); otherwise store_cascade_starts is empty.

#include <vector>

#include "data/experiment.h"
#include "model/lpv_model.h"

namespace lpvid {

/// The physical parameters of one starting point (see above).
struct StoreCascadeShape {
  double b1 = 0, k1 = 0, k12 = 0, k2 = 0;  ///< inflow gain, outflows (k12: into store 2)
  double c1 = 0, c2 = 0;                   ///< zero levels of the √ laws
  double o1 = 0, o2 = 0;                   ///< overflow levels
  double e1 = -1, e12 = 0.5, e2 = -1;      ///< overflow gains
  double h1 = 0, h2 = 0;                   ///< the levels at the first sample (x0)
  double phi = 0;                          ///< output offset φ (y = x2 + φ)
};

/// The model of `shape`, with the columns and scheduling variables of `like`
/// (SISO) followed by the four state columns.
LpvModel<double> store_cascade_model(const StoreCascadeShape& shape, const LpvModel<double>& like);

/// The starting grid above (empty when the family does not apply), from the
/// linear model and the rows `est` the family is fitted on.
std::vector<LpvModel<double>> store_cascade_starts(const LpvModel<double>& linear, const Experiment<double>& est);

}  // namespace lpvid
