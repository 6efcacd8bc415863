#include "toeplitz/affine_residual.h"

#include <type_traits>

#include "core/finite_check.h"

#include <stdexcept>

#include "core/input_error.h"
#include "model/simulate.h"
#include "model/state_scheduling.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {
namespace {

template <typename T>
bool has_unknown_offset(const LpvModel<T>& model, const Unknowns& u) {
  return u.offset && !model.offset.basis.empty() && model.offset.values.empty();
}

void add_correction_names(std::vector<std::string>& names, const std::vector<Monomial>& basis,
                          const std::vector<std::string>& rho_names, Eigen::Index n_out, Eigen::Index nx,
                          Eigen::Index nu, const std::string& c, const std::string& d) {
  for (const Monomial& f : basis) {
    const std::string b = "[" + f.text(rho_names) + "]";
    for (Eigen::Index r = 0; r < n_out; ++r)
      for (Eigen::Index j = 0; j < nx; ++j)
        names.push_back(c + b + "(" + std::to_string(r + 1) + "," + std::to_string(j + 1) + ")");
    for (Eigen::Index r = 0; r < n_out; ++r)
      for (Eigen::Index j = 0; j < nu; ++j)
        names.push_back(d + b + "(" + std::to_string(r + 1) + "," + std::to_string(j + 1) + ")");
  }
}

}  // namespace

namespace {

/// Column blocks of Jr (= ∂ŷ/∂p) and Jz, in parameter order.
template <typename T>
struct JacobianBlocks {
  std::vector<Mat<T>> jy, jz;
  void add(Mat<T> y, Mat<T> z) {
    jy.push_back(std::move(y));
    jz.push_back(std::move(z));
  }
};

/// θ of the correction S_C(ρ) (eq. 10): C and D, and C1, D1 for the general structure.
template <typename T>
void add_correction_blocks(const LpvModel<T>& model, const Experiment<T>& exp, const Simulation<T>& sim,
                           AffineResidual<T>& a, JacobianBlocks<T>& blocks) {
  const bool multiplicative = model.uncertainty.structure == UncertaintyStructure::kMultiplicative;
  const Mat<T> J = output_jacobian(model, exp, sim);
  a.layout.n_theta_out = J.cols();
  blocks.add(J, multiplicative ? Mat<T>(model.uncertainty.weight * J) : Mat<T>(Mat<T>::Zero(a.n * a.nz, J.cols())));
  add_correction_names(a.names, model.correction.basis, model.scheduling, model.ny, model.nx, model.nu, "C", "D");
  if (model.uncertainty.structure != UncertaintyStructure::kGeneral) return;
  const Mat<T> J1 = correction_jacobian(model, exp, sim, a.nz);
  a.layout.n_theta_unc = J1.cols();
  blocks.add(Mat<T>::Zero(a.n * a.ny, J1.cols()), J1);
  add_correction_names(a.names, model.correction.basis, model.scheduling, a.nz, model.nx, model.nu, "C1", "D1");
}

/// φ of the output offset Φ(ρ).
template <typename T>
void add_offset_block(const LpvModel<T>& model, const Experiment<T>& exp, AffineResidual<T>& a, JacobianBlocks<T>& blocks) {
  const Mat<T> J = offset_jacobian(model, exp);
  a.layout.n_phi = J.cols();
  blocks.add(J, Mat<T>::Zero(a.n * a.nz, J.cols()));
  for (size_t j = 0; j < model.offset.basis.size(); ++j)
    for (int r = 0; r < model.ny; ++r)
      a.names.push_back("phi[" + model.offset.basis[j].text(model.scheduling) + "](" + std::to_string(r + 1) + ")");
}

/// Record k's own initial state: record_x0[k] when given, else the model's x0 (else 0).
template <typename T>
Vec<T> own_initial_state(const LpvModel<T>& model, const std::vector<Vec<T>>& record_x0, size_t k) {
  if (k < record_x0.size() && record_x0[k].size() != 0) return record_x0[k];
  return model.x0.size() == model.nx ? model.x0 : Vec<T>(Vec<T>::Zero(model.nx));
}

/// Column c of record `record`'s x0 block (record < 0: the one model x0) with
/// a state offset E(ρ): the response to x0 is not linear (E acts from x = 0,
/// and "@sqrt(x<i>-c)" columns follow x), so the column is the secant
/// sim(x0 + e_c) − sim(x0) along the actual input. Only the identification's
/// objective is approximate; the certificate checks the folded model (x0 +
/// p_x0) by its exact simulation.
template <typename T>
Simulation<T> x0_secant(const LpvModel<T>& model, const Experiment<T>& exp, int record, int c) {
  LpvModel<T> m1 = model;
  if (record < 0) {
    m1.x0 = own_initial_state(model, {}, 0);
    m1.x0(c) += T(1);
    return simulate(m1, exp);
  }
  Experiment<T> e1 = exp;
  e1.record_x0.resize(exp.records.size());
  for (size_t k = 0; k < exp.records.size(); ++k) e1.record_x0[k] = own_initial_state(model, exp.record_x0, k);
  e1.record_x0[static_cast<size_t>(record)](c) += T(1);
  return simulate(m1, e1);
}

/// The same column without a state offset: the simulation from e_c with zero
/// input (record ≥ 0: record `record` from e_c, the others from 0).
template <typename T>
Simulation<T> x0_free_response(const LpvModel<T>& model, const Experiment<T>& exp, int record, int c) {
  Experiment<T> free = exp;
  free.u.setZero();
  LpvModel<T> m0 = model;
  m0.offset.values.clear();
  m0.statics = StaticBlocks<T>{};  // zero u' (g_in(0) need not be 0)
  m0.x0 = Vec<T>::Zero(model.nx);
  if (record < 0) {
    m0.x0(c) = T(1);
  } else {
    free.record_x0.assign(exp.records.size(), Vec<T>::Zero(model.nx));
    free.record_x0[static_cast<size_t>(record)](c) = T(1);
  }
  return simulate(m0, free);
}

/// x0: the response of ŷ and z to each initial state (each record's own
/// with several records: K·nx columns, record k's zero off its rows).
template <typename T>
void add_x0_block(const LpvModel<T>& model, const Experiment<T>& exp, const Simulation<T>& sim, AffineResidual<T>& a,
                  JacobianBlocks<T>& blocks) {
  const bool per_record = several_records(a.records);
  const int K = per_record ? static_cast<int>(a.records.size()) : 1;
  Mat<T> Jy(a.n * a.ny, K * model.nx), Jz1(a.n * a.nz, K * model.nx);
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < model.nx; ++c) {
      const int record = per_record ? k : -1, col = k * model.nx + c;
      if (has_state_offset(model)) {
        const Simulation<T> s = x0_secant(model, exp, record, c);
        Jy.col(col) = stack_rows(Mat<T>(s.yhat - sim.yhat));
        Jz1.col(col) = stack_rows(Mat<T>(s.z - sim.z));
      } else {
        const Simulation<T> s = x0_free_response(model, exp, record, c);
        Jy.col(col) = stack_rows(s.yhat);
        Jz1.col(col) = stack_rows(s.z);
      }
      const std::string rec = per_record ? "[" + std::to_string(k + 1) + "]" : "";
      a.names.push_back("x0" + rec + "(" + std::to_string(c + 1) + ")");
    }
  a.layout.n_x0 = K * model.nx;
  a.layout.x0_records = K;
  blocks.add(Jy, Jz1);
}

}  // namespace

