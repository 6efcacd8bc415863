#pragma once
/// Generators and helpers for the identification / invalidation tests
/// (tests/identify; docs/design.md §5, §7, §8, §10). The cases are the library's
/// (examples/random_case.h, which says what is generated and why the truth
/// satisfies Theorem 2.1 at (δ, d_max) EXACTLY), drawn through rapidcheck
/// (support/rapidcheck_draw.h): each case is replayable from rapidcheck's seed
/// (rapidcheck properties) or from `sample(gen, seed)` in seeded TEST loops
/// (the seed is printed in failure messages), and shrinks.

#include <rapidcheck.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <unistd.h>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "core/rms.h"
#include "core/scalar.h"
#include "support/scratch_dir.h"
#include "data/csv_reader.h"
#include "data/csv_writer.h"
#include "data/data_reference.h"
#include "certify/certificate_files.h"
#include "data/experiment.h"
#include "data/experiment_builder.h"
#include "examples/random_case.h"
#include "toeplitz/affine_residual.h"
#include "certify/certify.h"
#include "lmi/bound_objective.h"
#include "model/lpv_model.h"
#include "model/monomial.h"
#include "model/param_matrix.h"
#include "model/simulate.h"
#include "support/gen_models.h"
#include "support/gen_numbers.h"
#include "support/rapidcheck_draw.h"

namespace lpvid {

/// Readable counterexamples (rapidcheck finds showValue by ADL, in RandomCase's namespace).
inline void showValue(const RandomCase& c, std::ostream& os) {
  os << "RandomCase delta=" << double_to_text(c.delta) << " dmax=" << double_to_text(c.dmax)
     << " zero inputs=" << c.zero_inputs << " delta delay=" << c.delay << "\n model:\n";
  showValue(c.model, os);
  if (!c.model.statics.empty())
    os << " static input " << to_string(c.model.statics.input.kind) << ", output "
       << to_string(c.model.statics.output.kind) << "\n";
  if (c.theta.size() > 0) {
    os << " true theta=";
    show_matrix(Mat<Rational>(c.theta), os);
    os << "\n";
  }
  os << " taps (K x ny*nz)=" << c.taps.rows() << "x" << c.taps.cols() << ": " << c.taps.transpose() << "\n ";
  showValue(c.exp, os);
}

}  // namespace lpvid

namespace lpvid::gen {

// The library's generator types under their test-suite names.
using IdentModelOptions = RandomModelOptions;
using IdentCaseOptions = RandomCaseOptions;
using IdentCase = RandomCase;
using random_case_detail::decimal_round;  // fir_*, all_monomials, generate_output, rms: namespace lpvid

/// The double nearest to each entry.
inline Mat<double> nearest_matrix(const Mat<Rational>& m) { return nearest_double(m); }

/// A model as described in examples/random_case.h; columns u1.., y1.., rho1...
inline rc::Gen<LpvModel<Rational>> ident_model(IdentModelOptions o = {}) {
  return drawn([o](RandomDraw& d) { return random_model(o, d); });
}

/// n samples (uniform in [min_n, max_n]) of u (entries ±0.1 … ±1, never 0)
/// and ρ (entries in [−1, 1], step 0.1); y empty.
inline rc::Gen<Experiment<Rational>> ident_trajectory(int nu, int n_rho, int min_n, int max_n) {
  return drawn([=](RandomDraw& d) { return random_trajectory(nu, n_rho, min_n, max_n, d); });
}

/// A model, a trajectory and data from a known truth (examples/random_case.h).
/// δ ∈ {0.05, …, 0.5}; d_max = f·rms(g_out(ŷ_true + Φ) + w), f ∈ {0.01, …, 0.3}.
inline rc::Gen<IdentCase> ident_case(IdentCaseOptions o = {}) {
  return drawn([o](RandomDraw& d) { return random_case(o, d); });
}

/// One sample of a generator with a fixed seed and size (for seeded TEST
/// loops; rapidcheck's own seed is used by rapidcheck properties instead).
template <typename T>
T sample(const rc::Gen<T>& g, uint64_t seed, int size = 50) {
  return g(rc::Random(seed), size).value();
}

// ------------------------------------------------------------------ files

// ScratchDir (a fresh temp directory, removed on destruction): support/scratch_dir.h

/// Writes u, y, ρ under the model's column names (exact decimal text).
inline void write_experiment_csv(const std::string& path, const LpvModel<Rational>& model, const Experiment<Rational>& e) {
  write_csv(path, experiment_columns(model.columns, e));
}

/// Reads a data file for a model, as the CLI does (exact or nearest double).
template <typename T>
Experiment<T> read_experiment(const std::string& path, const LpvModel<T>& model) {
  return make_experiment<T>(read_table(path), model.columns);
}

// ------------------------------------------------------------------ pipeline

/// p rounded to 12 significant digits and folded into the exact model, as
/// `lpvid identify` does before certifying (src/cli/identify_command.cc).
inline LpvModel<Rational> fold_rounded(const LpvModel<Rational>& model, const ParameterLayout& layout,
                                       const Vec<double>& p, int digits = 12) {
  Vec<Rational> q(p.size());
  for (Eigen::Index i = 0; i < p.size(); ++i) q(i) = round_to_digits(p(i), digits);
  return apply_parameters(model, layout, q);
}

/// Certify options for a data file (its reference: file, sha256; full-horizon Δ by default).
inline CertifyOptions certify_options(const BoundObjective& objective, const std::string& data_path, long max_taps = 0) {
  CertifyOptions o;
  o.objective = objective;
  o.records = {read_data_table(data_path).reference};
  o.max_taps = max_taps;
  return o;
}

/// What a front end does with a certification: its certificates written at
/// `certificate_path` (certify/certificate_files.h), for the tests that read
/// them back or hand them to the lpvid-verify program; returns `b`.
inline CertifiedBounds written(CertifiedBounds b, const std::string& certificate_path) {
  write_certificates(b, certificate_path);
  return b;
}

inline BoundObjective weighted_objective(double lambda = 0.5) {
  BoundObjective b;
  b.kind = BoundObjective::Kind::kWeighted;
  b.lambda = lambda;
  return b;
}
inline BoundObjective min_delta_objective(double dmax) {
  BoundObjective b;
  b.kind = BoundObjective::Kind::kMinDelta;
  b.dmax = dmax;
  return b;
}
inline BoundObjective min_dmax_objective(double delta) {
  BoundObjective b;
  b.kind = BoundObjective::Kind::kMinDmax;
  b.delta = delta;
  return b;
}
inline BoundObjective feasibility_objective(double delta, double dmax) {
  BoundObjective b;
  b.kind = BoundObjective::Kind::kFeasibility;
  b.delta = delta;
  b.dmax = dmax;
  return b;
}

/// The residual r = y − g_out(ŷ + Φ) of a fixed exact model, and z, as doubles (n × ny, n × nz).
struct FixedSignals {
  Mat<double> z, r;
};
inline FixedSignals fixed_signals(const LpvModel<Rational>& model, const Experiment<Rational>& exp) {
  const Simulation<Rational> sim = simulate(model, exp);
  return {nearest_matrix(sim.z), nearest_matrix(Mat<Rational>(exp.y - sim.output))};  // r = y − g_out(ŷ + Φ)
}

}  // namespace lpvid::gen
