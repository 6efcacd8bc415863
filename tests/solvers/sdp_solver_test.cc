#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>

#include "solvers/csdp_backend.h"
#include "solvers/sdpa_backend.h"
#include "support/gen_lmi.h"

namespace lpvid {
namespace {

// OpenBLAS reads this when it starts; ctest sets it too.
const int kSingleThreadedBlas = [] { return setenv("OPENBLAS_NUM_THREADS", "1", 0); }();

/// min t s.t. [[t, 1], [1, 1]] ⪰ 0: t = 1.
LmiProgram two_by_two() {
  LmiProgram p;
  const int t = p.add_variable("t", 1.0);
  const int b = p.add_block("B", 2);
  p.add_entry(b, t, 0, 0, 1.0);
  p.add_entry(b, -1, 0, 1, 1.0);
  p.add_entry(b, -1, 1, 1, 1.0);
  return p;
}

/// min t s.t. t I − M ⪰ 0: t = λ_max(M).
LmiProgram lambda_max_program(const Eigen::MatrixXd& M) {
  LmiProgram p;
  const int t = p.add_variable("t", 1.0);
  const int n = static_cast<int>(M.rows());
  const int b = p.add_block("tI-M", n);
  for (int i = 0; i < n; ++i) {
    p.add_entry(b, t, i, i, 1.0);
    for (int j = i; j < n; ++j) p.add_entry(b, -1, i, j, -M(i, j));
  }
  return p;
}

Eigen::MatrixXd random_symmetric(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i; j < n; ++j) M(i, j) = M(j, i) = normal(rng);
  return M;
}

/// diag(x, −x − 1) ⪰ 0 has no solution.
LmiProgram infeasible_program(bool diagonal, double cost) {
  LmiProgram p;
  const int x = p.add_variable("x", cost);
  const int b = p.add_block("D", 2, diagonal);
  p.add_entry(b, x, 0, 0, 1.0);
  p.add_entry(b, x, 1, 1, -1.0);
  p.add_entry(b, -1, 1, 1, -1.0);
  return p;
}

/// min x s.t. [[−x, 0], [0, 1]] ⪰ 0: x ≤ 0, unbounded below.
LmiProgram unbounded_program() {
  LmiProgram p;
  const int x = p.add_variable("x", 1.0);
  const int b = p.add_block("U", 2);
  p.add_entry(b, x, 0, 0, -1.0);
  p.add_entry(b, -1, 1, 1, 1.0);
  return p;
}

double min_eigenvalue(const Eigen::MatrixXd& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m, Eigen::EigenvaluesOnly).eigenvalues()(0);
}

/// Smallest eigenvalue of F(x) over all blocks, relative to the block's scale.
double worst_relative_eigenvalue(const LmiProgram& p, const std::vector<double>& x) {
  double worst = 1e300;
  for (int b = 0; b < static_cast<int>(p.blocks.size()); ++b) {
    const Eigen::MatrixXd v = p.block_value(b, x);
    worst = std::min(worst, min_eigenvalue(v) / std::max(1.0, v.cwiseAbs().maxCoeff()));
  }
  return worst;
}

class SolverTest : public testing::TestWithParam<std::string> {
 protected:
  SolveResult solve(const LmiProgram& p, SolverOptions o = {}) { return make_solver(GetParam())->solve(p, o); }
};

TEST_P(SolverTest, TwoByTwoHasOptimumOne) {
  const SolveResult r = solve(two_by_two());
  EXPECT_TRUE(has_solution(r.status)) << to_string(r.status) << ": " << r.message;
  ASSERT_EQ(r.x.size(), 1u);
  EXPECT_NEAR(r.x[0], 1.0, 1e-6);
  EXPECT_NEAR(r.objective, 1.0, 1e-6);
  EXPECT_NEAR(r.dual_objective, 1.0, 1e-6);
  EXPECT_EQ(r.backend, GetParam());
  EXPECT_GE(r.seconds, 0.0);
}

