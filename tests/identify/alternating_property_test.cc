// Identification by alternating Δ/θ descent (identify/alternating_identify.h):
//  - every iterate (θ_k, Δ_k) is a feasible point of the TRUE BMI of
//    Theorem 3.1: with θ rounded to 12 digits and folded in, its own Δ
//    certifies exactly (certify_with_taps: no re-solve), with a certified
//    objective at most the iterate's (the finite-horizon ‖T_Δ‖ is at most
//    the KYP bound ‖Δ‖_∞ ≤ t);
//  - the objective never rises (a rise by the SDP's accuracy is allowed only
//    at the last iterate, which is then discarded) and the result is the
//    best iterate;
//  - the θ step is the least-squares optimum for its Δ;
//  - Example 1 (noise-free, full basis): both certified bounds ≤ 1e-4.
// Tolerances as in identify_property_test.cc (solver accuracy 1e-7 of the
// scaled objective; checks at 100× that).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>

#include "core/input_error.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "identify/alternating_identify.h"
#include "identify/identify.h"
#include "certify/certify.h"
#include "model/model_file.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "toeplitz/fir.h"
#include "toeplitz/signal_toeplitz.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

using namespace gen;

IdentifyOptions alternating(double lambda, long taps) {
  IdentifyOptions o;
  o.method = IdentifyMethod::kAlternating;
  o.objective = weighted_objective(lambda);
  o.taps = taps;
  o.max_iterations = 6;
  o.rel_tol = 1e-12;  // keep going: exercise several Delta/theta rounds
  return o;
}

double mean_square(const Mat<Rational>& y) {
  const Mat<double> d = nearest_matrix(y);
  return d.squaredNorm() / static_cast<double>(d.size());
}

/// Random LPV case with 1–2 correction terms, either structure.
IdentCaseOptions case_options(int max_n) {
  IdentCaseOptions o;
  o.model.min_rho = 0;
  o.model.max_rho = 2;
  o.model.min_correction = 1;
  o.model.max_correction = 2;
  o.model.allow_additive = true;
  o.min_n = 8;
  o.max_n = max_n;
  return o;
}

/// A case written to a data file and read back as the CLI would.
struct WrittenCase {
  ScratchDir dir;
  std::string data;
  Experiment<double> exp;
  Experiment<Rational> exp_q;
  double abs_tol = 0;  ///< 1e-7 × mean square of y (see the header)
  WrittenCase(const IdentCase& c, const char* tag) : dir(tag), data(dir.file("data.csv")) {
    write_experiment_csv(data, c.model, c.exp);
    exp = read_experiment(data, convert_model<double>(c.model));
    exp_q = read_experiment(data, c.model);
    abs_tol = 1e-7 * mean_square(c.exp.y);
  }
};

RC_GTEST_PROP(AlternatingProperty, EveryIterateCertifiesAndTheObjectiveNeverRises, ()) {
  IdentCaseOptions o = case_options(24);
  o.true_correction = *rc::gen::arbitrary<bool>();
  const IdentCase c = *ident_case(o);
  const double lambda = *rc::gen::element(0.5, 0.1, 0.9);
  const long taps = *rc::gen::element(1L, 3L, 8L);
  const WrittenCase wc(c, "alt");
  const auto& [dir, data, exp, exp_q, abs_tol] = wc;
  auto solver = make_solver("csdp");

  const IdentifyResult res = identify(convert_model<double>(c.model), exp, alternating(lambda, taps), *solver);
  RC_LOG() << to_string(c.model.uncertainty.structure) << ", n = " << exp.n() << ", lambda " << lambda << ", taps "
           << taps << ", " << res.relaxation << ", status " << to_string(res.status) << "\n";
  RC_ASSERT(has_solution(res.status));
  RC_ASSERT(!res.iterates.empty());
  double previous = std::numeric_limits<double>::infinity();
  double best = std::numeric_limits<double>::infinity();
  Vec<double> best_p;
  for (size_t i = 0; i < res.iterates.size(); ++i) {
    const IterateRecord& it = res.iterates[i];
    RC_ASSERT(has_solution(it.status));  // a failed Δ step would only be allowed after a good one; CSDP solves these
    RC_ASSERT(it.taps.rows() >= 1);
    RC_ASSERT(it.delta2 >= 0.0);
    RC_ASSERT(it.dmax2 >= 0.0);
    const LpvModel<Rational> fixed = fold_rounded(c.model, res.layout, it.p);
    const std::string cert = dir.file("it" + std::to_string(i) + ".json");
    const BoundObjective w = weighted_objective(lambda);
    const CertifiedBounds b = written(certify_with_taps(fixed, exp_q, it.taps, certify_options(w, data), "csdp"), cert);
    const double certified = w.value(nearest_double(b.delta2), nearest_double(b.dmax2));
    RC_LOG() << "  iterate " << i << ": objective " << it.objective << " (delta2 " << it.delta2 << ", dmax2 "
             << it.dmax2 << "), certified " << b.verified() << " " << certified << " " << b.reason << "\n";
    RC_ASSERT(b.verified());
    RC_ASSERT(check_certificate_file(cert).holds);
    RC_ASSERT(certified <= it.objective * (1 + 1e-4) + abs_tol);
    const bool last = i + 1 == res.iterates.size();
    if (!last) RC_ASSERT(it.objective <= previous * (1 + 1e-7) + abs_tol);
    if (it.objective < best) best = it.objective, best_p = it.p;
    previous = std::min(previous, it.objective);
  }
  RC_ASSERT(res.p.size() == best_p.size());
  RC_ASSERT((res.p - best_p).norm() == 0.0);
  RC_TAG(to_string(c.model.uncertainty.structure), res.iterates.size() > 2 ? "3+ Delta steps" : "1-2 Delta steps");
}

