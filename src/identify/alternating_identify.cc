#include "identify/alternating_identify.h"

#include "model/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/deadline.h"
#include "lmi/delta_form_solve.h"
#include "lmi/delta_kyp_lmi.h"
#include "toeplitz/fir.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {
namespace {

/// T_Δ v for a stacked signal v (n·nz) → stacked n·ny: w = Δ ∗ v record by
/// record, each record from its first sample (one record: all of the horizon).
Vec<double> fir_stacked(const Mat<double>& taps, const Vec<double>& v, const AffineResidual<double>& a) {
  const Mat<double> z = unstack_rows(v, a.nz);
  Eigen::Index longest = 0;
  for (const Eigen::Index l : record_lengths_of(a.records, z.rows())) longest = std::max(longest, l);
  return stack_rows(apply_fir_records(taps, z, a.ny, longest, a.records));
}

/// An orthonormal basis of the span of the columns of Jr whose parameters do
/// not move z (Jz column zero): those enter (C2) linearly, so the Δ step
/// optimises them jointly with Δ (delta_kyp_lmi.h, extra regressors).
Mat<double> joint_regressors(const AffineResidual<double>& a) {
  std::vector<Eigen::Index> cols;
  for (Eigen::Index j = 0; j < a.num_params(); ++j)
    if (a.Jz.col(j).isZero(0.0) && !a.Jr.col(j).isZero(0.0)) cols.push_back(j);
  if (cols.empty()) return Mat<double>(a.Jr.rows(), 0);
  Mat<double> S(a.Jr.rows(), static_cast<Eigen::Index>(cols.size()));
  for (size_t c = 0; c < cols.size(); ++c) {
    const auto j = cols[c];
    S.col(static_cast<Eigen::Index>(c)) = a.Jr.col(j) / a.Jr.col(j).norm();
  }
  Eigen::ColPivHouseholderQR<Mat<double>> qr(S);
  qr.setThreshold(1e-10);
  const Eigen::Index rank = qr.rank();
  const Mat<double> Q = qr.householderQ() * Mat<double>::Identity(S.rows(), rank);
  return Q;
}

}  // namespace

Vec<double> alternating_parameter_step(const AffineResidual<double>& a, const Mat<double>& taps, double* dmax2) {
  // d(p) = r0 − Jr p − T_Δ(z0 + Jz p) = b − A p with b = r0 − T_Δ z0, A = Jr + T_Δ Jz.
  const Eigen::Index P = a.num_params();
  const bool delta_zero = taps.size() == 0 || taps.isZero(0.0);
  Vec<double> b = a.r0;
  if (!delta_zero) b -= fir_stacked(taps, a.z0, a);
  Vec<double> p = Vec<double>::Zero(P);
  if (P > 0) {
    Mat<double> A = a.Jr;
    if (!delta_zero)
      for (Eigen::Index j = 0; j < P; ++j) A.col(j) += fir_stacked(taps, Vec<double>(a.Jz.col(j)), a);
    // Column scaling keeps the decomposition's rank decision relative per column.
    Vec<double> scale(P);
    for (Eigen::Index j = 0; j < P; ++j) scale(j) = A.col(j).norm() > 0 ? 1.0 / A.col(j).norm() : 1.0;
    const Mat<double> As = A * scale.asDiagonal();
    Eigen::CompleteOrthogonalDecomposition<Mat<double>> cod(As);
    p = scale.asDiagonal() * cod.solve(b);
    b -= A * p;
  }
  if (dmax2 != nullptr) *dmax2 = b.squaredNorm() / static_cast<double>(a.n * a.ny);
  return p;
}