TEST_P(SolverTest, LambdaMaxMatchesEigenUpToSize30) {
  for (int n : {1, 2, 3, 5, 8, 13, 21, 30}) {
    const Eigen::MatrixXd M = random_symmetric(n, 1000u + static_cast<unsigned>(n));
    const double lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(M).eigenvalues()(n - 1);
    const SolveResult r = solve(lambda_max_program(M));
    EXPECT_EQ(r.status, SolveStatus::kOptimal) << "n = " << n << ": " << r.message;
    EXPECT_NEAR(r.x[0], lambda, 1e-6 * (1.0 + std::fabs(lambda))) << "n = " << n;
  }
}

TEST_P(SolverTest, InfeasibleLmiIsPrimalInfeasible) {
  for (bool diagonal : {true, false})
    for (double cost : {0.0, 1.0}) {
      const SolveResult r = solve(infeasible_program(diagonal, cost));
      EXPECT_EQ(r.status, SolveStatus::kPrimalInfeasible)
          << "diagonal " << diagonal << ", cost " << cost << ": " << to_string(r.status) << ", " << r.message;
    }
}

TEST_P(SolverTest, PrimalInfeasibleComesWithACertificate) {
  SolverOptions o;
  o.want_dual = true;
  const LmiProgram p = infeasible_program(false, 1.0);
  const SolveResult r = solve(p, o);
  ASSERT_EQ(r.status, SolveStatus::kPrimalInfeasible) << r.message;
  ASSERT_EQ(r.dual_blocks.size(), 1u);
  const Eigen::MatrixXd& Y = r.dual_blocks[0];
  // Y ⪰ 0, ⟨F_1, Y⟩ ≈ 0 and ⟨F0, Y⟩ < 0 (relative to |Y|).
  const double scale = Y.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_GE(min_eigenvalue(Y) / scale, -1e-6);
  EXPECT_NEAR((Y(0, 0) - Y(1, 1)) / scale, 0.0, 1e-6);
  EXPECT_LT(-Y(1, 1) / scale, -0.1);
}

TEST_P(SolverTest, UnboundedObjectiveIsDualInfeasible) {
  const SolveResult r = solve(unbounded_program());
  EXPECT_EQ(r.status, SolveStatus::kDualInfeasible) << to_string(r.status) << ": " << r.message;
}

TEST_P(SolverTest, ScalarInequalitiesSolveAnLp) {
  // min x + y s.t. x ≥ 1, y ≥ 2, x + y ≥ 4, x − y ≥ −1 (optimum 4, x in [1.5, 2]).
  LmiProgram p;
  const int x = p.add_variable("x", 1.0), y = p.add_variable("y", 1.0);
  p.add_scalar_inequality({{x, 1.0}}, -1.0);
  p.add_scalar_inequality({{y, 1.0}}, -2.0);
  p.add_scalar_inequality({{x, 1.0}, {y, 1.0}}, -4.0);
  p.add_scalar_inequality({{x, 1.0}, {y, -1.0}}, 1.0);
  const SolveResult r = solve(p);
  EXPECT_TRUE(has_solution(r.status)) << r.message;
  EXPECT_NEAR(r.objective, 4.0, 1e-6);
  EXPECT_GE(worst_relative_eigenvalue(p, r.x), -1e-7);
}

TEST_P(SolverTest, DualBlocksSatisfyTheDualConstraints) {
  // min t s.t. t I − M ⪰ 0 and t ≥ −10: Y ⪰ 0 with ⟨F_t, Y⟩ = c_t = 1.
  LmiProgram p = lambda_max_program(random_symmetric(6, 7u));
  p.add_scalar_inequality({{0, 1.0}}, 10.0);
  SolverOptions o;
  o.want_dual = true;
  const SolveResult r = solve(p, o);
  ASSERT_EQ(r.status, SolveStatus::kOptimal) << r.message;
  ASSERT_EQ(r.dual_blocks.size(), 2u);
  EXPECT_EQ(r.dual_blocks[0].rows(), 6);
  EXPECT_EQ(r.dual_blocks[0].cols(), 6);
  EXPECT_EQ(r.dual_blocks[1].rows(), 1);
  EXPECT_EQ(r.dual_blocks[1].cols(), 1);
  EXPECT_GE(min_eigenvalue(r.dual_blocks[0]), -1e-7);
  EXPECT_GE(r.dual_blocks[1](0, 0), -1e-7);
  EXPECT_NEAR(r.dual_blocks[0].trace() + r.dual_blocks[1](0, 0), 1.0, 1e-6);
  // −⟨F0, Y⟩ is the dual objective.
  double dual = 0.0;
  for (std::size_t b = 0; b < p.blocks.size(); ++b)
    for (const SymEntry& e : p.blocks[b].F0.entries)
      dual -= (e.i == e.j ? 1.0 : 2.0) * e.value *
              (p.blocks[b].diagonal ? r.dual_blocks[b](e.i, 0) : r.dual_blocks[b](e.i, e.j));
  EXPECT_NEAR(dual, r.dual_objective, 1e-6 * (1.0 + std::fabs(dual)));
}