// Fixed bounds. Minimising d_max at a fixed δ (docs/design.md §7.6): every iterate
// certifies with that δ exactly (its taps are shrunk onto δ if the solver's
// tolerance put them above) and a certified d_max² at most the iterate's;
// deciding consistency at bounds slightly above a certified weighted result
// succeeds, and well below it does not report a solution.
RC_GTEST_PROP(AlternatingProperty, FixedBoundsAreHonoured, ()) {
  const IdentCase c = *ident_case(case_options(20));
  const WrittenCase wc(c, "alt-fixed");
  const auto& [dir, data, exp, exp_q, abs_tol] = wc;
  auto solver = make_solver("csdp");

  IdentifyOptions io = alternating(0.5, 4);
  const IdentifyResult w = identify(convert_model<double>(c.model), exp, io, *solver);
  RC_ASSERT(has_solution(w.status));
  const CertifiedBounds bw = written(certify_with_taps(fold_rounded(c.model, w.layout, w.p), exp_q, w.taps,
                                               certify_options(io.objective, data), "csdp"), dir.file("w.json"));
  RC_ASSERT(bw.verified());

  // minimise d_max at δ = the weighted result's δ
  io.objective = min_dmax_objective(bw.delta);
  const IdentifyResult f = identify(convert_model<double>(c.model), exp, io, *solver);
  RC_LOG() << "fixed delta " << bw.delta << ": " << to_string(f.status) << ", " << f.iterates.size() << " steps\n";
  RC_ASSERT(has_solution(f.status));
  for (size_t i = 0; i < f.iterates.size(); ++i) {
    const IterateRecord& it = f.iterates[i];
    if (!has_solution(it.status)) continue;
    const CertifiedBounds b = written(certify_with_taps(fold_rounded(c.model, f.layout, it.p), exp_q, it.taps,
                                                certify_options(io.objective, data), "csdp"), dir.file("f.json"));
    RC_LOG() << "  iterate " << i << ": dmax2 " << it.dmax2 << ", certified " << b.verified() << " "
             << nearest_double(b.dmax2) << " " << b.reason << "\n";
    RC_ASSERT(b.verified());
    RC_ASSERT(nearest_double(b.delta2) <= bw.delta * bw.delta * (1 + 1e-12));  // the fixed δ (as decimal text), squared
    RC_ASSERT(nearest_double(b.dmax2) <= it.dmax2 * (1 + 1e-4) + abs_tol);
  }

  // consistency just above the weighted result: shown; far below: no solution
  io.objective = feasibility_objective(bw.delta * 1.01, bw.dmax * 1.01);
  const IdentifyResult yes = identify(convert_model<double>(c.model), exp, io, *solver);
  RC_ASSERT(has_solution(yes.status));
  io.objective = feasibility_objective(0.0, bw.dmax * 1e-3);
  const IdentifyResult no = identify(convert_model<double>(c.model), exp, io, *solver);
  RC_LOG() << "feasibility above: " << to_string(yes.status) << ", far below: " << to_string(no.status) << "\n";
  RC_ASSERT(!has_solution(no.status) || bw.dmax == 0.0);
}

