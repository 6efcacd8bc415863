#pragma once
/// Simulation of the LPV model of docs/design.md §5 (paper eq. 1 with G11 = 0, G21 = I,
/// and eq. 8–10) along a measured trajectory, and the data that makes the
/// model output affine in the unknown correction θ (Theorem 3.1, eq. 14–15).
///
///   x_{k+1} = A(ρ_k) x_k + B(ρ_k) u_k + E(ρ_k),   x_0 = model.x0 (zero if empty)
///   ŷ_k     = C(ρ_k) x_k + D(ρ_k) u_k          (C = C2, D = D2; no offset)
///   z_k     = C1(ρ_k) x_k + D1(ρ_k) u_k        (model/uncertainty_channel.h)
///   Φ_k     = Σ_j h_j(ρ_k) φ_j                 (offset, zero unless given)
///
/// with A(ρ) = A_0(ρ) + Σ_i f_i(ρ) A_i and B(ρ) = B_0(ρ) + Σ_i f_i(ρ) B_i: the
/// fixed A_i, B_i of the correction S_C (eq. 10) are part of the state
/// equation, and so is the state offset E(ρ) = Σ_j h_j(ρ) e_j (model.state_offset,
/// zero unless given). The correction's C_i, D_i are unknowns; since A_i, B_i are fixed
/// the state x does not depend on them and
///
///   ŷ_k(θ) = ŷ_k + Σ_i f_i(ρ_k) (C_i x_k + D_i u_k)
///
/// is affine in θ (output_jacobian below gives the exact linear part).
///
/// Everything is templated on the scalar (double or Rational) and uses only
/// +, −, ×: no tolerance, no sqrt (docs/design.md §13.4); the one root, of a
/// "@sqrt(x<i>-c)" column, is the exact rounded root of model/state_scheduling.h.

#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/scalar.h"
#include "core/stop_request.h"
#include "data/experiment.h"
#include "model/lpv_model.h"
#include "model/monomial.h"
#include "model/param_matrix.h"
#include "model/state_scheduling.h"
#include "model/uncertainty_channel.h"