TEST_P(SolverTest, SolvingTwiceGivesTheSameAnswer) {
  const LmiProgram p = lambda_max_program(random_symmetric(10, 3u));
  const SolveResult a = solve(p);
  const SolveResult b = solve(two_by_two());
  const SolveResult c = solve(p);
  ASSERT_EQ(a.status, c.status);
  EXPECT_EQ(a.x, c.x);  // same input, same arithmetic
  EXPECT_NEAR(b.x[0], 1.0, 1e-6);
}

TEST_P(SolverTest, IsSilentUnlessVerbose) {
  testing::internal::CaptureStdout();
  solve(two_by_two());
  solve(infeasible_program(true, 1.0));
  solve(unbounded_program());
  solve(lambda_max_program(random_symmetric(5, 11u)));
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
}

TEST_P(SolverTest, StrayParamFilesInTheWorkingDirectoryChangeNothing) {
  const LmiProgram p = lambda_max_program(random_symmetric(8, 5u));
  const SolveResult before = solve(p);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lpvid_param_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path old = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  // A partial, hostile param.csdp (easy_sdp would read it and leave the rest
  // of its parameters uninitialised) and a param.sdpa.
  std::ofstream(dir / "param.csdp") << "axtol=0.5\natytol=0.5\nobjtol=0.5\npinftol=1\ndinftol=1\nmaxiter=1\n";
  std::ofstream(dir / "param.sdpa") << "1 unsigned int maxIteration;\n0.5 double 0.0 < epsilonStar;\n";
  const SolveResult after = solve(p);
  std::filesystem::current_path(old);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(after.status, before.status);
  EXPECT_EQ(after.x, before.x);
}

TEST_P(SolverTest, IterationLimitIsReported) {
  SolverOptions o;
  o.max_iterations = 2;
  const SolveResult r = solve(lambda_max_program(random_symmetric(12, 9u)), o);
  EXPECT_EQ(r.status, SolveStatus::kIterationLimit) << to_string(r.status) << ": " << r.message;
}

TEST_P(SolverTest, ConstantBlocksAndUnusedVariablesArePresolved) {
  // A constant PSD block and a variable with zero cost that appears nowhere.
  LmiProgram p = two_by_two();
  p.add_variable("unused", 0.0);
  const int c = p.add_block("const", 2);
  p.add_entry(c, -1, 0, 0, 1.0);
  p.add_entry(c, -1, 0, 1, 1.0);
  p.add_entry(c, -1, 1, 1, 1.0);  // [[1,1],[1,1]] ⪰ 0, singular
  SolverOptions o;
  o.want_dual = true;
  SolveResult r = solve(p, o);
  EXPECT_TRUE(has_solution(r.status)) << r.message;
  ASSERT_EQ(r.x.size(), 2u);
  EXPECT_NEAR(r.x[0], 1.0, 1e-6);
  EXPECT_EQ(r.x[1], 0.0);
  ASSERT_EQ(r.dual_blocks.size(), 2u);
  EXPECT_TRUE(r.dual_blocks[1].isZero());
  EXPECT_NE(r.message.find("does not depend on x"), std::string::npos) << r.message;

  // The same with a cost on the unused variable: unbounded below.
  p.set_cost(1, -1.0);
  r = solve(p);
  EXPECT_EQ(r.status, SolveStatus::kDualInfeasible) << r.message;

  // A constant block that is not PSD: infeasible whatever x is.
  p.add_entry(c, -1, 1, 1, -2.0);
  r = solve(p);
  EXPECT_EQ(r.status, SolveStatus::kPrimalInfeasible) << r.message;
  EXPECT_NE(r.message.find("'const'"), std::string::npos) << r.message;

  // Nothing depends on x at all.
  LmiProgram q;
  q.add_variable("x", 0.0);
  q.add_scalar_inequality({}, 1.0);
  r = solve(q);
  EXPECT_EQ(r.status, SolveStatus::kOptimal) << r.message;
}

