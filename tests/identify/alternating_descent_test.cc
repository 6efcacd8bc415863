// The alternating method alternates (identify/alternating_identify.h):
// iterate k's Δ step is solved at p_k, where the previous iterate's p step
// ended, so
//  (a) the objective J never rises from one iterate to the next, up to the
//      SDP's accuracy: Δ_{k−1} is a feasible point of iterate k's Δ step
//      (at p_k), so its optimum is at most J(p_k, Δ_{k−1}), the objective
//      of iterate k − 1; the p step only lowers it further. Only the
//      accepted iterates (all but a last one that rose or failed) must be
//      monotone exactly; a rise of the discarded one is allowed only by the
//      SDP's accuracy (below). The result is the last accepted iterate's
//      pair (p, taps);
//  (b) where the θ step matters (multiplicative structure: z moves with θ,
//      so Δ_0 changes the least-squares p), iterate 1's Δ step is solved
//      at p_1 ≠ p_0 and reaches a strictly lower objective (before the fix
//      every Δ step was solved at p_0 and iterate 1 repeated iterate 0);
//  (c) the final (p, taps) certifies exactly (certify_with_taps) with a
//      certified objective at most iterate 0's.
//
// Tolerance. The SDP backend stops at a relative duality gap of 1e-7 of the
// SCALED program (z and r divided by their RMS, delta_kyp_lmi.h), so an
// optimum is accurate to about 1e-7·(J + σ²) in original units, σ² the mean
// square of the residual; we allow a rise of 1e-7·J + 1e-7·ms(y) (ms(y) ≥ σ²
// up to the fit), the tolerance of alternating_property_test.cc.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "certify/certify.h"
#include "data/csv_reader.h"
#include "data/experiment_builder.h"
#include "identify/alternating_identify.h"
#include "identify/identify.h"
#include "model/model_file.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"

