#include "identify/identify.h"
#include "model/simulate.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "identify/alternating_identify.h"
#include "lmi/delta_form_lmi.h"
#include "toeplitz/record_segments.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {

namespace {

/// The samples pinned at z = 0: each record's leading zero samples of z0
/// (one record: 0 … m−1).
std::vector<Eigen::Index> pinned_samples_of(const Mat<double>& z0, const RecordLengths& records) {
  const RecordLengths lengths = record_lengths_of(records, z0.rows());
  const std::vector<Eigen::Index> start = record_starts(lengths);
  std::vector<Eigen::Index> rows;
  for (size_t k = 0; k < lengths.size(); ++k) {
    const Eigen::Index m = leading_zero_rows(z0, start[k], lengths[k]);
    for (Eigen::Index j = 0; j < m; ++j) rows.push_back(start[k] + j);
  }
  return rows;
}

/// The rows of Jz (n·nz stacked) of the pinned samples.
Mat<double> pinned_jacobian_rows(const AffineResidual<double>& a, const std::vector<Eigen::Index>& samples) {
  Mat<double> lead(static_cast<Eigen::Index>(samples.size()) * a.nz, a.Jz.cols());
  for (size_t i = 0; i < samples.size(); ++i)
    lead.middleRows(static_cast<Eigen::Index>(i) * a.nz, a.nz) = a.Jz.middleRows(samples[i] * a.nz, a.nz);
  return lead;
}

}  // namespace

ReducedProblem reduce_problem(const LpvModel<double>& model, const Experiment<double>& exp, const Unknowns& unknowns) {
  ReducedProblem rp;
  rp.residual = build_affine_residual(model, exp, unknowns);
  const AffineResidual<double>& a = rp.residual;
  const Eigen::Index P = a.num_params();
  const Mat<double> z0 = unstack_rows(a.z0, a.nz);
  const std::vector<Eigen::Index> pinned = pinned_samples_of(z0, a.records);
  rp.pinned = static_cast<Eigen::Index>(pinned.size());
  // Directions that keep z_k = 0 at the pinned samples (docs/design.md §8.4: the relaxation
  // at a point with z̄_k = 0 forces it): the null space of those rows of Jz.
  const Mat<double> lead = pinned_jacobian_rows(a, pinned);
  if (P == 0) {
    rp.N = Mat<double>::Zero(0, 0);
  } else if (lead.rows() == 0 || lead.isZero(0.0)) {
    rp.N = Mat<double>::Identity(P, P);
  } else {
    Eigen::JacobiSVD<Mat<double>> svd(lead, Eigen::ComputeFullV);
    const double tol = svd.singularValues().size() ? svd.singularValues()(0) * 1e-12 * static_cast<double>(P) : 0.0;
    Eigen::Index rank = 0;
    for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i)
      if (svd.singularValues()(i) > tol) ++rank;
    rp.N = svd.matrixV().rightCols(P - rank);
  }
  AffineSignals& s = rp.signals;
  s.zb = z0;
  s.rb = unstack_rows(a.r0, a.ny);
  for (Eigen::Index j = 0; j < rp.N.cols(); ++j) {
    Mat<double> Zj = unstack_rows(Vec<double>(a.Jz * rp.N.col(j)), a.nz);
    for (const Eigen::Index k : pinned) Zj.row(k).setZero();  // zero up to rounding by construction of N
    s.Z.push_back(Zj);
    s.R.push_back(unstack_rows(Vec<double>(a.Jr * rp.N.col(j)), a.ny));
  }
  return rp;
}

namespace {

/// The relaxation's w form (T_wᵀT_w ⪯ δ²T_zᵀT_z) is one record's
/// construction; over several records the alternating method runs in the Δ
/// form instead (docs/several_records.md), and says so.
IdentifyResult identify_records_alternating(const LpvModel<double>& model, const Experiment<double>& exp,
                                            const IdentifyOptions& options, SdpSolver& solver) {
  IdentifyResult out = identify_alternating(model, exp, options, solver);
  out.relaxation += "; the paper's relaxation takes one record, so " + std::to_string(exp.records.size()) +
                    " records are identified by this method instead";
  return out;
}

}  // namespace

IdentifyResult identify(const LpvModel<double>& model, const Experiment<double>& exp_in, const IdentifyOptions& options,
                        SdpSolver& solver) {
  const Experiment<double> exp = with_state_scheduling(model, exp_in);  // "@x<i>" columns
  options.objective.validate();
  if (options.method == IdentifyMethod::kAlternating) return identify_alternating(model, exp, options, solver);
  if (exp.record_count() > 1) return identify_records_alternating(model, exp, options, solver);
  ReducedProblem rp = reduce_problem(model, exp, options.unknowns);
  IdentifyResult out;
  out.layout = rp.residual.layout;
  out.names = rp.residual.names;
  out.pinned_samples = rp.pinned;
  out.free_directions = rp.N.cols();
  const Eigen::Index P = rp.residual.num_params();
  bool z_moves = false;
  for (const auto& Zj : rp.signals.Z)
    if (!Zj.isZero(0.0)) z_moves = true;

  Vec<double> q_bar = Vec<double>::Zero(rp.N.cols());
  double previous = std::numeric_limits<double>::infinity();
  const int max_solves = options.iterate && z_moves ? options.max_iterations : 1;
  for (int it = 0; it < max_solves; ++it) {
    const auto start = std::chrono::steady_clock::now();
    RelaxedSolution sol = solve_relaxed(rp.signals, q_bar, options.objective, solver, options.solver);
    IterateRecord rec;
    rec.index = it;
    rec.status = sol.solve.status;
    rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.status = sol.solve.status;
    out.message = sol.solve.message;
    if (!has_solution(sol.solve.status)) {
      if (it == 0) {
        out.p = Vec<double>::Zero(P);
        out.iterates.push_back(rec);
        out.relaxation = "failed";
        return out;
      }
      break;  // keep the last good iterate
    }
    rec.delta2 = sol.delta2;
    rec.dmax2 = sol.dmax2;
    rec.objective = options.objective.value(sol.delta2, sol.dmax2);
    rec.p = P ? Vec<double>(rp.N * sol.q) : Vec<double>(0);
    out.iterates.push_back(rec);
    const double gain = previous - rec.objective;
    if (it > 0 && gain < 0) break;  // rounding made it worse: keep the previous iterate
    out.p = rec.p;
    q_bar = sol.q;
    if (it > 0 && !(gain > options.rel_tol * std::max(std::abs(previous), 1e-300))) break;
    previous = rec.objective;
  }
  const int solves = static_cast<int>(out.iterates.size());
  if (!z_moves)
    out.relaxation = "none (z does not depend on the unknowns: Theorem 3.1 is an LMI)";
  else if (!options.iterate)
    out.relaxation = "linearised at the initial model (paper, after eq. 16)";
  else
    out.relaxation = "iterated re-linearisation (" + std::to_string(solves) + " solves)";
  return out;
}

}  // namespace lpvid
