// The loader of a claim's model and records (model/load_problem.h) on files
// written here, with answers by construction: two records, the second a
// window of its file's rows, each with its own initial state; the stacked
// data equals the numbers written, each reference names its file, its rows
// and the sha256 of its bytes; a window past the file's end is refused
// naming the file.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "core/file_io.h"
#include "core/input_error.h"
#include "core/sha256.h"
#include "model/load_problem.h"
#include "support/input_error_text.h"
#include "support/scratch_dir.h"

namespace lpvid {
namespace {

// x+ = x/2 + u, y = x: one state, one input, one output
const char* kLoaderModel =
    R"({"format": "lpvid-model/1", "states": 1, "inputs": 1, "outputs": 1, "scheduling": [], "columns": {"u": ["u"], "y": ["y"]},
        "initial": {"A": [{"basis": "1", "value": [["1/2"]]}], "B": [{"basis": "1", "value": [[1]]}],
                    "C": [{"basis": "1", "value": [[1]]}]},
        "uncertainty": {"structure": "additive", "weight": "1/10"}})";

// row k of a.csv: u = k/4, y = -k; row k of b.csv: u = 1/10 + k, y = k/8
const char* kLoaderA = "u,y\n0,0\n0.25,-1\n0.5,-2\n";
const char* kLoaderB = "u,y\n0.1,0\n1.1,0.125\n2.1,0.25\n3.1,0.375\n4.1,0.5\n";

InitialState constant_state(const Rational& x) {
  return [x](Eigen::Index nx) { return Vec<Rational>::Constant(nx, x); };
}

struct LoadProblem : ::testing::Test {
  gen::ScratchDir dir{"load-problem"};
  void SetUp() override {
    write_text_file(dir.file("model.json"), kLoaderModel, "model");
    write_text_file(dir.file("a.csv"), kLoaderA, "data");
    write_text_file(dir.file("b.csv"), kLoaderB, "data");
  }
  LoadedProblem load(std::pair<long, long> b_rows) const {
    const std::vector<RecordRequest> records = {{dir.file("a.csv"), std::nullopt, "", constant_state(Rational(3))},
                                                {dir.file("b.csv"), b_rows, "", constant_state(Rational(-1, 7))}};
    return load_problem(dir.file("model.json"), records, std::nullopt, bytes_on_disk());
  }
};

TEST_F(LoadProblem, StacksTheRecordsWithTheirWindowsAndInitialStates) {
  const LoadedProblem p = load({1, 4});
  ASSERT_EQ(p.exp_q.record_lengths(), (std::vector<Eigen::Index>{3, 3}));
  ASSERT_EQ(p.exp_d.record_lengths(), (std::vector<Eigen::Index>{3, 3}));
  for (long k = 0; k < 3; ++k) {  // a.csv, every row
    EXPECT_EQ(p.exp_q.u(k, 0), Rational(k) / Rational(4)) << k;
    EXPECT_EQ(p.exp_q.y(k, 0), Rational(-k)) << k;
  }
  for (long k = 1; k < 4; ++k) {  // b.csv, rows 1:4
    EXPECT_EQ(p.exp_q.u(2 + k, 0), Rational(1, 10) + Rational(k)) << k;
    EXPECT_EQ(p.exp_q.y(2 + k, 0), Rational(k) / Rational(8)) << k;
    EXPECT_EQ(p.exp_d.y(2 + k, 0), k / 8.0) << k;
  }
  ASSERT_EQ(p.exp_q.record_x0.size(), 2u);
  EXPECT_EQ(p.exp_q.record_x0[0], Vec<Rational>::Constant(1, Rational(3)));
  EXPECT_EQ(p.exp_q.record_x0[1], Vec<Rational>::Constant(1, Rational(-1, 7)));
  ASSERT_EQ(p.exp_d.record_x0.size(), 2u);
  EXPECT_EQ(p.exp_d.record_x0[1](0), -1.0 / 7.0);
  EXPECT_EQ(p.model_q.x0, Vec<Rational>::Zero(1));  // several records: the model's own x0 is kept
  ASSERT_EQ(p.records.size(), 2u);
  EXPECT_EQ(p.records[0].file, dir.file("a.csv"));
  EXPECT_EQ(p.records[0].row_begin, 0);
  EXPECT_EQ(p.records[0].row_end, -1);
  EXPECT_EQ(p.records[0].sha256, sha256_hex(kLoaderA));
  EXPECT_EQ(p.records[1].file, dir.file("b.csv"));
  EXPECT_EQ(p.records[1].row_begin, 1);
  EXPECT_EQ(p.records[1].row_end, 4);
  EXPECT_EQ(p.records[1].sha256, sha256_hex(kLoaderB));
}

TEST_F(LoadProblem, OneRecordsInitialStateIsTheModels) {
  const std::vector<RecordRequest> one = {{dir.file("b.csv"), std::nullopt, "", constant_state(Rational(5, 2))}};
  const LoadedProblem p = load_problem(dir.file("model.json"), one, std::nullopt, bytes_on_disk());
  EXPECT_EQ(p.model_q.x0, Vec<Rational>::Constant(1, Rational(5, 2)));
  EXPECT_EQ(p.model_d.x0(0), 2.5);
  EXPECT_TRUE(p.exp_q.record_x0.empty());
  EXPECT_EQ(p.exp_q.n(), 5);
}

TEST_F(LoadProblem, AWindowPastTheEndIsRefusedNamingTheFile) {
  EXPECT_EQ(gen::error_of([&] { load({2, 6}); }), "rows 2:6: " + dir.file("b.csv") + " has only 5 rows");
}

TEST_F(LoadProblem, HeldBytesAreReadNotTheFiles) {
  std::map<std::string, std::string> held = {{dir.file("model.json"), kLoaderModel}, {dir.file("b.csv"), kLoaderA}};
  const std::vector<RecordRequest> one = {{dir.file("b.csv"), std::nullopt, "", {}}};
  const LoadedProblem p = load_problem(dir.file("model.json"), one, std::nullopt, bytes_held(held));
  EXPECT_EQ(p.exp_q.n(), 3);  // a.csv's bytes under b.csv's name
  EXPECT_EQ(p.records[0].sha256, sha256_hex(kLoaderA));
  held.erase(dir.file("b.csv"));
  EXPECT_THROW(load_problem(dir.file("model.json"), one, std::nullopt, bytes_held(held)), InputError);
}

}  // namespace
}  // namespace lpvid