namespace lpvid {

/// The matrices of the model as functions of ρ, checked and with the fixed
/// correction A_i, B_i folded into A and B. C, D are C2, D2 (the output ŷ);
/// C1, D1 the uncertainty channel z (docs/design.md §5).
template <typename T>
struct SystemMatrices {
  ParamMatrix<T> A;   ///< nx × nx: A_0(ρ) + Σ_i f_i(ρ) A_i
  ParamMatrix<T> B;   ///< nx × nu: B_0(ρ) + Σ_i f_i(ρ) B_i
  ParamMatrix<T> C;   ///< ny × nx
  ParamMatrix<T> D;   ///< ny × nu
  ParamMatrix<T> C1;  ///< nz × nx
  ParamMatrix<T> D1;  ///< nz × nu
};

namespace detail {

inline void check_basis(const Monomial& f, int n_rho, const std::string& where) {
  if (static_cast<int>(f.powers.size()) != n_rho)
    throw std::invalid_argument(where + ": basis function has " + std::to_string(f.powers.size()) +
                                " powers but the model has " + std::to_string(n_rho) +
                                " scheduling variables");
  for (int p : f.powers)
    if (p < 0) throw std::invalid_argument(where + ": negative power in a basis function");
}

template <typename T>
void check_terms(const ParamMatrix<T>& m, int n_rho, const std::string& name) {
  for (const auto& t : m.terms) check_basis(t.basis, n_rho, "model matrix " + name);
}

/// ρ_k as a vector (length nρ; works for nρ = 0 with any number of rows).
template <typename T>
Vec<T> rho_at(const Mat<T>& rho, Eigen::Index k) {
  if (rho.cols() == 0) return Vec<T>(0);
  return rho.row(k).transpose();
}

/// Fixed correction matrix i (A_i or B_i): an empty list means all zero, a
/// 0×0 entry means zero; otherwise rows × cols.
template <typename T>
Mat<T> correction_matrix(const std::vector<Mat<T>>& list, size_t i, size_t n_basis, Eigen::Index rows,
                         Eigen::Index cols, const char* name) {
  if (list.empty()) return Mat<T>::Zero(rows, cols);
  if (list.size() != n_basis)
    throw std::invalid_argument(std::string("correction ") + name + " has " + std::to_string(list.size()) +
                                " matrices but the correction basis has " + std::to_string(n_basis) +
                                " functions");
  const Mat<T>& m = list[i];
  if (m.size() == 0) return Mat<T>::Zero(rows, cols);
  if (m.rows() != rows || m.cols() != cols)
    throw std::invalid_argument(std::string("correction ") + name + "_" + std::to_string(i + 1) + " is " +
                                shape_text(m.rows(), m.cols()) + ", expected " + shape_text(rows, cols));
  return m;
}

}  // namespace detail

/// Checks every size of the model (matrices, terms, basis functions against
/// nρ, correction A_i/B_i, offset, x0, uncertainty channel) and returns the
/// matrices of docs/design.md §5 as functions of ρ. Throws std::invalid_argument with
/// the offending sizes. A 0×0 matrix without terms is read as zero.
template <typename T>
SystemMatrices<T> system_matrices(const LpvModel<T>& model) {
  const int nx = model.nx, nu = model.nu, ny = model.ny, n_rho = model.n_rho();
  if (nx < 0 || nu < 0 || ny < 0)
    throw std::invalid_argument("model sizes must be non-negative (nx=" + std::to_string(nx) +
                                ", nu=" + std::to_string(nu) + ", ny=" + std::to_string(ny) + ")");
  SystemMatrices<T> s;
  s.A = detail::given_or_zero(model.A, nx, nx, "A");
  s.B = detail::given_or_zero(model.B, nx, nu, "B");
  s.C = detail::given_or_zero(model.C, ny, nx, "C");
  s.D = detail::given_or_zero(model.D, ny, nu, "D");
  detail::check_terms(s.A, n_rho, "A");
  detail::check_terms(s.B, n_rho, "B");
  detail::check_terms(s.C, n_rho, "C");
  detail::check_terms(s.D, n_rho, "D");

  const auto& corr = model.correction;
  const size_t n_basis = corr.basis.size();
  for (size_t i = 0; i < n_basis; ++i) {
    detail::check_basis(corr.basis[i], n_rho, "correction basis " + std::to_string(i + 1));
    const Mat<T> Ai = detail::correction_matrix(corr.A, i, n_basis, nx, nx, "A");
    const Mat<T> Bi = detail::correction_matrix(corr.B, i, n_basis, nx, nu, "B");
    // A(ρ) = A_0(ρ) + Σ_i f_i(ρ) A_i, likewise B (eq. 8–10).
    s.A.add(corr.basis[i], Ai);
    s.B.add(corr.basis[i], Bi);
  }

  s.C1 = uncertainty_C1(model);
  s.D1 = uncertainty_D1(model);
  detail::check_terms(s.C1, n_rho, "uncertainty C1");
  detail::check_terms(s.D1, n_rho, "uncertainty D1");

  const auto& off = model.offset;
  for (size_t j = 0; j < off.basis.size(); ++j)
    detail::check_basis(off.basis[j], n_rho, "offset basis " + std::to_string(j + 1));
  if (!off.values.empty()) {
    if (off.values.size() != off.basis.size())
      throw std::invalid_argument("offset has " + std::to_string(off.values.size()) + " values but " +
                                  std::to_string(off.basis.size()) + " basis functions");
    for (size_t j = 0; j < off.values.size(); ++j)
      if (off.values[j].size() != ny)
        throw std::invalid_argument("offset value " + std::to_string(j + 1) + " has length " +
                                    std::to_string(off.values[j].size()) + ", expected ny = " +
                                    std::to_string(ny));
  }
  const auto& soff = model.state_offset;
  for (size_t j = 0; j < soff.basis.size(); ++j)
    detail::check_basis(soff.basis[j], n_rho, "state_offset basis " + std::to_string(j + 1));
  if (soff.values.size() != soff.basis.size())
    throw std::invalid_argument("state_offset has " + std::to_string(soff.values.size()) + " values but " +
                                std::to_string(soff.basis.size()) + " basis functions");
  for (size_t j = 0; j < soff.values.size(); ++j)
    if (soff.values[j].size() != nx)
      throw std::invalid_argument("state_offset value " + std::to_string(j + 1) + " has length " +
                                  std::to_string(soff.values[j].size()) + ", expected nx = " + std::to_string(nx));
  state_functions<T>(model.columns.rho, nx);  // state columns name existing states and parse
  if (model.x0.size() != 0 && model.x0.size() != nx)
    throw std::invalid_argument("x0 has length " + std::to_string(model.x0.size()) + ", expected nx = " +
                                std::to_string(nx));
  return s;
}

/// Checks that the experiment fits the model: u is n × nu, ρ is n × nρ (any
/// number of rows when nρ = 0), y is n × ny or empty (simulation does not
/// need y). Throws std::invalid_argument with both sizes.
template <typename T>
void check_experiment(const LpvModel<T>& model, const Experiment<T>& exp) {
  const Eigen::Index n = exp.n();
  const std::string src = exp.source.empty() ? "experiment" : "experiment '" + exp.source + "'";
  if (exp.u.cols() != model.nu)
    throw std::invalid_argument(src + " has nu = " + std::to_string(exp.u.cols()) + " input columns, model has nu = " +
                                std::to_string(model.nu));
  if (exp.y.size() != 0 && (exp.y.cols() != model.ny || exp.y.rows() != n))
    throw std::invalid_argument(src + ": y is " + shape_text(exp.y.rows(), exp.y.cols()) +
                                ", expected n x ny = " + shape_text(n, model.ny));
  if (exp.rho.cols() != model.n_rho())
    throw std::invalid_argument(src + " has n_rho = " + std::to_string(exp.rho.cols()) +
                                " scheduling columns, model has n_rho = " + std::to_string(model.n_rho()));
  if (model.n_rho() > 0 && exp.rho.rows() != n)
    throw std::invalid_argument(src + ": rho has " + std::to_string(exp.rho.rows()) + " rows but u has " +
                                std::to_string(n));
}

/// Output offset Φ(ρ) = Σ_j h_j(ρ) φ_j (paper eq. 20) at one sample; zero
/// when the values are unknown (empty). Length ny.
template <typename T>
void basis_sum_into(const std::vector<Monomial>& basis, const std::vector<Vec<T>>& values, Eigen::Index size,
                    const Vec<T>& rho, Vec<T>& sum) {
  sum.setZero(size);
  for (size_t j = 0; j < values.size(); ++j) sum += basis[j].template eval<T>(rho) * values[j];
}

template <typename T>
Vec<T> basis_sum(const std::vector<Monomial>& basis, const std::vector<Vec<T>>& values, Eigen::Index size,
                 const Vec<T>& rho) {
  Vec<T> sum;
  basis_sum_into(basis, values, size, rho, sum);
  return sum;
}

template <typename T>
Vec<T> offset_at(const LpvModel<T>& model, const Vec<T>& rho) {
  return basis_sum(model.offset.basis, model.offset.values, model.ny, rho);
}

/// State offset E(ρ) = Σ_j h_j(ρ) e_j (model.state_offset) at one sample;
/// length nx (zero without a state offset).
template <typename T>
Vec<T> state_offset_at(const LpvModel<T>& model, const Vec<T>& rho) {
  return basis_sum(model.state_offset.basis, model.state_offset.values, model.nx, rho);
}

/// True when the model has a state offset term (model.state_offset).
template <typename T>
bool has_state_offset(const LpvModel<T>& model) {
  return !model.state_offset.empty();
}

/// The trajectories of one simulation; row k is sample k (k = 0 … n−1).
template <typename T>
struct Simulation {
  Mat<T> x;       ///< n × nx: x_k (x_0 = model.x0)
  Mat<T> yhat;    ///< n × ny: ŷ_k = C(ρ_k) x_k + D(ρ_k) u_k (no offset)
  Mat<T> z;       ///< n × nz: z_k = C1(ρ_k) x_k + D1(ρ_k) u_k
  Mat<T> offset;  ///< n × ny: Φ(ρ_k) (zero if the offset values are not given)
  Mat<T> output;  ///< n × ny: g_out(ŷ_k + Φ_k), the model's prediction of y (model/static_blocks.h)
  Mat<T> rho;     ///< n × nρ: the scheduling used, "@x<i>" columns from the state (model/state_scheduling.h)
};

/// Simulates the model (docs/design.md §5, paper eq. 1 / 8–10) along the experiment's u
/// and ρ from x_0 = model.x0 (zero if empty). The LPV part sees the input
/// u' = g_in(u_{k−d}) of the model's static blocks (identity unless declared),
/// plus the state offset E(ρ_k) (model.state_offset);
/// the model's prediction of y is output = g_out(yhat + offset). A scheduling
/// column "@x<i>" (or "@sqrt(x<i>-c)", …) is a function of the model's own state (model/state_scheduling.h): the
/// experiment's column is ignored and recomputed. Throws std::invalid_argument on size mismatches.
namespace detail {

/// exp with zero columns inserted at the model's "@x<i>" scheduling positions
/// when exp.rho lacks exactly those (they are not data); exp otherwise.
template <typename T>
Experiment<T> with_state_columns(const LpvModel<T>& model, const Experiment<T>& exp) {
  const auto own = state_scheduled(model.columns.rho, model.nx);
  if (own.empty() || exp.rho.cols() + static_cast<Eigen::Index>(own.size()) != model.n_rho()) return exp;
  Experiment<T> out = exp;
  out.rho = Mat<T>::Zero(exp.n(), model.n_rho());
  Eigen::Index from = 0;
  for (Eigen::Index j = 0; j < model.n_rho(); ++j)
    if (state_scheduling_index(model.columns.rho[static_cast<size_t>(j)]) < 0) out.rho.col(j) = exp.rho.col(from++);
  return out;
}

}  // namespace detail

namespace detail {

/// The per-sample matrices and vectors of simulate_one_record, allocated
/// once per simulation (a fit simulates a record hundreds of times: one heap
/// allocation per sample and matrix was half its time). Every product is
/// evaluated into its own buffer exactly as the expression
/// `(C x + D u)` evaluates its two products into temporaries, so the
/// numbers are those of the per-sample expressions, bit for bit.
template <typename T>
struct SimulationWorkspace {
  Mat<T> A, B, C, D, C1, D1;
  Vec<T> rho, u, x, x_next, cx, du, offset;
};

/// The output pass of a simulation: from the states x_k and the scheduling
/// ρ_k of every sample (rows of x and rho) and the LPV part's input u'
/// (u_model), the rows of sim.yhat, sim.z (with_z), sim.offset and then
/// sim.output. Each sample's outputs depend on that sample's x_k, ρ_k, u'_k
/// only, so this pass after the state pass gives the numbers of the one loop
/// that computed both, bit for bit. x and rho may be sim.x and sim.rho.
template <typename T>
void output_pass(const LpvModel<T>& model, const SystemMatrices<T>& s, const Mat<T>& x, const Mat<T>& rho,
                 const Mat<T>& u_model, bool with_z, Simulation<T>& sim) {
  const Eigen::Index n = x.rows();
  sim.yhat = Mat<T>::Zero(n, model.ny);
  sim.z = Mat<T>::Zero(with_z ? n : 0, model.nz());
  sim.offset = Mat<T>::Zero(n, model.ny);
  SimulationWorkspace<T> w;
  for (Eigen::Index k = 0; k < n; ++k) {
    if ((k & 255) == 0) check_stop();
    w.rho = rho.row(k).transpose();
    w.u = u_model.row(k).transpose();
    w.x = x.row(k).transpose();
    s.C.at_into(w.rho, w.C);
    s.D.at_into(w.rho, w.D);
    w.cx.noalias() = w.C * w.x;
    w.du.noalias() = w.D * w.u;
    sim.yhat.row(k) = (w.cx + w.du).transpose();
    if (with_z) {
      s.C1.at_into(w.rho, w.C1);
      s.D1.at_into(w.rho, w.D1);
      w.cx.noalias() = w.C1 * w.x;
      w.du.noalias() = w.D1 * w.u;
      sim.z.row(k) = (w.cx + w.du).transpose();
    }
    basis_sum_into(model.offset.basis, model.offset.values, model.ny, w.rho, w.offset);
    sim.offset.row(k) = w.offset.transpose();
  }
  sim.output = model.statics.output.apply(Mat<T>(sim.yhat + sim.offset));
}

}  // namespace detail

/// What a simulation computes: everything, or only what `output` needs (the
/// fits' residuals: the uncertainty channel z = C1 x + D1 u is left out and
/// sim.z is empty; x, yhat, offset, output and rho are the same numbers, bit
/// for bit, since z feeds nothing else).
enum class SimulationParts { kAll, kOutput };

/// One record: the state pass (x_k and the scheduling ρ_k, which may depend
/// on x_k), then the output pass (detail::output_pass).
template <typename T>
Simulation<T> simulate_one_record(const LpvModel<T>& model, const Experiment<T>& exp_in,
                                  SimulationParts parts = SimulationParts::kAll) {
  const SystemMatrices<T> s = system_matrices(model);
  const Experiment<T> exp = detail::with_state_columns(model, exp_in);  // may omit "@x<i>" columns
  check_experiment(model, exp);
  const Eigen::Index n = exp.n();
  Simulation<T> sim;
  sim.x = Mat<T>::Zero(n, model.nx);
  sim.rho = exp.rho;
  const std::vector<StateScheduled<T>> own = state_functions<T>(model.columns.rho, model.nx);
  const bool affine = has_state_offset(model);
  const Mat<T> u_model = model.statics.model_input(exp.u);  // u' = g_in(u_{k−d})
  Vec<T> x = model.x0.size() == 0 ? Vec<T>(Vec<T>::Zero(model.nx)) : model.x0;
  detail::SimulationWorkspace<T> w;
  w.rho.resize(exp.rho.cols());
  for (Eigen::Index k = 0; k < n; ++k) {
    if ((k & 255) == 0) check_stop();  // an exact simulation of a long record takes seconds: a stop is seen within 256 rows
    sim.x.row(k) = x.transpose();
    if (k + 1 == n) break;
    if (exp.rho.cols() > 0) w.rho = exp.rho.row(k).transpose();
    for (const StateScheduled<T>& f : own) {
      w.rho(f.j) = state_function_value(f.function, T(x(f.i)), f.shift);
      sim.rho(k, f.j) = w.rho(f.j);
    }
    w.u = u_model.row(k).transpose();
    s.A.at_into(w.rho, w.A);
    s.B.at_into(w.rho, w.B);
    w.x_next.noalias() = w.A * x + w.B * w.u;
    x.swap(w.x_next);
    if (affine) {  // E(ρ_k)
      basis_sum_into(model.state_offset.basis, model.state_offset.values, model.nx, w.rho, w.offset);
      x += w.offset;
    }
  }
  if (n > 0)  // the last sample's scheduling on its own state (no step follows it)
    for (const StateScheduled<T>& f : own) sim.rho(n - 1, f.j) = state_function_value(f.function, T(x(f.i)), f.shift);
  detail::output_pass(model, s, sim.x, sim.rho, u_model, parts == SimulationParts::kAll, sim);
  return sim;
}

/// The output of `model` on a trajectory simulated with another model that
/// has the same state equation (A, B, E, x0, input blocks and scheduling):
/// only C, D, the output offset and the output map may differ. The numbers
/// of simulate_output(model, exp) for a single record, without the state
/// pass. `trajectory` is simulate_one_record(other, exp) (x and rho used),
/// `u_model` = other.statics.model_input(exp.u).
template <typename T>
Mat<T> output_on_trajectory(const LpvModel<T>& model, const Simulation<T>& trajectory, const Mat<T>& u_model) {
  Simulation<T> out;
  detail::output_pass(model, system_matrices(model), trajectory.x, trajectory.rho, u_model, false, out);
  return std::move(out.output);
}

/// Record k of a stacked experiment (data/experiment.h) as an experiment of
/// its own (no record list).
template <typename T>
Experiment<T> record_of(const Experiment<T>& exp, Eigen::Index first, Eigen::Index rows) {
  Experiment<T> e;
  e.source = exp.source;
  e.u = exp.u.middleRows(first, rows);
  e.y = exp.y.middleRows(first, rows);
  e.rho = exp.rho.middleRows(first, rows);
  return e;
}

/// The state `model` starts record k from when the data give none of its
/// own: x0 for k = 0, LpvModel::later_x0[k-1] when it has nx values, else x0.
template <typename T>
Vec<T> record_start_state(const LpvModel<T>& model, size_t k) {
  if (k >= 1 && k - 1 < model.later_x0.size() && model.later_x0[k - 1].size() == model.nx) return model.later_x0[k - 1];
  return model.x0;
}

/// Simulates the model along the experiment: one record as
/// simulate_one_record; several records (exp.records) one after another,
/// each from its own initial state (exp.record_x0[k] when given, else the
/// model's own state of that record, LpvModel::later_x0, else model.x0),
/// with the model's input delays starting afresh in each record;
/// the trajectories are stacked like the records.
template <typename T>
Simulation<T> simulate(const LpvModel<T>& model, const Experiment<T>& exp, SimulationParts parts = SimulationParts::kAll) {
  if (exp.record_count() == 1 && exp.record_x0.empty()) return simulate_one_record(model, exp, parts);
  const std::vector<Eigen::Index> lengths = exp.record_lengths();
  if (!exp.record_x0.empty() && exp.record_x0.size() != lengths.size())
    throw std::invalid_argument(std::to_string(exp.record_x0.size()) + " initial states for " +
                                std::to_string(lengths.size()) + " records");
  Eigen::Index total = 0;
  for (const Eigen::Index l : lengths) total += l;
  if (total != exp.n())
    throw std::invalid_argument("the records' lengths add up to " + std::to_string(total) + ", not the " +
                                std::to_string(exp.n()) + " rows of the data");
  Simulation<T> sim;
  Eigen::Index first = 0;
  for (size_t k = 0; k < lengths.size(); ++k) {
    LpvModel<T> mk = model;
    mk.x0 = !exp.record_x0.empty() && exp.record_x0[k].size() != 0 ? exp.record_x0[k] : record_start_state(model, k);
    const Simulation<T> s = simulate_one_record(mk, record_of(exp, first, lengths[k]), parts);
    if (k == 0) {
      sim.x = Mat<T>(exp.n(), s.x.cols());
      sim.yhat = Mat<T>(exp.n(), s.yhat.cols());
      sim.z = Mat<T>(parts == SimulationParts::kAll ? exp.n() : 0, s.z.cols());
      sim.offset = Mat<T>(exp.n(), s.offset.cols());
      sim.output = Mat<T>(exp.n(), s.output.cols());
      sim.rho = Mat<T>(exp.n(), s.rho.cols());
    }
    sim.x.middleRows(first, lengths[k]) = s.x;
    sim.yhat.middleRows(first, lengths[k]) = s.yhat;
    if (parts == SimulationParts::kAll) sim.z.middleRows(first, lengths[k]) = s.z;
    sim.offset.middleRows(first, lengths[k]) = s.offset;
    sim.output.middleRows(first, lengths[k]) = s.output;
    sim.rho.middleRows(first, lengths[k]) = s.rho;
    first += lengths[k];
  }
  return sim;
}

/// simulate(model, exp).output, bit for bit, without the uncertainty channel z
/// (what a fit's residual and a free-run score need).
template <typename T>
Mat<T> simulate_output(const LpvModel<T>& model, const Experiment<T>& exp) {
  return simulate(model, exp, SimulationParts::kOutput).output;
}

/// Index of each scalar unknown θ_p of the correction (Theorem 3.1, eq. 10)
/// for an output with `n_out` rows whose correction is Σ_i f_i(ρ)(C_i x + D_i u):
/// basis i major; within basis i first C_i (n_out × nx) row-major, then D_i
/// (n_out × nu) row-major. So
///   θ[i·n_out·(nx+nu) + r·nx + c]             = C_i(r, c)
///   θ[i·n_out·(nx+nu) + n_out·nx + r·nu + c]  = D_i(r, c)
struct CorrectionLayout {
  Eigen::Index n_basis = 0, n_out = 0, nx = 0, nu = 0;