namespace lpvid {
namespace {

using namespace gen;

IdentifyOptions descent_options(const BoundObjective& objective, long taps, int max_iterations) {
  IdentifyOptions o;
  o.method = IdentifyMethod::kAlternating;
  o.objective = objective;
  o.taps = taps;
  o.max_iterations = max_iterations;
  o.rel_tol = 0;  // only a stall (no gain at all) or a rise ends the descent
  return o;
}

/// Random LPV case with 1–2 correction terms and a true θ on them;
/// multiplicative only (z moves with θ) or either structure.
IdentCaseOptions descent_case(bool multiplicative_only) {
  IdentCaseOptions o;
  o.model.min_rho = 0;
  o.model.max_rho = 2;
  o.model.min_correction = 1;
  o.model.max_correction = 2;
  o.model.allow_additive = !multiplicative_only;
  o.true_correction = true;
  o.min_n = 10;
  o.max_n = 24;
  return o;
}

double mean_square_y(const IdentCase& c) {
  const Mat<double> y = nearest_matrix(c.exp.y);
  return y.squaredNorm() / static_cast<double>(y.size());
}

/// The last iterate that the descent's rule accepts: every iterate is
/// accepted until one fails or rises above the previous accepted one.
size_t last_accepted(const IdentifyResult& r) {
  size_t k = 0;
  for (size_t i = 1; i < r.iterates.size(); ++i) {
    if (!has_solution(r.iterates[i].status) || r.iterates[i].objective > r.iterates[k].objective) break;
    k = i;
  }
  return k;
}

// (a), and the bookkeeping around it: iterate k's Δ step at iterate k − 1's
// p; the result is the accepted iterate's (p, taps).
RC_GTEST_PROP(AlternatingDescent, TheObjectiveNeverRisesAndThetaIsFedBack, ()) {
  const IdentCase c = *ident_case(descent_case(false));
  const double lambda = *rc::gen::element(0.5, 0.1, 0.9);
  const long taps = *rc::gen::element(2L, 4L, 8L);
  const Experiment<double> exp = nearest_double(c.exp);
  const double abs_tol = 1e-7 * mean_square_y(c);
  auto solver = make_solver("csdp");

  const IdentifyResult res =
      identify(convert_model<double>(c.model), exp, descent_options(weighted_objective(lambda), taps, 8), *solver);
  RC_LOG() << to_string(c.model.uncertainty.structure) << ", n = " << exp.n() << ", lambda " << lambda << ", "
           << res.relaxation << "\n";
  RC_ASSERT(has_solution(res.status));
  const AffineResidual<double> a = build_affine_residual(convert_model<double>(c.model), exp, Unknowns{});
  RC_ASSERT((res.iterates.front().p_delta_step - alternating_parameter_step(a, Mat<double>(), nullptr)).norm() == 0.0);
  for (size_t i = 1; i < res.iterates.size(); ++i) {
    const IterateRecord& prev = res.iterates[i - 1];
    const IterateRecord& it = res.iterates[i];
    RC_LOG() << "  iterate " << i << ": objective " << it.objective << " (previous " << prev.objective << ", change "
             << it.objective - prev.objective << ")\n";
    RC_ASSERT((it.p_delta_step - prev.p).norm() == 0.0);
    if (has_solution(it.status)) RC_ASSERT(it.objective <= prev.objective * (1 + 1e-7) + abs_tol);
  }
  const size_t k = last_accepted(res);
  for (size_t i = 1; i <= k; ++i) RC_ASSERT(res.iterates[i].objective <= res.iterates[i - 1].objective);
  RC_ASSERT((res.p - res.iterates[k].p).norm() == 0.0);
  RC_ASSERT(res.taps.rows() == res.iterates[k].taps.rows());
  RC_ASSERT((res.taps - res.iterates[k].taps).norm() == 0.0);
  RC_TAG(to_string(c.model.uncertainty.structure), res.iterates.size() > 2 ? "3+ Delta steps" : "1-2 Delta steps");
}

// (b): multiplicative structure, a true θ and a nonzero Δ in the data.
// Where iterate 0's Δ moved the least-squares p (the θ step matters),
// iterate 1's Δ step is solved at that new p, and its objective differs from
// iterate 0's (a different SDP; before the fix iterate 1 was iterate 0 again,
// bit for bit). How much it gains is not a property (the descent is local;
// measured on 150 such cases, seed 7: > 1e-6 relative in 93, > 1e-4 in 51,
// > 1e-2 in 11, at most 8 %; a rise within the SDP's accuracy in 8, then
// discarded), so only its sign is checked, in (a).
RC_GTEST_PROP(AlternatingDescent, IterateOneMovesWhereTheThetaStepMatters, ()) {
  const IdentCase c = *ident_case(descent_case(true));
  RC_PRE(!c.taps.isZero(0.0));
  const Experiment<double> exp = nearest_double(c.exp);
  auto solver = make_solver("csdp");
  const IdentifyResult res =
      identify(convert_model<double>(c.model), exp, descent_options(weighted_objective(0.5), 4, 2), *solver);
  RC_ASSERT(has_solution(res.status));
  RC_ASSERT(res.iterates.size() == 2u);
  const IterateRecord& i0 = res.iterates[0];
  const IterateRecord& i1 = res.iterates[1];
  const double moved = (i0.p - i0.p_delta_step).norm() / (1 + i0.p_delta_step.norm());
  RC_LOG() << "n = " << exp.n() << ", |taps_0| " << i0.taps.norm() << ", p moved " << moved << ", objectives "
           << i0.objective << " -> " << i1.objective << " (relative gain "
           << (i0.objective - i1.objective) / i0.objective << ")\n";
  RC_PRE(moved > 0.0);
  RC_ASSERT(has_solution(i1.status));
  RC_ASSERT((i1.p_delta_step - i0.p).norm() == 0.0);
  RC_ASSERT((i1.p_delta_step - i0.p_delta_step).norm() > 0.0);
  RC_ASSERT(i1.objective != i0.objective);
  const double gain = (i0.objective - i1.objective) / i0.objective;
  RC_TAG(gain > 1e-4 ? "gain > 1e-4" : gain > 0 ? "gain in (0, 1e-4]" : "rise (discarded)");
}

// (c): the final pair certifies exactly, no higher than iterate 0's objective.
RC_GTEST_PROP(AlternatingDescent, TheFinalPairCertifiesBelowTheFirstIterate, ()) {
  const IdentCase c = *ident_case(descent_case(false));
  ScratchDir dir("alt-descent");
  const std::string data = dir.file("data.csv");
  write_experiment_csv(data, c.model, c.exp);
  const Experiment<double> exp = read_experiment(data, convert_model<double>(c.model));
  const Experiment<Rational> exp_q = read_experiment(data, c.model);
  const BoundObjective w = weighted_objective(0.5);
  auto solver = make_solver("csdp");
  const IdentifyResult res = identify(convert_model<double>(c.model), exp, descent_options(w, 4, 8), *solver);
  RC_ASSERT(has_solution(res.status));
  const CertifiedBounds b =
      certify_with_taps(fold_rounded(c.model, res.layout, res.p), exp_q, res.taps, certify_options(w, data), "csdp");
  const double certified = w.value(nearest_double(b.delta2), nearest_double(b.dmax2));
  RC_LOG() << res.relaxation << ": certified " << b.verified() << " " << certified << ", iterate 0 "
           << res.iterates.front().objective << " " << b.reason << "\n";
  RC_ASSERT(b.verified());
  RC_ASSERT(certified <= res.iterates.front().objective * (1 + 1e-4) + 1e-7 * mean_square_y(c));
}

// The Example 1 noise-free fixture, basis {1, ρ1, ρ2} (docs/benchmarks.md, "--method
// alternating"). W = 0.01 makes z about 1 % of y, so Δ is dear: at λ = 0.5
// the least-squares start is stationary (iterate 1 is solved at a different
// p, since Δ_0 ≠ 0 moves the least-squares p, but gains nothing), and the
// descent ends below the paper's single relaxation step (an independent
// method: the linearised BMI in the w form); at λ = 1e-4 Δ pays, and
// iterate 1 gains far more than the SDP's accuracy (1e-7 relative).
TEST(AlternatingDescentExample1, DistinctIteratesEndBelowTheRelaxation) {
  const std::string dir_name = std::string(LPVID_SOURCE_DIR) + "/fixtures/example1/";
  LpvModel<double> model = read_model_file<double>(dir_name + "initial_model.json");
  const Monomial one{{0, 0}}, r1{{1, 0}}, r2{{0, 1}};
  model.correction = zero_correction<double>({one, r1, r2}, model.nx, model.nu);  // as --basis 1,rho1,rho2
  const Experiment<double> exp = make_experiment<double>(read_table(dir_name + "noise_free_n40.csv"), model.columns);
  auto solver = make_solver("csdp");
  IdentifyOptions io = descent_options(weighted_objective(0.5), 16, 25);
  io.rel_tol = 1e-4;  // the CLI's default
  const IdentifyResult alt = identify(model, exp, io, *solver);
  ASSERT_TRUE(has_solution(alt.status)) << alt.message;
  ASSERT_GE(alt.iterates.size(), 2u);
  EXPECT_GT((alt.iterates[1].p_delta_step - alt.iterates[0].p_delta_step).norm(), 0.0);
  const IdentifyResult relaxation = identify(model, exp, IdentifyOptions{}, *solver);
  ASSERT_TRUE(has_solution(relaxation.status)) << relaxation.message;
  const double relaxed = relaxation.iterates.front().objective;
  const double ended = alt.iterates[last_accepted(alt)].objective;
  std::cout << std::scientific << std::setprecision(6) << "[ example1 ] lambda 0.5: " << alt.relaxation
            << ", objective " << alt.iterates[0].objective << " -> "
            << ended << "; relaxation " << relaxed << "\n";
  EXPECT_LE(ended, relaxed);

  io.objective = weighted_objective(1e-4);
  const IdentifyResult cheap = identify(model, exp, io, *solver);
  ASSERT_TRUE(has_solution(cheap.status)) << cheap.message;
  ASSERT_GE(cheap.iterates.size(), 2u);
  std::cout << "[ example1 ] lambda 1e-4: " << cheap.relaxation << ", objective " << cheap.iterates[0].objective
            << " -> " << cheap.iterates[1].objective << std::defaultfloat << "\n";
  EXPECT_LT(cheap.iterates[1].objective, cheap.iterates[0].objective * (1 - 1e-4));
}

}  // namespace
}  // namespace lpvid
