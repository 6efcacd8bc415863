// diagnose on several estimation records of one plant (diagnose/fold_plan.h,
// diagnose/record_roles.h, diagnose/record_windows.h; docs/several_records.md).
// Known answers by construction:
//  - folds are made within the records: no block crosses a seam, the blocks
//    tile every record, each record gets its share (k <= R: one per record),
//    and a fold's training rows never contain its block nor cross a seam;
//  - one record reduces to the one-record rules (folds, training rows,
//    windows, pooled score of one test set = its own score);
//  - the done-when case: two records of the coupled-drives analogue (one
//    |·|-sensor plant, input amplitudes 1 and 0.5, each from rest) diagnosed
//    jointly find the analogue's declared effect (abs_value), and the bound
//    on a window meeting both records is ONE claim whose certificate lists
//    both records and holds for the independent exact checker;
//  - the pooled test score is the RMS over every scored sample of both test
//    records (recomputed here from the per-record figures).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli/certificate_names.h"
#include "cli/diagnose_report.h"
#include "data/data_reference.h"
#include "data/experiment_builder.h"
#include "diagnose/diagnose.h"
#include "diagnose/fold_plan.h"
#include "diagnose/record_roles.h"
#include "diagnose/record_windows.h"
#include "diagnose/window_identification.h"
#include "examples/plant_analogues.h"
#include "fit/linear_fit.h"
#include "fit/output_error_fit.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

/// The record that holds rows [b, e), or -1 when they cross a seam.
int record_holding(const std::vector<Eigen::Index>& records, Eigen::Index b, Eigen::Index e) {
  Eigen::Index first = 0;
  for (size_t k = 0; k < records.size(); ++k) {
    if (b >= first && e <= first + records[k]) return static_cast<int>(k);
    first += records[k];
  }
  return -1;
}

TEST(SeveralRecordsDiagnose, FoldsStayInsideTheRecords) {
  const std::vector<Eigen::Index> records{300, 200, 120};
  const Eigen::Index n = 620;
  for (int k : {2, 3, 4, 5, 7}) {
    const std::vector<FoldBlock> b = blocked_folds(records, k, 10);
    ASSERT_EQ(b.size(), static_cast<size_t>(std::max(k, 3))) << k;
    std::vector<int> per_record(3, 0);
    for (size_t j = 0; j < b.size(); ++j) {
      const int r = record_holding(records, b[j].first, b[j].last);
      ASSERT_GE(r, 0) << "fold " << j << " crosses a seam at k = " << k;
      ++per_record[static_cast<size_t>(r)];
      if (j > 0) {
        EXPECT_EQ(b[j].first, b[j - 1].last);  // they tile the stacked rows in order
      }
      // fold j's training rows: records whole or one side of the block, never the block
      for (const FoldBlock& p : training_pieces(records, b, j)) {
        EXPECT_GE(record_holding(records, p.first, p.last), 0);
        EXPECT_TRUE(p.last <= b[j].first || p.first >= b[j].last);
      }
    }
    EXPECT_EQ(b.front().first, 0);
    EXPECT_EQ(b.back().last, n);
    for (int c : per_record) EXPECT_GE(c, 1) << k;
  }
  // k = 7 over lengths 300, 200, 120: 4 extra blocks shared 1.94, 1.29, 0.77 → 1, 1, 1 + the
  // largest remainder (0.94, record 1): 3, 2, 2 blocks
  std::vector<int> per(3, 0);
  for (const FoldBlock& f : blocked_folds(records, 7, 10)) ++per[static_cast<size_t>(record_holding(records, f.first, f.last))];
  EXPECT_EQ(per, (std::vector<int>{3, 2, 2}));
  // the middle record's second block: its training rows are the other two records and the longer side
  const std::vector<FoldBlock> b = blocked_folds(records, 2, 10);  // folds = records
  EXPECT_EQ(b[1].first, 300);
  EXPECT_EQ(b[1].last, 500);
  const std::vector<FoldBlock> t = training_pieces(records, b, 1);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[0].first, 0);
  EXPECT_EQ(t[0].last, 300);
  EXPECT_EQ(t[1].first, 500);
  EXPECT_EQ(t[1].last, 620);
}

