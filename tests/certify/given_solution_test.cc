// certify_fixed_model_from (certify/certify.h): a fixed model certified from a
// solve done elsewhere, as the class optimum is from the class bound's own
// solve. Its interval must be as tight as a fresh certification's and
// overlap it (both are exactly checked bounds of the same optimum); a
// solution of another program must still give a sound interval.
#include <gtest/gtest.h>

#include "certify/certify.h"
#include "examples/paper_example1.h"
#include "lmi/delta_form_barrier.h"
#include "model/simulate.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "support/scratch_dir.h"

namespace lpvid {
namespace {

struct GivenCase {
  LpvModel<Rational> model = example1_initial_model();
  Experiment<Rational> exp;
  CertifyOptions options;
  gen::ScratchDir dir{"given_solution"};
  Mat<double> z, r;
};

void make_given_case(const BoundObjective& objective, GivenCase& c) {
  Example1Options eo;
  eo.n = 40;
  eo.noise_variance = 0.01;
  c.exp = example1_experiment(eo);
  const std::string data = c.dir.file("data.csv");
  gen::write_experiment_csv(data, c.model, c.exp);
  c.options = gen::certify_options(objective, data);
  const Simulation<Rational> sim = simulate(c.model, c.exp);
  c.z = nearest_double(sim.z);
  c.r = nearest_double(Mat<Rational>(c.exp.y - sim.output));
}

/// The two intervals bound the same optimum: each lower end is at most the other's upper end.
void expect_same_optimum(const CertifiedBounds& a, const CertifiedBounds& b) {
  EXPECT_LE(a.lower.value, b.upper);
  EXPECT_LE(b.lower.value, a.upper);
}

TEST(GivenSolution, TheModelsOwnSolveGivesTheFreshInterval) {
  for (const BoundObjective& objective : {gen::weighted_objective(0.5), gen::min_dmax_objective(1.0)}) {
    GivenCase c;
    make_given_case(objective, c);
    auto solver = make_solver("csdp");
    const CertifiedBounds fresh = certify_fixed_model(c.model, c.exp, c.options, *solver);
    ASSERT_TRUE(fresh.verified() && fresh.lower.verified()) << fresh.reason << fresh.lower.reason;
    const DeltaFormSolution sol = solve_delta_form_barrier(c.z, c.r, c.options.objective);
    const CertifiedBounds given = certify_fixed_model_from(c.model, c.exp, c.options, *solver, sol);
    ASSERT_TRUE(given.verified() && given.lower.verified()) << given.reason << given.lower.reason;
    expect_same_optimum(fresh, given);
    EXPECT_EQ(given.solve_seconds, sol.solve.seconds) << "a second solve ran";
    EXPECT_LT(relative_gap(given), 1e-3);
  }
}

TEST(GivenSolution, ASolutionOfAnotherProgramStillGivesASoundInterval) {
  GivenCase c;
  make_given_case(gen::weighted_objective(0.5), c);
  auto solver = make_solver("csdp");
  const CertifiedBounds fresh = certify_fixed_model(c.model, c.exp, c.options, *solver);
  ASSERT_TRUE(fresh.verified() && fresh.lower.verified());
  // the program of a residual three times as large: its Δ and dual point are not this model's
  const DeltaFormSolution other = solve_delta_form_barrier(c.z, Mat<double>(3.0 * c.r), c.options.objective);
  const CertifiedBounds given = certify_fixed_model_from(c.model, c.exp, c.options, *solver, other);
  ASSERT_TRUE(given.verified() && given.lower.verified()) << given.reason << given.lower.reason;
  expect_same_optimum(fresh, given);
}

}  // namespace
}  // namespace lpvid
