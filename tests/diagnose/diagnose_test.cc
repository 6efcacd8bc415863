// diagnose() as a library call, on data made by
// construction (examples/effect_cases.h: the declared LPV system plus an
// undeclared output offset of 0.5 and white noise of std 0.02):
//  - it names the offset, and the bounds after are verified, their
//    certificates hold for the independent exact checker, and d_max falls
//    to the noise level while before it cannot (the offset is unexplained);
//  - the test role is scored last and chooses nothing: a different test set
//    (even a wrong one) leaves every choice and every exact bound unchanged,
//    and the score equals the free-run RMS of the chosen model on it;
//  - bad options are refused before any work.
#include <cmath>
#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "cli/certificate_names.h"
#include "data/data_reference.h"
#include "data/experiment_builder.h"
#include "diagnose/diagnose.h"
#include "fit/output_error_fit.h"
#include "examples/effect_cases.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

using gen::ScratchDir;

struct OffsetCase {
  LpvModel<double> declared;
  ExperimentViews est;  ///< each view read from the file
  Experiment<double> selection, test;
  std::string data;
};

OffsetCase offset_case(const ScratchDir& dir) {
  const EffectCase c = make_effect_case("output_offset", 200, 5, 0.02);
  OffsetCase o;
  o.data = dir.file("est.csv");
  gen::write_experiment_csv(o.data, c.declared, c.estimation);
  o.declared = convert_model<double>(c.declared);
  o.est.exp_q = gen::read_experiment<Rational>(o.data, c.declared);
  o.est.exp_d = gen::read_experiment<double>(o.data, o.declared);
  // the validation record of the case, cut in two: selection, then test
  const Experiment<double> val = nearest_double(c.validation);
  o.selection = select_rows(val, 0, 100);
  o.test = select_rows(val, 100, val.n());
  return o;
}

DiagnoseOptions options(const OffsetCase& c) {
  DiagnoseOptions o;
  o.ranking.max_effects = 1;
  o.windows = {{0, 80}};
  o.certify.records = {read_data_table(c.data).reference};
  o.certify.max_taps = 16;
  o.certify.full_horizon_limit = 0;
  return o;
}

TEST(Diagnose, CertificatePathsNameWindowAndSide) {
  EXPECT_EQ(cli::diagnose_certificate_path("d/c.json", 0, 1, false), "d/c.before.json");
  EXPECT_EQ(cli::diagnose_certificate_path("d/c.json", 0, 1, true), "d/c.after.json");
  EXPECT_EQ(cli::diagnose_certificate_path("d/c.json", 1, 3, true), "d/c.w2.after.json");
  EXPECT_EQ(cli::diagnose_certificate_path("d/c", 2, 3, false), "d/c.w3.before.json");
}

