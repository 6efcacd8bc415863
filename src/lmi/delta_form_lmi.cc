#include "lmi/delta_form_lmi.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "lmi/free_regressors.h"
#include "lmi/noise_block.h"
#include "core/rms.h"
#include "core/input_error.h"
#include "core/number_text.h"
#include "toeplitz/signal_toeplitz.h"

namespace lpvid {

void read_delta_solution(const SolveResult& solve, const DeltaScaledVariables& v, const BoundObjective& objective,
                         Mat<double>& taps, double& delta2, double& dmax2) {
  const Eigen::Index q = v.ny * v.nz;
  const double kz = v.sigma_z / v.sigma_r;  // h' = kz·h, t' = kz²·t, s' = s/σ_r²
  const bool ok = has_solution(solve.status);
  taps = Mat<double>::Zero(v.K, q);
  if (ok)
    for (Eigen::Index l = 0; l < v.K; ++l)
      for (Eigen::Index c = 0; c < q; ++c) taps(l, c) = solve.x[static_cast<size_t>(v.tap0 + l * q + c)] / kz;
  delta2 = v.t >= 0 && ok ? std::max(0.0, solve.x[static_cast<size_t>(v.t)]) / (kz * kz) : objective.delta.approx * objective.delta.approx;
  dmax2 = v.s >= 0 && ok ? std::max(0.0, solve.x[static_cast<size_t>(v.s)]) * v.sigma_r * v.sigma_r
                         : objective.dmax.approx * objective.dmax.approx;
}

namespace {

/// Σ_k m_k: the rows of the stack before each record's first nonzero z.
Eigen::Index count_head_rows(const Mat<double>& z, const RecordLengths& records) {
  const std::vector<Eigen::Index> start = record_starts(records);
  Eigen::Index m = 0;
  for (size_t k = 0; k < records.size(); ++k) m += leading_zero_rows(z, start[k], records[k]);
  return m;
}

/// The program and where its variables are.
struct DeltaFormLayout : SignalScaling {  ///< n, ny, nz, the scales σ_z, σ_r; L = records_horizon, m = head rows
  LmiProgram program;
  RecordLengths records;  ///< n_1 … n_K (one record: {n})
  Eigen::Index K = 0;
  int tap0 = -1;  ///< first tap variable: h_l(i, j) is tap0 + l·ny·nz + i·nz + j
  int t = -1;     ///< δ² (scaled), -1 if fixed
  int s = -1;     ///< d_max² (scaled), -1 if fixed
  int free0 = -1;  ///< first free variable f_c (column c of Q, lmi/free_regressors.h), -1 without
};

/// LmiProgram::about of a Δ-form program (what an outside solver's x means).
void describe(DeltaFormLayout& f, const BoundObjective& obj) {
  auto& a = f.program.about;
  a = {{"kind", kDeltaFormKind},
       {"theorem", "Theorem 2.1 for a fixed model, Delta form: (C1') [t I, T_Delta; T_Delta', I] >= 0 and (C2) "
                   "[n ny s, d'; d, I] >= 0 with d = r - Delta*z (lmi/delta_form_lmi.h)"},
       {"objective", obj.describe()},
       {"samples", std::to_string(f.n)},
       {"leading_zeros", std::to_string(f.m)},
       {"horizon", std::to_string(f.L)},
       {"taps", std::to_string(f.K)},
       {"ny", std::to_string(f.ny)},
       {"nz", std::to_string(f.nz)},
       {"sigma_z", double_to_text(f.sigma_z)},
       {"sigma_r", double_to_text(f.sigma_r)},
       {"scaling", "the solver saw z/sigma_z (samples leading_zeros..n-1 of z set its RMS) and r/sigma_r"},
       {"tap_variables", "h<l>[<i>,<j>] is entry (i, j) of tap l of Delta times sigma_z/sigma_r (original = value * "
                         "sigma_r / sigma_z)"}};
  if (f.t >= 0) a.emplace_back("delta2_variable", "delta2 is delta^2 times (sigma_z/sigma_r)^2 (original = value * "
                                                  "(sigma_r/sigma_z)^2)");
  else a.emplace_back("delta_fixed", double_to_text(obj.delta.approx));
  if (f.s >= 0) a.emplace_back("dmax2_variable", "dmax2 is d_max^2 / sigma_r^2 (original = value * sigma_r^2)");
  else a.emplace_back("dmax_fixed", double_to_text(obj.dmax.approx));
  if (obj.kind == BoundObjective::Kind::kWeighted) a.emplace_back("lambda", double_to_text(obj.lambda));
  if (several_records(f.records)) {
    std::string lengths;
    for (const Eigen::Index l : f.records) lengths += (lengths.empty() ? "" : " ") + std::to_string(l);
    a.emplace_back("records", lengths);
    a.emplace_back("records_meaning", "the rows are records of these lengths stacked, each from rest for Delta "
                                      "(Delta*z record by record); leading_zeros counts the rows before each "
                                      "record's first nonzero z, and sigma_z is the RMS of z from the first "
                                      "nonzero sample of the stack");
  }
}

/// Free regressors in (C2)'s block B: d' = r/σ_r − Δ'∗z' − Q f' with one free
/// variable f'_c per column of Q (f' = f/σ_r, Q f the free part G q of d).
void add_free_variables(DeltaFormLayout& f, const FreeRegressors& regressors, int B) {
  const Mat<double>& Q = regressors.basis();
  if (Q.cols() == 0) return;
  f.free0 = f.program.num_vars;
  for (Eigen::Index c = 0; c < Q.cols(); ++c) {
    const int v = f.program.add_variable("f" + std::to_string(c));
    for (Eigen::Index row = 0; row < Q.rows(); ++row)
      if (Q(row, c) != 0.0) f.program.add_entry(B, v, 0, static_cast<int>(1 + row), -Q(row, c));
  }
  f.program.about.emplace_back("free_variables", "f<c> times sigma_r is the coefficient of column c of an orthonormal "
                                                 "basis Q of the free regressors' range in d = r - Delta*z - Q f");
}

/// (C2)'s variable part, −Δ∗z record by record (as apply_fir_records: in
/// record k, row j ≥ m'_k = max(0, n_k − L) gets −Σ_{l ≤ j − m'_k, l < K} h_l z_{j−l})
/// in column 0 of the noise block B; the constant part r is add_noise_block's.
void add_fir_terms(DeltaFormLayout& f, const Mat<double>& zs, int B) {
  const std::vector<Eigen::Index> start = record_starts(f.records);
  const Eigen::Index taps_per = f.ny * f.nz;
  for (size_t rec = 0; rec < f.records.size(); ++rec) {
    const Eigen::Index first = std::max<Eigen::Index>(0, f.records[rec] - f.L);
    for (Eigen::Index k = first; k < f.records[rec]; ++k)
      for (Eigen::Index i = 0; i < f.ny; ++i) {
        const Eigen::Index row_z = start[rec] + k;
        const int row = static_cast<int>(1 + row_z * f.ny + i);
        for (Eigen::Index l = 0; l <= std::min(k - first, f.K - 1); ++l)
          for (Eigen::Index j = 0; j < f.nz; ++j)
            if (zs(row_z - l, j) != 0.0)
              f.program.add_entry(B, static_cast<int>(f.tap0 + l * taps_per + i * f.nz + j), 0, row, -zs(row_z - l, j));
      }
  }
}

DeltaFormLayout build(const Mat<double>& z, const Mat<double>& r, const BoundObjective& obj, Eigen::Index max_taps,
                      const RecordLengths& records, const FreeRegressors& regressors = {}) {
  obj.validate();
  if (z.rows() != r.rows()) throw std::invalid_argument("delta form: z and r have different lengths");
  DeltaFormLayout f;
  static_cast<SignalScaling&>(f) = signal_scaling(z, r);
  f.records = record_lengths_of(records, z.rows());
  f.L = records_horizon(z, f.records);
  f.m = count_head_rows(z, f.records);
  f.K = max_taps > 0 ? std::min(max_taps, f.L) : f.L;
  const Mat<double> zs = z / f.sigma_z;
  const Mat<double> rs = r / f.sigma_r;
  const double kz = f.sigma_z / f.sigma_r;  // Δ' = kz·Δ, t' = kz²·t

  LmiProgram& p = f.program;
  const Eigen::Index taps_per = f.ny * f.nz;
  f.tap0 = p.num_vars;
  for (Eigen::Index l = 0; l < f.K; ++l)
    for (Eigen::Index i = 0; i < f.ny; ++i)
      for (Eigen::Index j = 0; j < f.nz; ++j)
        p.add_variable("h" + std::to_string(l) + "[" + std::to_string(i) + "," + std::to_string(j) + "]");
  // Objective in original units divided by σ_r²: λ t + (1−λ) s = σ_r²[(λ/σ_z²) t' + (1−λ) s'].
  if (!obj.delta_fixed())
    f.t = p.add_variable("delta2", obj.kind == BoundObjective::Kind::kWeighted ? obj.lambda / (f.sigma_z * f.sigma_z) : 1.0);
  if (!obj.dmax_fixed())
    f.s = p.add_variable("dmax2", obj.kind == BoundObjective::Kind::kWeighted ? 1.0 - obj.lambda : 1.0);
  describe(f, obj);

  // (C1'): [t I, T_Δ; T_Δᵀ, I] ⪰ 0, size L·ny + L·nz.
  const int A = p.add_block("C1_delta_form", static_cast<int>(f.L * (f.ny + f.nz)));
  const int off = static_cast<int>(f.L * f.ny);
  const double t_fixed = obj.delta.approx * obj.delta.approx * kz * kz;
  for (int i = 0; i < off; ++i) {
    if (f.t >= 0)
      p.add_entry(A, f.t, i, i, 1.0);
    else
      p.add_entry(A, -1, i, i, t_fixed);
  }
  for (int i = off; i < off + static_cast<int>(f.L * f.nz); ++i) p.add_entry(A, -1, i, i, 1.0);
  for (Eigen::Index a = 0; a < f.L; ++a)
    for (Eigen::Index b = std::max<Eigen::Index>(0, a - f.K + 1); b <= a; ++b)
      for (Eigen::Index i = 0; i < f.ny; ++i)
        for (Eigen::Index j = 0; j < f.nz; ++j)
          p.add_entry(A, static_cast<int>(f.tap0 + (a - b) * taps_per + i * f.nz + j), static_cast<int>(a * f.ny + i),
                      static_cast<int>(off + b * f.nz + j), 1.0);

  // (C2): [N s, dᵀ; d, I] ⪰ 0, d = r − Δ∗z (record by record).
  const int B = add_noise_block(p, f.s, obj.dmax.approx * obj.dmax.approx / (f.sigma_r * f.sigma_r), rs);
  add_fir_terms(f, zs, B);
  add_free_variables(f, regressors, B);
  return f;
}

}  // namespace

DeltaFormProgram delta_form_program(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                    Eigen::Index max_taps, const RecordLengths& records) {
  DeltaFormLayout f = build(z, r, objective, max_taps, records);
  return {std::move(f.program), {f.K, f.ny, f.nz, f.tap0, f.t, f.s, f.sigma_z, f.sigma_r}, f.m, f.L};
}

namespace {

/// q and d = r − Δ∗z − G q of a solve (original units; Q f = G q).
void read_free_solution(DeltaFormSolution& out, const DeltaFormLayout& f, const FreeRegressors& regressors,
                        const Mat<double>& z, const Mat<double>& r) {
  Vec<double> e = stack_rows(Mat<double>(r - apply_fir_records(out.taps, z, f.ny, f.L, f.records)));
  if (regressors.count() == 0) {
    out.noise_residual = unstack_rows(e, f.ny);
    return;
  }
  Vec<double> Qf = Vec<double>::Zero(e.size());
  if (f.free0 >= 0 && has_solution(out.solve.status))
    for (Eigen::Index c = 0; c < regressors.rank(); ++c)
      Qf += regressors.basis().col(c) * (f.sigma_r * out.solve.x[static_cast<size_t>(f.free0 + c)]);
  out.free_coefficients = regressors.coefficients(Qf);
  out.noise_residual = unstack_rows(Vec<double>(e - regressors.matrix() * out.free_coefficients), f.ny);
}

}  // namespace

DeltaFormSolution solve_delta_form(const Mat<double>& z, const Mat<double>& r, const BoundObjective& objective,
                                   SdpSolver& solver, const SolverOptions& options, Eigen::Index max_taps,
                                   const Mat<double>& free_regressors, const RecordLengths& records) {
  const FreeRegressors regressors(free_regressors, z.rows(), r.cols(), "delta form");
  DeltaFormLayout f = build(z, r, objective, max_taps, records, regressors);
  DeltaFormSolution out;
  out.solve = solver.solve(f.program, options);
  out.leading_zeros = f.m;
  out.horizon = f.L;
  read_delta_solution(out.solve, {f.K, f.ny, f.nz, f.tap0, f.t, f.s, f.sigma_z, f.sigma_r}, objective, out.taps,
                      out.delta2, out.dmax2);
  read_free_solution(out, f, regressors, z, r);
  if (options.want_dual && out.solve.dual_blocks.size() == 2) {
    const double kz = f.sigma_z / f.sigma_r;
    const Eigen::Index off = f.L * f.ny;
    out.dual_c1 = out.solve.dual_blocks[0];
    out.dual_c1.topRows(off) *= kz;
    out.dual_c1.leftCols(off) *= kz;
    out.dual_c2 = out.solve.dual_blocks[1];
    out.dual_c2.row(0) /= f.sigma_r;
    out.dual_c2.col(0) /= f.sigma_r;
  }
  return out;
}

}  // namespace lpvid