template <typename T>
std::string non_affine_unknowns(const LpvModel<T>& model, const Unknowns& unknowns) {
  if (!unknowns.x0 || model.nx == 0) return "";
  const std::string why = "the initial state x0 is among the unknowns, but ";
  const std::string fix = ": the residual is not affine in the unknowns, so no class claim over x0 is made (fix x0, "
                          "i.e. omit --free-x0, for a class bound)";
  if (unknowns.correction && !model.correction.basis.empty())
    return why + "the output correction C_i multiplies the state, which moves with x0 (yhat = (C + sum_i theta_i C_i) x(x0) "
                 "holds the product theta_i x0)" + fix;
  const auto own = state_scheduled(model.columns.rho, static_cast<int>(model.nx));
  if (!own.empty())
    return why + "the scheduling column '" + model.columns.rho[static_cast<size_t>(own.front().first)] +
           "' follows the state, which moves with x0 (rho, hence the model's matrices, depend on x0)" + fix;
  if (has_state_offset(model))
    return why + "the model has a state offset E(rho): the response to x0 is then not affine" + fix;
  return "";
}

template <typename T>
AffineResidual<T> build_affine_residual(const LpvModel<T>& model, const Experiment<T>& exp, const Unknowns& unknowns) {
  const Simulation<T> sim = simulate(model, exp);
  const bool any_unknown = (unknowns.correction && !model.correction.basis.empty()) ||
                           has_unknown_offset(model, unknowns) || (unknowns.x0 && model.nx > 0);
  if (any_unknown && model.statics.has_output())
    throw InputError("the model has a static output map (\"static\".\"output\", " +
                     std::string(to_string(model.statics.output.kind)) +
                     "): the output is then not affine in the unknowns, so Theorem 3.1 does not apply; fix the "
                     "parameters (e.g. by `lpvid diagnose`) and use `lpvid invalidate`");
  AffineResidual<T> a;
  a.n = exp.n();
  a.ny = model.ny;
  a.nz = model.nz();
  if (several_records(exp.records)) a.records = record_lengths_of(exp.records, exp.n());
  if (exp.y.rows() != exp.n() || exp.y.cols() != model.ny)
    throw std::invalid_argument("the experiment has no output y of size n x ny");
  a.z0 = stack_rows(sim.z);
  a.r0 = stack_rows(Mat<T>(exp.y - sim.output));

  JacobianBlocks<T> blocks;
  if (unknowns.correction && !model.correction.basis.empty()) add_correction_blocks(model, exp, sim, a, blocks);
  if (has_unknown_offset(model, unknowns)) add_offset_block(model, exp, a, blocks);
  if (unknowns.x0 && model.nx > 0) add_x0_block(model, exp, sim, a, blocks);
  Eigen::Index P = 0;
  for (const auto& b : blocks.jy) P += b.cols();
  a.Jr = Mat<T>::Zero(a.n * a.ny, P);
  a.Jz = Mat<T>::Zero(a.n * a.nz, P);
  Eigen::Index col = 0;
  for (size_t b = 0; b < blocks.jy.size(); ++b) {
    a.Jr.middleCols(col, blocks.jy[b].cols()) = blocks.jy[b];
    a.Jz.middleCols(col, blocks.jz[b].cols()) = blocks.jz[b];
    col += blocks.jy[b].cols();
  }
  if constexpr (std::is_same_v<T, double>) {  // what the identification's solvers will see
    const char* stage = "identification (Theorem 3.1: z and r affine in the unknowns)";
    check_finite_signal(a.z0, stage, "the model's uncertainty channel z");
    check_finite_signal(a.r0, stage, "the residual r = y - yhat");
    check_finite_signal(a.Jz, stage, "the sensitivity of z to the unknowns");
    check_finite_signal(a.Jr, stage, "the sensitivity of r to the unknowns");
  }
  return a;
}