TEST_P(SolverTest, ZeroCostOrZeroConstantTermIsFine) {
  // Pure feasibility: find x with 1 <= x <= 2 (c = 0).
  LmiProgram f;
  const int x = f.add_variable("x", 0.0);
  const int b = f.add_block("range", 2, true);
  f.add_entry(b, x, 0, 0, 1.0);
  f.add_entry(b, -1, 0, 0, -1.0);
  f.add_entry(b, x, 1, 1, -1.0);
  f.add_entry(b, -1, 1, 1, 2.0);
  SolveResult r = solve(f);
  EXPECT_TRUE(has_solution(r.status)) << r.message;
  EXPECT_GE(r.x[0], 1.0 - 1e-6);
  EXPECT_LE(r.x[0], 2.0 + 1e-6);

  // F0 = 0: min x + y s.t. [[x, y], [y, x]] ⪰ 0, i.e. x >= |y|: optimum 0.
  LmiProgram z;
  const int u = z.add_variable("x", 1.0), v = z.add_variable("y", 1.0);
  const int c = z.add_block("no_constant", 2);
  z.add_entry(c, u, 0, 0, 1.0);
  z.add_entry(c, u, 1, 1, 1.0);
  z.add_entry(c, v, 0, 1, 1.0);
  r = solve(z);
  EXPECT_TRUE(has_solution(r.status)) << r.message;
  EXPECT_NEAR(r.objective, 0.0, 1e-6);

  // Both zero.
  z.cost = {0.0, 0.0};
  r = solve(z);
  EXPECT_TRUE(has_solution(r.status)) << r.message;
  EXPECT_GE(worst_relative_eigenvalue(z, r.x), -1e-7);
}