namespace {

/// The Δ step: Theorem 2.1 at the fixed model p (KYP form, K taps), jointly
/// with the parameters that do not move z (their span E; the p step
/// recovers them: it minimises over all p, so it does at least as well).
/// Sets the record's status, taps and δ², and the result's status and message.
/// Several records: the Δ form over the records on their full horizon
/// (the KYP program's state would run across the records).
IterateRecord delta_step(const AffineResidual<double>& a, const Vec<double>& p, const Mat<double>& E,
                         const BoundObjective& inner, const IdentifyOptions& options, SdpSolver& solver,
                         IdentifyResult& out) {
  Mat<double> z = unstack_rows(a.z(p), a.nz), r = unstack_rows(a.r(p), a.ny);
  DeltaKypSolution ds;
  if (several_records(a.records)) {
    DeltaFormRequest request;
    request.solver = options.solver;
    request.free_regressors = E;
    DeltaFormSolution s = solve_delta_form(DeltaFormSignals{std::move(z), std::move(r), a.records}, inner, request, solver);
    ds.solve = std::move(s.solve);
    ds.taps = std::move(s.taps);
    ds.delta2 = s.delta2;
  } else {
    ds = solve_delta_kyp(z, r, inner, solver, options.solver, options.taps, E);
  }
  IterateRecord rec;
  rec.status = ds.solve.status;
  out.status = ds.solve.status;
  out.message = ds.solve.message;
  if (!has_solution(ds.solve.status)) return rec;
  rec.taps = ds.taps;
  rec.delta2 = ds.delta2;
  return rec;
}

/// A fixed (δ, d_max): the accepted iterate's d_max must reach the given
/// one; otherwise "infeasible" for this local method (never an invalidation).
void judge_given_dmax(const BoundObjective& objective, const IterateRecord& accepted, IdentifyResult& out) {
  const double given = objective.dmax.approx * objective.dmax.approx;
  if (accepted.dmax2 > given) {
    out.status = SolveStatus::kPrimalInfeasible;
    out.message = "alternating descent found no parameters with dmax <= the given bound at the given delta (a "
                  "local method: this does not invalidate the model class)";
  }
}

/// Iterate `index`: the Δ step at p (where the previous accepted iterate's p
/// step ended, or the least-squares start), then the p step for its Δ.
IterateRecord alternating_iterate(const AffineResidual<double>& a, const Vec<double>& p, const Mat<double>& E,
                                  const BoundObjective& inner, const IdentifyOptions& options, SdpSolver& solver,
                                  IdentifyResult& out, int index) {
  const auto start = std::chrono::steady_clock::now();  // reported only
  IterateRecord rec = delta_step(a, p, E, inner, options, solver, out);
  rec.index = index;
  rec.p_delta_step = p;
  if (has_solution(rec.status)) {
    rec.p = alternating_parameter_step(a, rec.taps, &rec.dmax2);
    rec.objective = inner.value(rec.delta2, rec.dmax2);
  }
  rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return rec;
}

/// The descent: appends every iterate to out.iterates and returns the index
/// of the accepted one (−1 if the first Δ step failed). Iterate k+1's Δ step
/// is solved at iterate k's p, where Δ_k is feasible, so J does not rise up
/// to the SDP's tolerance; an iterate that rises anyway ends the loop and is
/// not accepted, as is a failed Δ step after a good one. A gain below
/// rel_tol (relative) ends it too, that iterate accepted.
int descend(const AffineResidual<double>& a, const BoundObjective& inner, const IdentifyOptions& options,
            SdpSolver& solver, IdentifyResult& out) {
  Vec<double> p = alternating_parameter_step(a, Mat<double>(), nullptr);  // plain least squares: Δ = 0
  const Mat<double> E = joint_regressors(a);
  int accepted = -1;
  for (int it = 0; it < std::max(1, options.max_iterations); ++it) {
    check_deadline("the alternating identification was iterating");  // --timeout or a requested stop
    out.iterates.push_back(alternating_iterate(a, p, E, inner, options, solver, out, it));
    const IterateRecord& rec = out.iterates.back();
    if (!has_solution(rec.status)) break;
    bool stalled = false;
    if (accepted >= 0) {
      const double previous = out.iterates[static_cast<size_t>(accepted)].objective;
      const double gain = previous - rec.objective;
      if (gain < 0) break;  // the SDP's tolerance made it worse: keep the previous iterate
      stalled = !(gain > options.rel_tol * std::max(std::abs(previous), 1e-300));
    }
    accepted = it;
    p = rec.p;  // θ fed back: the next Δ step is solved at this iterate's p
    if (stalled) break;
  }
  return accepted;
}

}  // namespace

IdentifyResult identify_alternating(const LpvModel<double>& model, const Experiment<double>& exp_in,
                                    const IdentifyOptions& options, SdpSolver& solver) {
  const Experiment<double> exp = with_state_scheduling(model, exp_in);  // "@x<i>" columns
  options.objective.validate();
  const AffineResidual<double> a = build_affine_residual(model, exp, options.unknowns);
  IdentifyResult out;
  out.layout = a.layout;
  out.names = a.names;
  out.free_directions = a.num_params();
  // A fixed δ with d_max also fixed is decided by minimising d_max at that δ.
  BoundObjective inner = options.objective;
  const bool feasibility = inner.kind == BoundObjective::Kind::kFeasibility;
  if (feasibility) inner.kind = BoundObjective::Kind::kMinDmax;

  const int accepted = descend(a, inner, options, solver, out);
  if (accepted < 0) {  // the first Δ step failed: its status and message are out's
    out.p = Vec<double>::Zero(a.num_params());
    out.relaxation = "failed";
    return out;
  }
  const IterateRecord& best = out.iterates[static_cast<size_t>(accepted)];
  out.p = best.p;        // p_{k+1} = the p step for Δ_k ...
  out.taps = best.taps;  // ... and Δ_k: the pair certify_with_taps certifies
  if (!has_solution(out.iterates.back().status))
    out.message = "Delta step " + std::to_string(out.iterates.back().index) + " failed (" + out.message +
                  "); iterate " + std::to_string(accepted) + " is kept";
  out.status = best.status;
  out.relaxation = "alternating Delta/theta descent (" + std::to_string(out.iterates.size()) + " Delta steps, " +
                   (several_records(a.records) ? std::to_string(a.records.size()) + " records, full-horizon Delta form)"
                                               : std::to_string(options.taps) + " taps, KYP)");
  if (feasibility) judge_given_dmax(options.objective, best, out);
  return out;
}

}  // namespace lpvid