template <typename T>
LpvModel<T> apply_parameters(const LpvModel<T>& model, const ParameterLayout& a, const Vec<T>& p) {
  if (p.size() != a.size())
    throw std::invalid_argument("apply_parameters: " + std::to_string(p.size()) + " values for " +
                                std::to_string(a.size()) + " parameters");
  LpvModel<T> out = model;
  Eigen::Index at = 0;
  if (a.n_theta_out > 0) {
    out = fold_correction(model, Vec<T>(p.segment(at, a.n_theta_out)));
    at += a.n_theta_out;
  }
  if (a.n_theta_unc > 0) {
    const SystemMatrices<T> s = system_matrices(out);
    out.uncertainty.C1 = s.C1;
    out.uncertainty.D1 = s.D1;
    const Eigen::Index nz = model.nz(), nx = model.nx, nu = model.nu;
    for (size_t i = 0; i < model.correction.basis.size(); ++i) {
      Mat<T> C1(nz, nx), D1(nz, nu);
      for (Eigen::Index r = 0; r < nz; ++r) {
        for (Eigen::Index c = 0; c < nx; ++c) C1(r, c) = p(at++);
      }
      for (Eigen::Index r = 0; r < nz; ++r) {
        for (Eigen::Index c = 0; c < nu; ++c) D1(r, c) = p(at++);
      }
      out.uncertainty.C1.add(model.correction.basis[i], C1);
      out.uncertainty.D1.add(model.correction.basis[i], D1);
    }
  }
  if (a.n_phi > 0) {
    out.offset.values.clear();
    for (size_t j = 0; j < model.offset.basis.size(); ++j) {
      out.offset.values.push_back(p.segment(at, model.ny));
      at += model.ny;
    }
  }
  if (a.n_x0 > 0 && a.x0_records <= 1) {
    // p holds the change of x0 from the model's own x0 (r0, z0 were simulated from it)
    const Vec<T> base = model.x0.size() == a.n_x0 ? model.x0 : Vec<T>(Vec<T>::Zero(a.n_x0));
    out.x0 = base + p.segment(at, a.n_x0);
    at += a.n_x0;
  }
  return out;
}

template <typename T>
std::vector<Vec<T>> record_initial_states(const LpvModel<T>& model, const std::vector<Vec<T>>& record_x0,
                                          const ParameterLayout& a, const Vec<T>& p) {
  if (a.n_x0 == 0 || a.x0_records <= 1) return record_x0;
  if (p.size() != a.size() || a.n_x0 != a.x0_records * model.nx)
    throw std::invalid_argument("record_initial_states: the parameters do not match the layout");
  const Eigen::Index at = a.size() - a.n_x0;  // x0 is the last segment
  std::vector<Vec<T>> out;
  for (Eigen::Index k = 0; k < a.x0_records; ++k)
    out.push_back(own_initial_state(model, record_x0, static_cast<size_t>(k)) + p.segment(at + k * model.nx, model.nx));
  return out;
}

template std::string non_affine_unknowns(const LpvModel<double>&, const Unknowns&);
template std::string non_affine_unknowns(const LpvModel<Rational>&, const Unknowns&);
template AffineResidual<double> build_affine_residual(const LpvModel<double>&, const Experiment<double>&, const Unknowns&);
template AffineResidual<Rational> build_affine_residual(const LpvModel<Rational>&, const Experiment<Rational>&,
                                                        const Unknowns&);
template LpvModel<double> apply_parameters(const LpvModel<double>&, const ParameterLayout&, const Vec<double>&);
template LpvModel<Rational> apply_parameters(const LpvModel<Rational>&, const ParameterLayout&, const Vec<Rational>&);
template std::vector<Vec<double>> record_initial_states(const LpvModel<double>&, const std::vector<Vec<double>>&,
                                                        const ParameterLayout&, const Vec<double>&);
template std::vector<Vec<Rational>> record_initial_states(const LpvModel<Rational>&, const std::vector<Vec<Rational>>&,
                                                          const ParameterLayout&, const Vec<Rational>&);

}  // namespace lpvid
