// Where a certification's time went (CertifiedBounds: signals, solve, the
// upper end's building and its one exact check, the lower end and its
// check): each stage that ran is timed, the parts fit inside their wholes,
// and the reports of invalidate/certify/identify carry every stage's field.
#include <gtest/gtest.h>

#include "certify/certify.h"
#include "cli/report.h"
#include "examples/paper_example1.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "support/scratch_dir.h"

namespace lpvid {
namespace {

// Example 1 at n = 40, min dmax at delta = 1: both ends certified, so every
// stage ran and took some time; the stages are disjoint parts of the call.
TEST(StageSeconds, EachStageIsTimedAndTheStagesFitInTheCall) {
  Example1Options eo;
  eo.n = 40;
  eo.noise_variance = 0.01;
  const LpvModel<Rational> model = example1_initial_model();
  const Experiment<Rational> exp = example1_experiment(eo);
  gen::ScratchDir dir("stage_seconds");
  const std::string data = dir.file("data.csv");
  gen::write_experiment_csv(data, model, exp);
  auto solver = make_solver("csdp");
  const CertifiedBounds b = certify_fixed_model(model, exp, gen::certify_options(gen::min_dmax_objective(1.0), data), *solver);
  ASSERT_TRUE(b.verified()) << b.reason;
  ASSERT_TRUE(b.lower.verified()) << b.lower.reason;
  EXPECT_GT(b.signals_seconds, 0);
  EXPECT_GT(b.solve_seconds, 0);
  EXPECT_GT(b.upper_build_seconds, 0);
  EXPECT_GT(b.verify_seconds, 0);
  EXPECT_GT(b.lower.check_seconds, 0);
  EXPECT_LT(b.lower.check_seconds, b.lower.seconds);
  EXPECT_LE(b.signals_seconds + b.solve_seconds + b.upper_build_seconds + b.verify_seconds + b.lower.seconds,
            b.total_seconds);
}

// Each stage's time lands in its own report field (distinct values, so that
// no field reports another's).
TEST(StageSeconds, TheReportsCarryEachStagesField) {
  CertifiedBounds b;
  b.signals_seconds = 1;
  b.solve_seconds = 2;
  b.upper_build_seconds = 3;
  b.verify_seconds = 4;
  b.lower.seconds = 5;
  b.lower.check_seconds = 6;
  b.total_seconds = 7;
  const nlohmann::ordered_json c = cli::bounds_json(b, "signal", "csdp", CertificateFiles{})["certification"];
  EXPECT_EQ(c["signals_seconds"], 1);
  EXPECT_EQ(c["solve_seconds"], 2);
  EXPECT_EQ(c["upper_build_seconds"], 3);
  EXPECT_EQ(c["verify_seconds"], 4);
  EXPECT_EQ(c["dual_seconds"], 5);
  EXPECT_EQ(c["dual_check_seconds"], 6);
  EXPECT_EQ(c["total_seconds"], 7);
  const nlohmann::ordered_json i = cli::interval_json(b, gen::min_dmax_objective(1.0), CertificateFiles{});
  EXPECT_EQ(i["lower_seconds"], 5);
  EXPECT_EQ(i["lower_check_seconds"], 6);
}

}  // namespace
}  // namespace lpvid