TEST(SeveralRecordsDiagnose, OneRecordIsTheOneRecordRule) {
  for (const Eigen::Index n : {100, 257, 600}) {
    const std::vector<FoldBlock> a = blocked_folds(std::vector<Eigen::Index>{n}, 4, 10), b = blocked_folds(n, 4, 10);
    ASSERT_EQ(a.size(), b.size());
    for (size_t j = 0; j < a.size(); ++j) {
      EXPECT_EQ(a[j].first, b[j].first);
      EXPECT_EQ(a[j].last, b[j].last);
      // the one-record rule: the longer of the two stretches beside the block (ties: the one before)
      const std::vector<FoldBlock> t = training_pieces({n}, a, j);
      ASSERT_EQ(t.size(), 1u);
      const bool before = b[j].first >= n - b[j].last;
      EXPECT_EQ(t[0].first, before ? 0 : b[j].last);
      EXPECT_EQ(t[0].last, before ? b[j].first : n);
    }
    const std::vector<JointWindow> w = joint_windows({n}, {});
    const std::vector<RowWindow> d = default_bound_windows(n);
    ASSERT_EQ(w.size(), d.size());
    for (size_t j = 0; j < w.size(); ++j) EXPECT_EQ(w[j], JointWindow{d[j]});
  }
}

TEST(SeveralRecordsDiagnose, JointWindowsAreTheRecordsWindowsSideBySide) {
  // records of 430 and 120 rows: tiles 0:200, 200:430 (a last 30 joins) and 0:120
  const std::vector<JointWindow> w = joint_windows({430, 120}, {});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], (JointWindow{{0, 200}, {430, 550}}));
  EXPECT_EQ(w[1], (JointWindow{{200, 430}}));
  // a given window is cut at the seam
  const std::vector<JointWindow> g = joint_windows({430, 120}, {{400, 500}, {0, 10}});
  EXPECT_EQ(g[0], (JointWindow{{400, 430}, {430, 500}}));
  EXPECT_EQ(g[1], (JointWindow{{0, 10}}));
}

void write_csv(const std::string& path, const Experiment<double>& e) {
  std::ofstream f(path);
  f << "u1,y1\n";
  char line[96];
  for (Eigen::Index k = 0; k < e.n(); ++k) {
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", e.u(k, 0), e.y(k, 0));
    f << line;
  }
}

TEST(SeveralRecordsDiagnose, PooledTestScoreIsOverEverySample) {
  const std::vector<Experiment<double>> t = abs_sensor_records(150, {1.0, 0.5}, 3);
  const Eigen::Index warmup = 10;
  // ŷ = 0 on both: the RMS is the RMS of the scored y; the pooled one is over both
  std::vector<Mat<double>> yh{Mat<double>::Zero(150, 1), Mat<double>::Zero(150, 1)};
  const FreeRunScore p = pooled_test_score(t, {&yh[0], &yh[1]}, warmup);
  const double s1 = t[0].y.bottomRows(140).squaredNorm(), s2 = t[1].y.bottomRows(140).squaredNorm();
  EXPECT_NEAR(p.rms, std::sqrt((s1 + s2) / 280.0), 1e-12);
  EXPECT_EQ(p.scored, 280);
  // one set: its own score's formula
  const FreeRunScore one = pooled_test_score({t[0]}, {&yh[0]}, warmup);
  EXPECT_NEAR(one.rms, std::sqrt(s1 / 140.0), 1e-12);
}

/// Two records of the coupled-drives analogue (amplitudes 1 and 0.5, each
/// from rest) in files, read as the estimation records of one diagnosis.
struct TwoRecords {
  gen::ScratchDir dir{"several-records-diagnose"};
  Eigen::Index n = 300;
  LpvModel<double> declared;
  RoleRecords roles;
  std::vector<Experiment<double>> tests = abs_sensor_records(200, {1.0, 0.5}, 8);
  DiagnoseOptions options;

  TwoRecords() {
    const std::vector<Experiment<double>> recs = abs_sensor_records(static_cast<int>(n), {1.0, 0.5}, 7);
    const std::string a = dir.file("amp1.csv"), b = dir.file("amp05.csv");
    write_csv(a, recs[0]);
    write_csv(b, recs[1]);
    // the declared model: the linear order fit-linear would choose on the first record
    const ColumnMap cols{{"u1"}, {"y1"}, {}};
    declared = choose_order(select_rows(recs[0], 0, 210), select_rows(recs[0], 210, n), cols, 5, true, 5).fit.model;
    RolePlan plan;
    plan.data_path = a;
    plan.more_data = {RecordSource{b, {}, {}, std::nullopt, ""}};
    plan.selection = SelectionRole::kFolds;
    plan.folds = 4;
    plan.warmup = 10;
    roles = load_role_records(plan, declared, declared);
    options.ranking.max_effects = 1;
    options.ranking.folds = 4;
    options.ranking.fold_warmup = 10;
    options.ranking.threads = 2;
    options.test_warmup = 10;
    options.windows = {{n - 100, n + 100}};  // meets both records: one claim over two pieces
    for (const EstimationRecord& r : roles.records) options.certify.records.push_back(r.data);
    options.certify.max_taps = 16;
    options.certify.full_horizon_limit = 0;
  }
};