  Eigen::Index per_basis() const { return n_out * (nx + nu); }
  Eigen::Index size() const { return n_basis * per_basis(); }
  Eigen::Index index_C(Eigen::Index i, Eigen::Index r, Eigen::Index c) const {
    return i * per_basis() + r * nx + c;
  }
  Eigen::Index index_D(Eigen::Index i, Eigen::Index r, Eigen::Index c) const {
    return i * per_basis() + n_out * nx + r * nu + c;
  }
};

/// The θ layout of output_jacobian (n_out = ny).
template <typename T>
CorrectionLayout output_correction_layout(const LpvModel<T>& model) {
  return {static_cast<Eigen::Index>(model.correction.basis.size()), model.ny, model.nx, model.nu};
}

/// Regressors of the correction (eq. 10, 14–15): one n × (nx + nu) matrix per
/// basis function f_i, row k = f_i(ρ_k) [x_kᵀ u_kᵀ], so that
///   ŷ_k(θ) = ŷ_k + Σ_i [C_i D_i] · (row k of regressor i)ᵀ.
/// `sim` must be simulate(model, exp).
template <typename T>
std::vector<Mat<T>> correction_regressors(const LpvModel<T>& model, const Experiment<T>& exp,
                                          const Simulation<T>& sim) {
  check_experiment(model, exp);
  const Eigen::Index n = exp.n();
  if (sim.x.rows() != n || sim.x.cols() != model.nx)
    throw std::invalid_argument("correction_regressors: simulation does not match the experiment/model");
  const Mat<T> u_model = model.statics.model_input(exp.u);  // u' (model/static_blocks.h)
  std::vector<Mat<T>> out;
  for (const Monomial& f : model.correction.basis) {
    detail::check_basis(f, model.n_rho(), "correction basis");
    Mat<T> r(n, model.nx + model.nu);
    for (Eigen::Index k = 0; k < n; ++k) {
      const T fk = f.template eval<T>(detail::rho_at(exp.rho, k));
      r.row(k).head(model.nx) = fk * sim.x.row(k);
      r.row(k).tail(model.nu) = fk * u_model.row(k);
    }
    out.push_back(std::move(r));
  }
  return out;
}

/// Jacobian of a corrected output with `n_out` rows with respect to its
/// correction θ (layout: CorrectionLayout{N, n_out, nx, nu}):
/// (n·n_out) × (N·n_out·(nx+nu)), row k·n_out + r, with
///   ∂out_k(r)/∂C_i(r, c) = f_i(ρ_k) x_k(c),  ∂out_k(r)/∂D_i(r, c) = f_i(ρ_k) u_k(c),
/// all other entries zero. Exact: out(θ) = out(0) + J θ (stacked as in docs/design.md §4).
/// n_out = ny gives output_jacobian; n_out = nz gives the Jacobian of z for
/// the general structure's own C1_i, D1_i.
template <typename T>
Mat<T> correction_jacobian(const LpvModel<T>& model, const Experiment<T>& exp, const Simulation<T>& sim,
                           Eigen::Index n_out) {
  const std::vector<Mat<T>> reg = correction_regressors(model, exp, sim);
  const CorrectionLayout L{static_cast<Eigen::Index>(reg.size()), n_out, model.nx, model.nu};
  const Eigen::Index n = exp.n();
  Mat<T> J = Mat<T>::Zero(n * n_out, L.size());
  for (Eigen::Index i = 0; i < L.n_basis; ++i)
    for (Eigen::Index k = 0; k < n; ++k)
      for (Eigen::Index r = 0; r < n_out; ++r) {
        for (Eigen::Index c = 0; c < L.nx; ++c) J(k * n_out + r, L.index_C(i, r, c)) = reg[i](k, c);
        for (Eigen::Index c = 0; c < L.nu; ++c) J(k * n_out + r, L.index_D(i, r, c)) = reg[i](k, L.nx + c);
      }
  return J;
}

/// Theorem 3.1 / eq. 15: the exact linear part of the model output in the
/// unknown correction C_i (ny × nx), D_i (ny × nu):
///   stack(ŷ(θ)) = stack(sim.yhat) + J θ,
/// J is (n·ny) × (N·ny·(nx+nu)), θ ordered as output_correction_layout:
/// basis i major, then C_i row-major, then D_i row-major.
/// For the multiplicative structure (C1_i = W·C_i, D1_i = W·D_i, docs/design.md §5)
/// stack(z(θ)) = stack(sim.z) + W·J θ; for the additive structure z does not
/// depend on θ.
template <typename T>
Mat<T> output_jacobian(const LpvModel<T>& model, const Experiment<T>& exp, const Simulation<T>& sim) {
  return correction_jacobian(model, exp, sim, model.ny);
}

/// The model with a correction θ (layout output_correction_layout) folded
/// into C and D as extra terms f_i(ρ)·C_i, f_i(ρ)·D_i (e.g. for a certificate
/// or for simulating the identified model). The correction basis and its
/// fixed A_i, B_i are kept (they still act on the state).
template <typename T>
LpvModel<T> fold_correction(const LpvModel<T>& model, const Vec<T>& theta) {
  const CorrectionLayout L = output_correction_layout(model);
  if (theta.size() != L.size())
    throw std::invalid_argument("fold_correction: theta has length " + std::to_string(theta.size()) +
                                ", expected " + std::to_string(L.size()));
  const SystemMatrices<T> s = system_matrices(model);  // validates; gives sized C, D
  LpvModel<T> out = model;
  out.C = s.C;
  out.D = s.D;
  for (Eigen::Index i = 0; i < L.n_basis; ++i) {
    Mat<T> Ci(L.n_out, L.nx), Di(L.n_out, L.nu);
    for (Eigen::Index r = 0; r < L.n_out; ++r) {
      for (Eigen::Index c = 0; c < L.nx; ++c) Ci(r, c) = theta(L.index_C(i, r, c));
      for (Eigen::Index c = 0; c < L.nu; ++c) Di(r, c) = theta(L.index_D(i, r, c));
    }
    out.C.add(model.correction.basis[static_cast<size_t>(i)], Ci);
    out.D.add(model.correction.basis[static_cast<size_t>(i)], Di);
  }
  return out;
}

/// Jacobian of the offset Φ in its unknown values φ_j (paper eq. 20, docs/design.md §5)
/// when `model.offset.values` is empty: (n·ny) × (M·ny), M = offset basis
/// size, column j·ny + r holds h_j(ρ_k) in row k·ny + r. So
/// stack(Φ) = J_Φ [φ_1; …; φ_M].
template <typename T>
Mat<T> offset_jacobian(const LpvModel<T>& model, const Experiment<T>& exp) {
  check_experiment(model, exp);
  const Eigen::Index n = exp.n(), ny = model.ny;
  const Eigen::Index M = static_cast<Eigen::Index>(model.offset.basis.size());
  Mat<T> J = Mat<T>::Zero(n * ny, M * ny);
  for (Eigen::Index j = 0; j < M; ++j) {
    const Monomial& h = model.offset.basis[static_cast<size_t>(j)];
    detail::check_basis(h, model.n_rho(), "offset basis");
    for (Eigen::Index k = 0; k < n; ++k) {
      const T hk = h.template eval<T>(detail::rho_at(exp.rho, k));
      for (Eigen::Index r = 0; r < ny; ++r) J(k * ny + r, j * ny + r) = hk;
    }
  }
  return J;
}

}  // namespace lpvid

namespace lpvid {

/// The experiment with its "@x<i>" scheduling columns filled from the
/// model's own simulation (model/state_scheduling.h); unchanged otherwise.
/// Every consumer of exp.rho that does not simulate (Toeplitz matrices,
/// LMIs, regressors, the verifier) sees the trajectory through this.
template <typename T>
Experiment<T> with_state_scheduling(const LpvModel<T>& model, Experiment<T> exp) {
  if (state_scheduled(model.columns.rho, model.nx).empty()) return exp;
  exp.rho = simulate(model, exp).rho;  // full width even if exp omitted the "@x<i>" columns
  return exp;
}

}  // namespace lpvid