TEST_P(SolverTest, InvalidInputThrows) {
  LmiProgram p = two_by_two();
  p.blocks[0].F0.entries.push_back({0, 0, std::numeric_limits<double>::quiet_NaN()});
  EXPECT_THROW(solve(p), std::invalid_argument);
  SolverOptions o;
  o.gap_tol = -1.0;
  EXPECT_THROW(solve(two_by_two(), o), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Backends, SolverTest, testing::ValuesIn(available_solvers()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(SolverFactoryTest, KnowsCsdpAndSdpaAndNamesThemOnError) {
  EXPECT_EQ(available_solvers(), (std::vector<std::string>{"csdp", "sdpa"}));
  EXPECT_EQ(make_solver("csdp")->name(), "csdp");
  EXPECT_EQ(make_solver("sdpa")->name(), "sdpa");
  try {
    make_solver("mosek");
    FAIL() << "no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("csdp, sdpa"), std::string::npos) << e.what();
  }
}

TEST(SolveStatusTest, HasStableWords) {
  EXPECT_STREQ(to_string(SolveStatus::kOptimal), "optimal");
  EXPECT_STREQ(to_string(SolveStatus::kOptimalInaccurate), "optimal_inaccurate");
  EXPECT_STREQ(to_string(SolveStatus::kPrimalInfeasible), "primal_infeasible");
  EXPECT_STREQ(to_string(SolveStatus::kDualInfeasible), "dual_infeasible");
  EXPECT_STREQ(to_string(SolveStatus::kIterationLimit), "iteration_limit");
  EXPECT_STREQ(to_string(SolveStatus::kBackendError), "backend_error");
  EXPECT_TRUE(has_solution(SolveStatus::kOptimalInaccurate));
  EXPECT_FALSE(has_solution(SolveStatus::kIterationLimit));
}

TEST(StatusMappingTest, CsdpReturnCodes) {
  EXPECT_EQ(csdp_status(0), SolveStatus::kOptimal);
  EXPECT_EQ(csdp_status(1), SolveStatus::kDualInfeasible);    // CSDP's primal = our dual
  EXPECT_EQ(csdp_status(2), SolveStatus::kPrimalInfeasible);  // CSDP's dual = our LMI
  EXPECT_EQ(csdp_status(3), SolveStatus::kOptimalInaccurate);  // partial success is not success
  EXPECT_EQ(csdp_status(4), SolveStatus::kIterationLimit);
  for (int code : {5, 6, 7, 8, 9, 10, 42, -1}) EXPECT_EQ(csdp_status(code), SolveStatus::kBackendError) << code;
  std::string words;
  csdp_status(5, &words);
  EXPECT_NE(words.find("stuck at edge of primal feasibility"), std::string::npos) << words;
}

TEST(StatusMappingTest, SdpaPhaseWords) {
  const double tol = 1e-7;
  EXPECT_EQ(sdpa_status("pdOPT", 1e-9, false, tol), SolveStatus::kOptimal);
  EXPECT_EQ(sdpa_status("pdOPT     ", 1e-9, false, tol), SolveStatus::kOptimal);  // as SDPA pads it
  EXPECT_EQ(sdpa_status("pdFEAS", 5e-8, false, tol), SolveStatus::kOptimal);
  EXPECT_EQ(sdpa_status("pdFEAS", 5e-7, false, tol), SolveStatus::kOptimalInaccurate);
  EXPECT_EQ(sdpa_status("pdFEAS", 1e-2, true, tol), SolveStatus::kIterationLimit);
  EXPECT_EQ(sdpa_status("pdFEAS", 1e-2, false, tol), SolveStatus::kBackendError);
  for (const char* w : {"pINF_dFEAS", "dUNBD", "pdINF"})
    EXPECT_EQ(sdpa_status(w, 1.0, false, tol), SolveStatus::kPrimalInfeasible) << w;
  for (const char* w : {"pFEAS_dINF", "pUNBD"}) EXPECT_EQ(sdpa_status(w, 1.0, false, tol), SolveStatus::kDualInfeasible) << w;
  for (const char* w : {"noINFO", "pFEAS", "dFEAS"}) {
    EXPECT_EQ(sdpa_status(w, 1.0, true, tol), SolveStatus::kIterationLimit) << w;
    EXPECT_EQ(sdpa_status(w, 1.0, false, tol), SolveStatus::kBackendError) << w;
  }
  std::string words;
  EXPECT_EQ(sdpa_status("bogus", 0.0, false, tol, &words), SolveStatus::kBackendError);
  EXPECT_NE(words.find("'bogus'"), std::string::npos) << words;
}

// (e) Both backends agree on random well-posed programs, and both answers
// are feasible.
RC_GTEST_PROP(SolverProperty, CsdpAndSdpaAgreeOnWellPosedPrograms, ()) {
  const LmiProgram p = *gen::well_posed_lmi_program();
  const SolveResult a = make_solver("csdp")->solve(p, {});
  const SolveResult b = make_solver("sdpa")->solve(p, {});
  RC_LOG() << "csdp: " << to_string(a.status) << " " << a.objective << " (" << a.message << ")\n"
           << "sdpa: " << to_string(b.status) << " " << b.objective << " (" << b.message << ")\n";
  RC_ASSERT(has_solution(a.status));
  RC_ASSERT(has_solution(b.status));
  RC_ASSERT(std::fabs(a.objective - b.objective) <= 1e-6 * (1.0 + std::fabs(a.objective)));
  RC_ASSERT(worst_relative_eigenvalue(p, a.x) >= -1e-6);
  RC_ASSERT(worst_relative_eigenvalue(p, b.x) >= -1e-6);
}

}  // namespace
}  // namespace lpvid