TEST(SeveralRecordsDiagnose, TwoAmplitudesOfTheCoupledDrivesAnalogueDiagnosedJointly) {
  TwoRecords c;
  ASSERT_EQ(c.roles.records.size(), 2u);
  ASSERT_EQ(c.roles.est.exp_d.records, (std::vector<Eigen::Index>{c.n, c.n}));
  auto solver = make_solver("csdp");
  const DiagnoseResult r = diagnose(c.declared, c.roles.est, Experiment<double>{},
                                    c.tests, c.options, *solver);
  // the plant's effect, declared by the analogue
  ASSERT_FALSE(r.rank.chosen.empty());
  EXPECT_EQ(r.rank.chosen.front().kind, "abs_value");
  // 4 folds over 2 equal records: 2 blocks in each, none across the seam
  ASSERT_EQ(r.rank.fold_blocks.size(), 4u);
  for (const FoldBlock& f : r.rank.fold_blocks) EXPECT_GE(record_holding(c.roles.est.exp_d.records, f.first, f.last), 0);
  // the bound window is one claim over both records, naming each record's file rows
  ASSERT_EQ(r.after.size(), 1u);
  for (const WindowBounds* w : {&r.before[0], &r.after[0]}) {
    ASSERT_EQ(w->records.size(), 2u);
    EXPECT_EQ(w->records[0].file, c.roles.records[0].data.file);
    EXPECT_EQ(w->records[0].row_begin, c.n - 100);
    EXPECT_EQ(w->records[0].row_end, c.n);
    EXPECT_EQ(w->records[1].file, c.roles.records[1].data.file);
    EXPECT_EQ(w->records[1].row_begin, 0);
    EXPECT_EQ(w->records[1].row_end, 100);
  }
  // the optional Theorem 3.1 stage on the first window (inside the first
  // record) runs and names that record's file rows
  for (const WindowIdentification* id : {&r.before_id, &r.after_id}) {
    EXPECT_TRUE(id->failed.empty()) << id->failed;
    if (!id->applicable) continue;
    EXPECT_EQ(id->bounds.file_begin, c.n - 100);
    EXPECT_EQ(id->bounds.file_end, c.n);
  }
  // each test record scored once, and pooled over both
  ASSERT_EQ(r.tests.size(), 2u);
  const auto m = [](const TestScore& t) { return static_cast<double>(t.after.scored); };
  const double pooled = std::sqrt((r.tests[0].after.rms * r.tests[0].after.rms * m(r.tests[0]) +
                                   r.tests[1].after.rms * r.tests[1].after.rms * m(r.tests[1])) /
                                  (m(r.tests[0]) + m(r.tests[1])));
  EXPECT_NEAR(r.pooled_after.rms, pooled, 1e-9 * pooled);
  EXPECT_LT(r.pooled_after.rms, r.pooled_before.rms);

  // the report lists each estimation record; its figures are the after model's free run on
  // that record alone from the record's own fitted initial state, which the report states
  // (recomputed here record by record)
  cli::DiagnoseReport ri;
  ri.result = &r;
  ri.est = &c.roles.est.exp_d;
  ri.tests = &c.tests;
  ri.folds = true;
  ri.records = c.roles.records;
  const std::string report = c.dir.file("report.json");
  const cli::DiagnoseFigures figures = cli::draw_diagnose_figures(ri);
  cli::print_diagnose_text(ri, figures);
  cli::write_diagnose_json(ri, figures, report);
  std::ifstream f(report);
  const nlohmann::json j = nlohmann::json::parse(f);
  ASSERT_TRUE(j.contains("records"));
  ASSERT_EQ(j["records"].size(), 2u);
  ASSERT_TRUE(j.contains("tests_pooled"));
  EXPECT_NEAR(j["tests_pooled"]["rms_after"].get<double>(), pooled, 1e-9 * pooled);
  for (size_t k = 0; k < 2; ++k) {
    const nlohmann::json& e = j["records"][k];
    EXPECT_EQ(e["sha256"].get<std::string>(), c.roles.records[k].data.sha256);
    EXPECT_EQ(e["samples"].get<Eigen::Index>(), c.n);
    const Experiment<double> alone = select_rows(c.roles.est.exp_d, static_cast<Eigen::Index>(k) * c.n, static_cast<Eigen::Index>(k + 1) * c.n);
    LpvModel<double> from_own_state = r.after_model;
    from_own_state.later_x0.clear();
    ASSERT_EQ(e["x0_after"].size(), static_cast<size_t>(from_own_state.nx));
    for (Eigen::Index i = 0; i < from_own_state.nx; ++i) from_own_state.x0(i) = e["x0_after"][static_cast<size_t>(i)].get<double>();
    const Mat<double> res = alone.y - simulate(from_own_state, alone).output;
    EXPECT_NEAR(e["rms_after"].get<double>(), std::sqrt(res.squaredNorm() / static_cast<double>(res.size())), 1e-9);
  }
}

