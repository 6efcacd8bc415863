#include "solvers/sdpa_file.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_lmi.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

std::string written(const LmiProgram& p) {
  std::ostringstream out;
  write_sdpa(p, out);
  return out.str();
}

LmiProgram read_text(const std::string& text, const std::string& name = "test.dat-s") {
  std::istringstream in(text);
  return read_sdpa(in, name);
}

/// The InputError message of reading `text`, or "" if it reads.
std::string read_error(const std::string& text) {
  try {
    read_text(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// A fresh directory under the system temp dir, removed at the end.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(fs::temp_directory_path() / ("lpvid_" + tag + "_" + std::to_string(getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

bool have_command(const std::string& name) {
  return std::system(("command -v " + name + " > /dev/null 2>&1").c_str()) == 0;
}

/// Runs `command` in `dir`; returns its exit status.
int run_in(const fs::path& dir, const std::string& command) {
  const int status = std::system(("cd '" + dir.string() + "' && " + command + " > log.txt 2>&1").c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

LmiProgram lambda_max_program(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  LmiProgram p;
  const int t = p.add_variable("t", 1.0);
  const int b = p.add_block("tI-M", n);
  for (int i = 0; i < n; ++i) {
    p.add_entry(b, t, i, i, 1.0);
    for (int j = i; j < n; ++j) p.add_entry(b, -1, i, j, -normal(rng));
  }
  return p;
}

// --- writing and reading -------------------------------------------------------

TEST(SdpaFileTest, WritesSdpaSignConventionOneBasedUpperTriangle) {
  LmiProgram p;
  const int t = p.add_variable("t", 1.0);
  const int b = p.add_block("B", 2);
  p.add_entry(b, t, 0, 0, 1.0);
  p.add_entry(b, -1, 1, 0, 1.0);  // stored as (0, 1)
  p.add_entry(b, -1, 1, 1, 1.0);
  p.add_scalar_inequality({{t, 2.0}}, 0.5);
  const std::string text = written(p);
  EXPECT_NE(text.find("\n1 = mDIM\n2 = nBLOCK\n2 -1\n1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n0 1 1 2 -1\n0 1 2 2 -1\n1 1 1 1 1\n0 2 1 1 -0.5\n1 2 1 1 2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("*lpvid-block 1 B\n"), std::string::npos) << text;
  EXPECT_NE(text.find("*lpvid-var 1 t\n"), std::string::npos) << text;
  EXPECT_EQ(text[0], '"');
}

TEST(SdpaFileTest, ReadsTheUsualVariations) {
  const LmiProgram p = read_text(
      "\"a comment\n"
      "* another\n"
      "\n"
      "2 = mDIM\n"
      "2 =nBLOCK\n"
      "{2,\n"
      " -1}\n"
      "(1.5, -2)\r\n"
      "0 1 2 1 3\n"       // i > j: the (1, 2) entry
      "1 1 1 1 1\n"
      "1 1 1 1 0.5\n"     // duplicate: summed
      "\n"
      "2 2 1 1 4e-1\n");
  EXPECT_EQ(p.num_vars, 2);
  EXPECT_EQ(p.cost, (std::vector<double>{1.5, -2.0}));
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].size, 2);
  EXPECT_FALSE(p.blocks[0].diagonal);
  EXPECT_TRUE(p.blocks[1].diagonal);
  EXPECT_EQ(p.blocks[0].F0.entries, (std::vector<SymEntry>{{0, 1, -3.0}}));  // F0 = −F_0(file)
  ASSERT_EQ(p.blocks[0].Fi.size(), 1u);
  EXPECT_EQ(p.blocks[0].Fi[0].second.entries, (std::vector<SymEntry>{{0, 0, 1.5}}));
  EXPECT_EQ(p.blocks[1].Fi[0].first, 1);
  EXPECT_EQ(p.blocks[1].Fi[0].second.entries, (std::vector<SymEntry>{{0, 0, 0.4}}));
  EXPECT_TRUE(p.var_names.empty());
}

TEST(SdpaFileTest, ErrorsNameTheFileAndLine) {
  const std::string header = "\"c\n1\n1\n2\n1\n";  // entries start on line 6
  EXPECT_NE(read_error(header + "0 1 1 1\n").find("test.dat-s:6: "), std::string::npos);
  EXPECT_NE(read_error(header + "1 1 1 1 1\n2 1 1 1 1\n").find("test.dat-s:7: matrix number '2'"), std::string::npos);
  EXPECT_NE(read_error(header + "1 2 1 1 1\n").find(":6: block number '2'"), std::string::npos);
  EXPECT_NE(read_error(header + "1 1 3 1 1\n").find(":6: entry (3, 1) is outside block 1"), std::string::npos);
  EXPECT_NE(read_error(header + "1 1 1 1 nan\n").find(":6: value 'nan'"), std::string::npos);
  EXPECT_NE(read_error("\"c\n1\n1\n-2\n1\n1 1 1 2 1\n").find(":6: off-diagonal entry (1, 2) in diagonal block 1"),
            std::string::npos);
  EXPECT_NE(read_error("\"c\n1\n1\n0\n1\n").find(":4: block 1 has size 0"), std::string::npos);
  EXPECT_NE(read_error("\"c\n2\n1\n2\n").find("end of file while reading cost coefficient 1"), std::string::npos);
  EXPECT_NE(read_error("\"c\nabc\n").find(":2: expected the number of variables"), std::string::npos);
  EXPECT_NE(read_error("\"c\n1\n1\n2\n1 7\n").find(":5: more numbers than expected"), std::string::npos);
  EXPECT_EQ(read_error(header + "1 1 1 1 1\n"), "");
  EXPECT_THROW(read_sdpa_file("/nonexistent/dir/x.dat-s"), InputError);
}

TEST(SdpaFileTest, NamesWithLineBreaksCannotBeWritten) {
  LmiProgram p;
  p.add_variable("a\nb", 1.0);
  std::ostringstream out;
  EXPECT_THROW(write_sdpa(p, out), std::invalid_argument);
}

// (f) write → read gives the same program, exactly (17 significant digits).
RC_GTEST_PROP(SdpaFileProperty, WriteThenReadIsTheCompressedProgram, ()) {
  LmiProgram p = *gen::well_posed_lmi_program();
  // Values that are not short decimals, names, and an unused variable.
  const int b = *rc::gen::inRange(0, static_cast<int>(p.blocks.size()));
  p.add_entry(b, -1, 0, 0, 1.0 / 3.0);
  p.add_entry(b, p.num_vars - 1, 0, 0, -std::ldexp(1.0, -60) * 7);
  p.add_variable("unused name", 0.1);
  p.blocks[0].name = "first block";
  const LmiProgram q = read_text(written(p));
  RC_ASSERT(q == p.compressed());
  RC_ASSERT(written(q) == written(p));
}

// --- the fixtures know their answers --------------------------------------------

TEST(SdpaFileTest, FixturesHaveTheirKnownAnswersWithBothBackends) {
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(LPVID_SOURCE_DIR) / "fixtures" / "sdp")) {
    if (entry.path().extension() != ".dat-s") continue;
    const LmiProgram p = read_sdpa_file(entry.path().string());
    std::ifstream in(entry.path());
    std::string line, expected_status;
    double expected_objective = 0.0;
    while (std::getline(in, line))
      if (line.rfind("*lpvid-expect ", 0) == 0) {
        std::istringstream words(line.substr(14));
        words >> expected_status >> expected_objective;
      }
    ASSERT_FALSE(expected_status.empty()) << entry.path() << " has no *lpvid-expect line";
    for (const std::string& backend : available_solvers()) {
      const SolveResult r = make_solver(backend)->solve(p, {});
      const bool optimal_expected = expected_status == "optimal";
      if (optimal_expected) {
        EXPECT_TRUE(has_solution(r.status)) << entry.path() << " " << backend << ": " << r.message;
        EXPECT_NEAR(r.objective, expected_objective, 1e-6 * (1.0 + std::fabs(expected_objective)))
            << entry.path() << " " << backend;
      } else {
        EXPECT_STREQ(to_string(r.status), expected_status.c_str()) << entry.path() << " " << backend << ": "
                                                                   << r.message;
      }
    }
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST(SdpaFileTest, FixtureNamesAreRead) {
  const LmiProgram p =
      read_sdpa_file((fs::path(LPVID_SOURCE_DIR) / "fixtures/sdp/lmi_and_scalar_inequalities.dat-s").string());
  EXPECT_EQ(p.var_names, (std::vector<std::string>{"x", "y"}));
  ASSERT_EQ(p.blocks.size(), 2u);
  EXPECT_EQ(p.blocks[0].name, "xy_lmi");
  EXPECT_EQ(p.blocks[1].name, "lower_bounds");
  EXPECT_TRUE(p.blocks[1].diagonal);
}

// --- outside solvers --------------------------------------------------------------

/// Our CSDP parameters (csdp_backend.cc, first run) as a param.csdp file, so
/// that the command and the library take the same path.
void write_param_csdp(const fs::path& dir) {
  std::ofstream(dir / "param.csdp") << "axtol=1.0e-8\natytol=1.0e-8\nobjtol=1.0e-7\npinftol=1.0e8\ndinftol=1.0e8\n"
                                       "maxiter=100\nminstepfrac=0.90\nmaxstepfrac=0.97\nminstepp=1.0e-8\n"
                                       "minstepd=1.0e-8\nusexzgap=1\ntweakgap=0\naffine=0\nprintlevel=1\n"
                                       "perturbobj=0\nfastmode=0\n";
}

/// SDPA's parameter file with our tolerances and full-precision xVec.
void write_param_sdpa(const fs::path& dir) {
  std::ofstream(dir / "param.sdpa") << "100     unsigned int maxIteration;\n"
                                       "1.0E-7  double 0.0 < epsilonStar;\n"
                                       "1.0E2   double 0.0 < lambdaStar;\n"
                                       "2.0     double 1.0 < omegaStar;\n"
                                       "-1.0E8  double lowerBound;\n"
                                       "1.0E8   double upperBound;\n"
                                       "0.1     double 0.0 <= betaStar <  1.0;\n"
                                       "0.2     double 0.0 <= betaBar  <  1.0, betaStar <= betaBar;\n"
                                       "0.9     double 0.0 < gammaStar  <  1.0;\n"
                                       "1.0E-8  double 0.0 < epsilonDash;\n"
                                       "%+.17e  char*  xPrint   (default %+8.3e,   NOPRINT skips printout)\n"
                                       "%+.17e  char*  XPrint   (default %+8.3e,   NOPRINT skips printout)\n"
                                       "%+.17e  char*  YPrint   (default %+8.3e,   NOPRINT skips printout)\n"
                                       "%+10.16e char* infPrint (default %+10.16e, NOPRINT skips printout)\n";
}

std::vector<LmiProgram> outside_solver_programs() {
  std::vector<LmiProgram> programs{lambda_max_program(8, 21u)};
  programs.push_back(
      read_sdpa_file((fs::path(LPVID_SOURCE_DIR) / "fixtures/sdp/lmi_and_scalar_inequalities.dat-s").string()));
  return programs;
}

TEST(SdpaFileTest, CsdpCommandSolvesTheWrittenFileLikeTheLibrary) {
  if (!have_command("csdp")) GTEST_SKIP() << "the csdp command is not installed";
  TempDir dir("csdp_cli");
  write_param_csdp(dir.path());
  for (const LmiProgram& p : outside_solver_programs()) {
    write_sdpa_file(p, (dir.path() / "prob.dat-s").string());
    const int code = run_in(dir.path(), "csdp prob.dat-s prob.sol");
    const SolveResult outside = read_csdp_solution((dir.path() / "prob.sol").string(), p, code);
    const SolveResult inside = make_solver("csdp")->solve(p, {});
    ASSERT_EQ(outside.status, SolveStatus::kOptimal) << outside.message;
    ASSERT_EQ(inside.status, SolveStatus::kOptimal) << inside.message;
    ASSERT_EQ(outside.x.size(), inside.x.size());
    for (std::size_t k = 0; k < inside.x.size(); ++k)
      EXPECT_NEAR(outside.x[k], inside.x[k], 1e-6 * (1.0 + std::fabs(inside.x[k]))) << "x_" << k;
    EXPECT_NEAR(outside.dual_objective, outside.objective, 1e-6 * (1.0 + std::fabs(outside.objective)));
    EXPECT_EQ(outside.backend, "csdp (command)");
  }
}

TEST(SdpaFileTest, SdpaCommandSolvesTheWrittenFileLikeTheLibrary) {
  if (!have_command("sdpa")) GTEST_SKIP() << "the sdpa command is not installed";
  TempDir dir("sdpa_cli");
  write_param_sdpa(dir.path());
  for (const LmiProgram& p : outside_solver_programs()) {
    write_sdpa_file(p, (dir.path() / "prob.dat-s").string());
    ASSERT_EQ(run_in(dir.path(), "sdpa prob.dat-s prob.out"), 0);
    const SolveResult outside = read_sdpa_result((dir.path() / "prob.out").string(), p, {});
    const SolveResult inside = make_solver("sdpa")->solve(p, {});
    ASSERT_TRUE(has_solution(outside.status)) << outside.message;
    ASSERT_TRUE(has_solution(inside.status)) << inside.message;
    ASSERT_EQ(outside.x.size(), inside.x.size());
    for (std::size_t k = 0; k < inside.x.size(); ++k)
      EXPECT_NEAR(outside.x[k], inside.x[k], 1e-6 * (1.0 + std::fabs(inside.x[k]))) << "x_" << k;
    EXPECT_GT(outside.iterations, 0);
    EXPECT_EQ(outside.backend, "sdpa (command)");
  }
}

TEST(SdpaFileTest, OutsideSolutionsThatDoNotFitAreRejectedWithFileAndLine) {
  TempDir dir("bad_solution");
  const LmiProgram p = lambda_max_program(3, 1u);
  const std::string sol = (dir.path() / "x.sol").string();
  std::ofstream(sol) << "1.0 2.0\n";
  try {
    read_csdp_solution(sol, p, 0);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.sol:1: y has 2 entries"), std::string::npos) << e.what();
  }
  std::ofstream(sol) << "1.0\n2 1 4 4 1.0\n";
  try {
    read_csdp_solution(sol, p, 0);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("x.sol:2: entry (4, 4) does not fit block 1"), std::string::npos) << e.what();
  }
  const std::string out = (dir.path() / "x.out").string();
  std::ofstream(out) << "phase.value  = pdOPT\nxVec = \n{+1.0e+00,+2.0e+00}\n";
  EXPECT_THROW(read_sdpa_result(out, p, {}), InputError);
  std::ofstream(out) << "nothing here\n";
  EXPECT_THROW(read_sdpa_result(out, p, {}), InputError);
}

}  // namespace
}  // namespace lpvid
