// The comparison of models with measured data (fit/compare_models.h) on
// answers known by construction: the true model on its own noise-free record
// scores fit 100 %, a window that starts mid-record needs its state (fitted,
// it scores 100 % again), records are pooled sample by sample, and a model
// that cannot be compared ends the comparison with the models before it kept.
#include <gtest/gtest.h>

#include <string>

#include "core/input_error.h"
#include "core/number_text.h"
#include "fit/compare_models.h"
#include "model/model_file.h"
#include "model/simulate.h"

namespace lpvid {
namespace {

/// x+ = a x + u, y = x, reading the columns "u" and "y" (a model file's text).
LpvModel<double> first_order(const std::string& a) {
  const std::string text = R"({"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": [],
    "columns": {"u": ["u"], "y": ["y"], "rho": []},
    "initial": {"A": [{"basis": "1", "value": [[)" + a + R"(]]}], "B": [{"basis": "1", "value": [[1]]}],
                "C": [{"basis": "1", "value": [[1]]}], "D": []},
    "uncertainty": {"structure": "additive", "weight": 1}})";
  return parse_model_json<double>(text, "first_order.json");
}

/// The model's noise-free record from x0 = 0 as a table (columns u, y),
/// the input a square wave of period 10.
CompareRecord record_of(const LpvModel<double>& m, Eigen::Index n, const std::string& file) {
  Experiment<double> e;
  e.u.resize(n, 1);
  for (Eigen::Index k = 0; k < n; ++k) e.u(k, 0) = (k / 5) % 2 == 0 ? 1.0 : -1.0;
  e.rho = Mat<double>(n, 0);
  const Mat<double> y = simulate(m, e).output;
  CompareRecord r;
  r.file = file;
  r.table.file = file;
  r.table.header = {"u", "y"};
  for (Eigen::Index k = 0; k < n; ++k) {
    r.table.rows.push_back({double_to_text(e.u(k, 0)), double_to_text(y(k, 0))});
    r.table.line_numbers.push_back(static_cast<long>(k) + 2);
  }
  return r;
}

TEST(CompareModels, TheTrueModelFitsItsRecordAndAWindowNeedsItsState) {
  const LpvModel<double> truth = first_order("0.8");
  CompareRecord window = record_of(truth, 60, "d.csv");
  window.rows = std::make_pair(30L, 60L);
  window.rows_text = "30:60";
  CompareOptions o;
  CompareResult from_zero = compare_models({truth}, {"t.json"}, {window}, o);
  ASSERT_FALSE(from_zero.failure);
  EXPECT_LT(from_zero.models.front().pooled.fit_percent_all, 99.0);  // x0 = 0 misses the state at row 30
  o.fit_x0 = true;
  o.warmup = 3;
  const CompareResult fitted = compare_models({truth}, {"t.json"}, {window}, o);
  ASSERT_FALSE(fitted.failure);
  const RecordComparison& c = fitted.models.front().records.front();
  EXPECT_EQ(c.first, 30);
  EXPECT_EQ(c.skip, 3);
  EXPECT_EQ(fitted.models.front().samples, 27);
  EXPECT_GT(c.scores.fit_percent_all, 99.999);
  EXPECT_EQ(fitted.models.front().pooled.rms_all, c.scores.rms_all);  // one record: pooled = its own
}

TEST(CompareModels, RecordsArePooledAndAModelThatCannotBeComparedEndsTheComparison) {
  const LpvModel<double> truth = first_order("0.8"), wrong = first_order("0.5");
  LpvModel<double> unreadable = truth;
  unreadable.columns.u = {"nope"};
  const std::vector<CompareRecord> records{record_of(truth, 40, "a.csv"), record_of(truth, 25, "b.csv")};
  const CompareResult r =
      compare_models({truth, wrong, unreadable, truth}, {"t.json", "w.json", "n.json", "t2.json"}, records, {});
  ASSERT_EQ(r.models.size(), 2u);
  EXPECT_EQ(r.models[0].samples, 65);
  EXPECT_GT(r.models[0].pooled.fit_percent_all, 99.999);
  EXPECT_LT(r.models[1].pooled.fit_percent_all, r.models[0].pooled.fit_percent_all);
  ASSERT_TRUE(r.failure);
  try {
    std::rethrow_exception(r.failure);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column 'nope' not found"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lpvid