// Folds = records: each fold's training rows are the other record alone, so a
// candidate of a fold is built on a model with one initial state fewer than
// the whole estimation data's. It is still the same effect (regression: every
// candidate was unmatched on such folds, scored +inf, and none was chosen).
TEST(SeveralRecordsDiagnose, FoldsAsManyAsRecordsStillScoreEveryCandidate) {
  TwoRecords c;
  RankingOptions o = c.options.ranking;
  o.folds = 2;
  const RankingResult r = rank_effects(c.declared, c.roles.est.exp_d, Experiment<double>{}, o);
  ASSERT_EQ(r.fold_blocks.size(), 2u);
  ASSERT_FALSE(r.rounds.empty());
  size_t finite = 0;
  for (const ScoredCandidate& s : r.rounds.front().ranked) finite += std::isfinite(s.rms_validation) ? 1 : 0;
  EXPECT_GT(finite, r.rounds.front().ranked.size() / 2);
  ASSERT_FALSE(r.chosen.empty());
  EXPECT_EQ(r.chosen.front().kind, "abs_value");
}

// The joint bound window of two records: one certificate naming both
// records' rows, checked from the files.
TEST(SeveralRecordsDiagnose, JointBoundCertificateListsBothRecordsAndVerifies) {
  TwoRecords c;
  auto solver = make_solver("csdp");
  CertifyOptions o = diagnose_policy(c.options.certify);
  WindowBounds w = certify_joint_window(c.declared, c.roles.est,
                                        {{c.n - 100, c.n}, {c.n, c.n + 100}}, o, *solver);
  ASSERT_TRUE(w.bounds.verified()) << w.bounds.reason;
  cli::write_window_certificate(w, c.dir.file("c.json"), 0, 1, false);
  std::ifstream f(w.certificate);
  const nlohmann::json j = nlohmann::json::parse(f);
  ASSERT_TRUE(j.contains("records")) << w.certificate;
  EXPECT_EQ(j["records"].size(), 2u);
  const CertificateVerdict v = check_certificate_file(w.certificate);
  EXPECT_TRUE(v.holds) << w.certificate << ": " << v.reason;
}

// Theorem 3.1 on a window inside the SECOND record: the certificate names
// that record's file and its rows there (not the first record's file at
// stacked rows), and it is checked from the file.
TEST(SeveralRecordsDiagnose, WindowInTheSecondRecordIsCertifiedOnItsOwnFile) {
  TwoRecords c;
  auto solver = make_solver("csdp");
  CertifyOptions o = diagnose_policy(c.options.certify);
  o.lower_end = false;
  const ExperimentViews& est = c.roles.est;
  const WindowIdentification id = try_identify_on_window(c.declared, est, c.n + 10, c.n + 110, o, *solver);
  ASSERT_TRUE(id.failed.empty()) << id.failed;
  ASSERT_TRUE(id.applicable) << id.why_not;
  EXPECT_EQ(id.bounds.file_begin, 10);
  EXPECT_EQ(id.bounds.file_end, 110);
  ASSERT_TRUE(id.bounds.bounds.verified()) << id.bounds.bounds.reason;
  ASSERT_EQ(id.bounds.bounds.certificate->records.size(), 1u);
  const DataReference& named = id.bounds.bounds.certificate->records.front().data;
  EXPECT_EQ(named.file, c.roles.records[1].data.file);
  EXPECT_EQ(named.sha256, c.roles.records[1].data.sha256);
  EXPECT_EQ(named.row_begin, 10);
  EXPECT_EQ(named.row_end, 110);
  WindowBounds w = id.bounds;
  cli::write_window_certificate(w, c.dir.file("second.json"), 0, 1, false);
  const CertificateVerdict v = check_certificate_file(w.certificate);
  EXPECT_TRUE(v.holds) << w.certificate << ": " << v.reason;

  // the plain Theorem 2.1 window there names the same rows
  const WindowBounds b = certify_window(c.declared, est, c.n + 10, c.n + 110, o, *solver);
  EXPECT_EQ(b.file_begin, 10);
  EXPECT_EQ(b.file_end, 110);
  ASSERT_TRUE(b.bounds.verified()) << b.bounds.reason;
  EXPECT_EQ(b.bounds.certificate->records.front().data.file, c.roles.records[1].data.file);
}

}  // namespace
}  // namespace lpvid