// The θ step is the least-squares optimum of d(p) = r(p) − T_Δ z(p) for its
// Δ: the normal equations hold.
RC_GTEST_PROP(AlternatingProperty, ParameterStepIsTheLeastSquaresOptimum, ()) {
  const IdentCase c = *ident_case(case_options(20));
  const LpvModel<double> md = convert_model<double>(c.model);
  const Experiment<double> exp = nearest_double(c.exp);
  const AffineResidual<double> a = build_affine_residual(md, exp, Unknowns{});
  const Eigen::Index K = *rc::gen::inRange(1, 5);
  Mat<double> taps(K, a.ny * a.nz);
  for (Eigen::Index i = 0; i < taps.size(); ++i) taps(i) = 0.1 * *rc::gen::inRange(-10, 11);
  double dmax2 = -1;
  const Vec<double> p = alternating_parameter_step(a, taps, &dmax2);
  RC_ASSERT(p.size() == a.num_params());
  RC_ASSERT(p.size() > 0);
  auto residual = [&](const Vec<double>& q) {
    const Mat<double> z = unstack_rows(a.z(q), a.nz);
    return Vec<double>(a.r(q) - stack_rows(apply_fir(taps, z, a.ny, z.rows())));
  };
  const Vec<double> d = residual(p);
  RC_ASSERT(std::abs(d.squaredNorm() / static_cast<double>(a.n * a.ny) - dmax2) <= 1e-9 * (1 + dmax2));
  // Normal equations: d(p) is affine, so column j of its Jacobian is d(p + e_j) − d(p) up to
  // rounding, and the optimum has every column orthogonal to d, up to rounding relative to the
  // size of the data's residual d(0).
  const double scale = residual(Vec<double>::Zero(p.size())).norm();
  for (Eigen::Index j = 0; j < p.size(); ++j) {
    Vec<double> q = p;
    q(j) += 1.0;
    const Vec<double> col = residual(q) - d;
    RC_LOG() << "column " << j << ": |col.d| " << std::abs(col.dot(d)) << ", |col| " << col.norm() << ", |d| "
             << d.norm() << ", |d(0)| " << scale << "\n";
    RC_ASSERT(std::abs(col.dot(d)) <= 1e-9 * col.norm() * scale + 1e-12 * scale * scale);
  }
}

// Example 1 (noise-free fixture, full basis; as example1_test.cc): the
// alternating method reaches the rounding floor too, certified with its own Δ.
TEST(AlternatingExample1, ReachesTheRoundingFloor) {
  const std::string dir_name = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/";
  const LpvModel<Rational> model_q = read_model_file<Rational>(dir_name + "initial_model.json");
  const LpvModel<double> model_d = read_model_file<double>(dir_name + "initial_model.json");
  const std::string data = dir_name + "noise_free_n40.csv";
  const TextTable table = read_table(data);
  const Experiment<Rational> exp_q = make_experiment<Rational>(table, model_q.columns);
  const Experiment<double> exp_d = make_experiment<double>(table, model_d.columns);
  auto solver = make_solver("csdp");
  IdentifyOptions io = alternating(0.5, 16);
  io.max_iterations = 25;
  const IdentifyResult res = identify(model_d, exp_d, io, *solver);
  ASSERT_TRUE(has_solution(res.status)) << res.message;
  ScratchDir dir("alt-example1");
  const LpvModel<Rational> fixed = fold_rounded(model_q, res.layout, res.p);
  const CertifiedBounds b =
      written(certify_with_taps(fixed, exp_q, res.taps, certify_options(io.objective, data), "csdp"), dir.file("c.json"));
  ASSERT_TRUE(b.verified()) << b.reason;
  std::cout << "[ example1 ] alternating: " << res.relaxation << ", certified delta = " << b.delta
            << ", dmax = " << b.dmax << "\n";
  EXPECT_LE(b.delta, 1e-4);
  EXPECT_LE(b.dmax, 1e-4);
}

TEST(AlternatingBadInput, ZeroUncertaintyChannelIsAnInputError) {
  const std::string dir_name = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/";
  const LpvModel<double> model = read_model_file<double>(dir_name + "initial_model.json");
  Experiment<double> exp = make_experiment<double>(read_table(dir_name + "noise_free_n40.csv"), model.columns);
  exp.u.setZero();
  auto solver = make_solver("csdp");
  EXPECT_THROW(identify(model, exp, alternating(0.5, 4), *solver), InputError);
}

}  // namespace
}  // namespace lpvid