TEST(Diagnose, FindsTheOffsetAndTheTestSetChoosesNothing) {
  ScratchDir dir("diagnose-lib");
  const OffsetCase c = offset_case(dir);
  auto solver = make_solver("csdp");

  DiagnoseResult r = diagnose(c.declared, c.est, c.selection, {c.test}, options(c), *solver);
  cli::write_diagnose_certificates(r, dir.file("a.json"));  // as lpvid diagnose names them
  ASSERT_EQ(r.rank.chosen.size(), 1u);
  EXPECT_EQ(r.rank.chosen.front().kind, "output_offset");
  // the reported parameter is the certified (rounded, written) model's, exactly
  const auto& phi = r.rank.chosen.front().parameters["phi"];
  ASSERT_EQ(r.after_model.offset.values.size(), 1u);
  EXPECT_EQ(phi[0][0].get<double>(), r.after_model.offset.values[0](0));
  EXPECT_EQ(phi[0][0].get<double>(), nearest_double(r.after[0].model.offset.values[0](0)));  // the file reads its shortest decimal
  ASSERT_EQ(r.before.size(), 1u);
  ASSERT_EQ(r.after.size(), 1u);
  ASSERT_TRUE(r.verified()) << r.before[0].bounds.reason << " / " << r.after[0].bounds.reason;
  for (const auto* w : {&r.before[0], &r.after[0]}) {
    EXPECT_EQ(w->begin, 0);
    EXPECT_EQ(w->end, 80);
    const CertificateVerdict v = check_certificate_file(w->certificate);
    EXPECT_TRUE(v.holds) << w->certificate << ": " << v.reason;
  }
  EXPECT_EQ(r.after[0].certificate, dir.file("a.after.json"));
  // after: only the noise (std 0.02) is left; before: the 0.5 offset is not explained
  EXPECT_LT(r.after[0].bounds.dmax, 0.04);
  EXPECT_GT(r.before[0].bounds.dmax, 0.2);

  // what the report shows comes with the result (a second front end renders it):
  // the residual on the selection record, before and after, by free run
  const ShownRecord& shown = r.shown;
  EXPECT_FALSE(shown.last_fold);
  ASSERT_EQ(shown.data.n(), c.selection.n());
  ASSERT_TRUE(shown.finite);
  Mat<double> y_after;
  validation_rms(r.after_model, c.selection, DiagnoseOptions{}.ranking.init_samples, &y_after);
  EXPECT_EQ(shown.y_after, y_after);
  const Mat<double> res_after = c.selection.y - y_after;
  EXPECT_NEAR(shown.after.rms.overall, std::sqrt(res_after.squaredNorm() / static_cast<double>(res_after.size())), 1e-12);
  EXPECT_LT(shown.after.rms.overall, 0.04);  // the noise
  EXPECT_GT(shown.before.rms.overall, 0.2);  // the unexplained offset
  for (const RankingRound& rr : r.rank.rounds) {
    for (const ScoredCandidate& sc : rr.ranked) {
      EXPECT_TRUE(sc.estimation_share >= 0 && sc.estimation_share <= 1 + 1e-12) << sc.estimation_share;
    }
    if (rr.chosen >= 0) {
      EXPECT_GE(rr.ranked[static_cast<size_t>(rr.chosen)].estimation_share, kMinEstimationShare);
    }
  }
  // the offset candidate explains most of the declared model's estimation residual
  const RankingRound& first = r.rank.rounds.front();
  ASSERT_GE(first.chosen, 0);
  EXPECT_GT(first.ranked[static_cast<size_t>(first.chosen)].estimation_share, 0.5);
  ASSERT_EQ(r.estimation_after.rows(), c.est.exp_d.n());

  // the test role: the chosen models' free-run RMS, computed here again
  ASSERT_EQ(r.tests.size(), 1u);
  EXPECT_EQ(r.tests[0].samples, c.test.n());
  EXPECT_DOUBLE_EQ(r.tests[0].after.rms, warmup_score(r.after_model, c.test, DiagnoseOptions{}.test_warmup).rms);
  EXPECT_LT(r.tests[0].after.rms, 0.04);
  EXPECT_GT(r.tests[0].before.rms, 0.2);

  // a wrong test set (outputs scaled by 10) beside the right one, and no test
  // set at all, change no choice and no exact bound; two test sets are scored
  // separately, each as if it were alone
  Experiment<double> wrong = c.test;
  wrong.y *= 10.0;
  for (const std::vector<Experiment<double>>& t : {std::vector<Experiment<double>>{wrong, c.test}, std::vector<Experiment<double>>{}}) {
    const DiagnoseResult s = diagnose(c.declared, c.est, c.selection, t, options(c), *solver);
    ASSERT_EQ(s.tests.size(), t.size());
    ASSERT_EQ(s.rank.chosen.size(), 1u);
    EXPECT_EQ(s.rank.chosen.front().label, r.rank.chosen.front().label);
    ASSERT_TRUE(s.verified());
    EXPECT_EQ(s.before[0].bounds.delta2, r.before[0].bounds.delta2);
    EXPECT_EQ(s.before[0].bounds.dmax2, r.before[0].bounds.dmax2);
    EXPECT_EQ(s.after[0].bounds.delta2, r.after[0].bounds.delta2);
    EXPECT_EQ(s.after[0].bounds.dmax2, r.after[0].bounds.dmax2);
    if (!t.empty()) {
      EXPECT_GT(s.tests[0].after.rms, 2 * r.tests[0].after.rms);
      EXPECT_EQ(s.tests[1].after.rms, r.tests[0].after.rms);
      EXPECT_EQ(s.tests[1].before.rms, r.tests[0].before.rms);
    }
  }
}

TEST(Diagnose, BadOptionsAreRefusedBeforeAnyWork) {
  ScratchDir dir("diagnose-lib-bad");
  const OffsetCase c = offset_case(dir);
  auto solver = make_solver("csdp");
  DiagnoseOptions o = options(c);
  o.windows = {{150, 250}};  // the estimation record has 200 rows
  EXPECT_THROW(diagnose(c.declared, c.est, c.selection, {}, o, *solver), InputError);
  o = options(c);
  o.threads = 2;  // no solver factory
  EXPECT_THROW(diagnose(c.declared, c.est, c.selection, {}, o, *solver), InputError);
  o = options(c);
  const Experiment<double> short_sel = select_rows(c.selection, 0, 6);
  EXPECT_THROW(diagnose(c.declared, c.est, short_sel, {}, o, *solver), InputError);
  EXPECT_THROW(diagnose(c.declared, c.est, c.selection, {c.test, short_sel}, o, *solver), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir.file("x.before.json")));
}

}  // namespace
}  // namespace lpvid
