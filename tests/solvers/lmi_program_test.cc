#include "solvers/lmi_program.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "support/gen_lmi.h"

namespace lpvid {
namespace {

template <typename F>
std::string invalid_argument_message(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "<no std::invalid_argument thrown>";
}

TEST(LmiProgramTest, AddEntryStoresTheUpperTriangleAndSumsDuplicates) {
  LmiProgram p;
  const int x = p.add_variable("x", 2.0);
  const int b = p.add_block("B", 3);
  p.add_entry(b, x, 2, 0, 1.5);  // stored as (0, 2)
  p.add_entry(b, x, 0, 2, 0.5);
  p.add_entry(b, -1, 1, 1, -1.0);
  p.compress();
  ASSERT_EQ(p.blocks[0].Fi.size(), 1u);
  EXPECT_EQ(p.blocks[0].Fi[0].second.entries, (std::vector<SymEntry>{{0, 2, 2.0}}));
  EXPECT_EQ(p.blocks[0].F0.entries, (std::vector<SymEntry>{{1, 1, -1.0}}));
  EXPECT_EQ(p.cost, (std::vector<double>{2.0}));
  EXPECT_EQ(p.var_names, (std::vector<std::string>{"x"}));
}

TEST(LmiProgramTest, CompressMergesPairsOfOneVariableAndDropsZeros) {
  LmiProgram p;
  p.add_variables(2);
  const int b = p.add_block("B", 2);
  p.add_entry(b, 1, 0, 0, 1.0);
  p.add_entry(b, 0, 0, 1, 1.0);
  p.add_entry(b, 1, 1, 1, 3.0);  // a second pair for variable 1
  p.add_entry(b, 0, 0, 1, -1.0);  // variable 0 cancels to nothing
  EXPECT_EQ(p.blocks[0].Fi.size(), 4u);  // 1, 0, 1, 0: a new pair at each switch
  p.compress();
  ASSERT_EQ(p.blocks[0].Fi.size(), 1u);
  EXPECT_EQ(p.blocks[0].Fi[0].first, 1);
  EXPECT_EQ(p.blocks[0].Fi[0].second.entries, (std::vector<SymEntry>{{0, 0, 1.0}, {1, 1, 3.0}}));
}

TEST(LmiProgramTest, BadEntriesThrowNamingBlockVariableAndEntry) {
  LmiProgram p;
  const int t = p.add_variable("t");
  const int b = p.add_block("C1", 2);
  const int d = p.add_block("bounds", 2, true);
  std::string m = invalid_argument_message([&] { p.add_entry(b, t, 0, 2, 1.0); });
  EXPECT_NE(m.find("'C1'"), std::string::npos) << m;
  EXPECT_NE(m.find("variable 't'"), std::string::npos) << m;
  EXPECT_NE(m.find("(0, 2)"), std::string::npos) << m;
  m = invalid_argument_message([&] { p.add_entry(d, t, 0, 1, 1.0); });
  EXPECT_NE(m.find("off-diagonal entry in a diagonal block"), std::string::npos) << m;
  m = invalid_argument_message([&] { p.add_entry(b, -1, 1, 1, std::numeric_limits<double>::quiet_NaN()); });
  EXPECT_NE(m.find("not finite"), std::string::npos) << m;
  EXPECT_NE(m.find("F0 (constant term)"), std::string::npos) << m;
  EXPECT_THROW(p.add_entry(b, 1, 0, 0, 1.0), std::invalid_argument);   // unknown variable
  EXPECT_THROW(p.add_entry(5, 0, 0, 0, 1.0), std::invalid_argument);   // unknown block
  EXPECT_THROW(p.add_block("empty", 0), std::invalid_argument);
  EXPECT_THROW(p.set_cost(0, std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(p.add_scalar_inequality({{3, 1.0}}, 0.0), std::invalid_argument);
  EXPECT_NO_THROW(p.validate());
}

TEST(LmiProgramTest, ValidateCatchesHandEditedPrograms) {
  LmiProgram p;
  p.add_variables(1);
  p.add_block("B", 2);
  p.blocks[0].F0.entries.push_back({1, 0, 1.0});  // lower triangle
  EXPECT_NE(invalid_argument_message([&] { p.validate(); }).find("i <= j"), std::string::npos);
  p.blocks[0].F0.entries.clear();
  p.cost.push_back(1.0);
  EXPECT_NE(invalid_argument_message([&] { p.validate(); }).find("cost has 2 entries"), std::string::npos);
  p.cost.pop_back();
  p.blocks[0].Fi.emplace_back(4, SymSparse{});
  EXPECT_NE(invalid_argument_message([&] { p.validate(); }).find("variable 4 out of range"), std::string::npos);
}

TEST(LmiProgramTest, ScalarInequalitiesShareOneDiagonalBlock) {
  LmiProgram p;
  p.add_variables(2);
  EXPECT_EQ(p.add_scalar_inequality({{0, 1.0}}, -1.0), std::make_pair(0, 0));
  EXPECT_EQ(p.add_scalar_inequality({{0, 1.0}, {1, 1.0}}, -4.0), std::make_pair(0, 1));
  ASSERT_EQ(p.blocks.size(), 1u);
  EXPECT_TRUE(p.blocks[0].diagonal);
  EXPECT_EQ(p.blocks[0].size, 2);
  const Eigen::MatrixXd v = p.block_value(0, {2.0, 3.0});
  EXPECT_EQ(v(0, 0), 1.0);
  EXPECT_EQ(v(1, 1), 1.0);
  EXPECT_EQ(v(0, 1), 0.0);
}

TEST(LmiProgramTest, UnnamedVariablesGetNamesOnceOneIsNamed) {
  LmiProgram p;
  p.add_variables(2);
  EXPECT_TRUE(p.var_names.empty());
  p.add_variable("delta2", 1.0);
  EXPECT_EQ(p.var_names, (std::vector<std::string>{"x0", "x1", "delta2"}));
  EXPECT_EQ(p.var_name(1), "x1");
  EXPECT_EQ(p.cost, (std::vector<double>{0.0, 0.0, 1.0}));
}

// Compressing changes the representation, never the matrices.
RC_GTEST_PROP(LmiProgramProperty, CompressKeepsEveryBlockValue, ()) {
  LmiProgram p = *gen::well_posed_lmi_program();
  // Add duplicate and cancelling contributions.
  const int b = *rc::gen::inRange(0, static_cast<int>(p.blocks.size()));
  const int var = *rc::gen::inRange(-1, p.num_vars);
  p.add_entry(b, var, 0, 0, 0.75);
  p.add_entry(b, var, 0, 0, -0.25);
  std::vector<double> x;
  for (int k = 0; k < p.num_vars; ++k) x.push_back(*rc::gen::inRange(-8, 9) / 8.0);
  const LmiProgram q = p.compressed();
  RC_ASSERT(q.nonzeros() <= p.nonzeros());
  for (int k = 0; k < static_cast<int>(p.blocks.size()); ++k)
    RC_ASSERT((p.block_value(k, x) - q.block_value(k, x)).cwiseAbs().maxCoeff() <= 1e-12);
  RC_ASSERT(q.compressed() == q);
}

}  // namespace
}  // namespace lpvid
