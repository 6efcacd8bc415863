// Theorem 2.1 solved by an outside solver (certify/outside_solution.h): the
// exported program, the `csdp` program's answer read back, and what a wrong
// or foreign answer can do (at worst fail to verify, never a false claim).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include <nlohmann/json.hpp>

#include "certify/certify.h"
#include "core/input_error.h"
#include "data/csv_reader.h"
#include "data/data_reference.h"
#include "data/experiment_builder.h"
#include "certify/certify.h"
#include "certify/outside_solution.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "solvers/sdpa_file.h"
#include "solvers/sdpa_sidecar.h"
#include "support/fixtures.h"
#include "support/scratch_dir.h"
#include "solvers/solver_factory.h"

namespace lpvid {
namespace {

struct OutsideSolution : ::testing::Test {
  LpvModel<Rational> model = read_model_file<Rational>(gen::kExample1Fixtures + "initial_model.json");
  Experiment<Rational> exp = make_experiment<Rational>(read_table(gen::kExample1Fixtures + "noise_free_n40.csv"), model.columns);
  gen::ScratchDir dir{"outside_solution"};
  CertifyOptions options() const {
    CertifyOptions o;
    o.objective.kind = BoundObjective::Kind::kWeighted;
    o.objective.lambda = 0.5;
    o.max_taps = 6;
    o.lower_end = false;
    o.records = {read_data_table(gen::kExample1Fixtures + "noise_free_n40.csv").reference};
    return o;
  }
  /// The program at `p` and a CSDP solution file at `sol` whose y is all zeros.
  void write_zero_solution(const std::string& p, const std::string& sol) const {
    const Theorem21Program built = theorem21_program(model, exp, options());
    write_sdpa_file(built.delta.program, p);
    std::ofstream out(sol);
    for (int k = 0; k < built.delta.program.num_vars; ++k) out << (k ? " " : "") << "0";
    out << "\n";
  }
  /// Runs the csdp program on `program`; returns its exit status (-1: not run).
  int csdp(const std::string& program, const std::string& solution) const {
    const int s = std::system(("csdp " + program + " " + solution + " > " + dir.file("csdp.txt") + " 2>&1").c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  }
};

TEST_F(OutsideSolution, ExportedProgramCarriesItsMeaningAndReadsBackUnchanged) {
  const std::string p = dir.file("p.dat-s");
  write_sdpa_with_sidecar(theorem21_program(model, exp, options()).delta.program, p);
  const Theorem21Program built = theorem21_program(model, exp, options());
  const LmiProgram back = read_sdpa_file(p);
  EXPECT_EQ(back, built.delta.program.compressed());  // about lines and names included
  const auto side = nlohmann::json::parse(std::ifstream(sdpa_sidecar_path(p)));
  EXPECT_EQ(side["about"]["kind"], kDeltaFormKind);
  EXPECT_EQ(side["about"]["taps"], "6");
  // K·ny·nz taps, then δ² and d_max² (weighted objective).
  const long taps = 6 * model.ny * model.nz();
  ASSERT_EQ(side["variables"].size(), static_cast<size_t>(taps + 2));
  EXPECT_EQ(side["variables"][0]["name"], "h0[0,0]");
  EXPECT_EQ(side["variables"][taps]["name"], "delta2");
  EXPECT_EQ(side["variables"][taps + 1]["name"], "dmax2");
  EXPECT_EQ(std::stod(side["about"]["sigma_z"].get<std::string>()), built.delta.variables.sigma_z);
}

TEST_F(OutsideSolution, CsdpProgramAnswerCertifiesLikeTheLinkedSolver) {
  if (std::system("command -v csdp > /dev/null 2>&1") != 0) GTEST_SKIP() << "the csdp program is not installed";
  const std::string p = dir.file("p.dat-s"), sol = dir.file("p.sol");
  write_sdpa_with_sidecar(theorem21_program(model, exp, options()).delta.program, p);
  ASSERT_EQ(csdp(p, sol), 0);
  const CertifiedBounds outside = certify_outside_solution(model, exp, options(), read_outside_solution(p, sol, SolutionFormat::kCsdp, 0));
  ASSERT_TRUE(outside.verified()) << outside.reason;
  // The same program solved by the linked CSDP library through the usual path.
  CertifyOptions own = options();
  own.structured = false;  // the K-tap SDP, as exported
  auto solver = make_solver("csdp");
  const CertifiedBounds linked = certify_fixed_model(model, exp, own, *solver);
  ASSERT_TRUE(linked.verified()) << linked.reason;
  const double a = nearest_double(outside.upper), b = nearest_double(linked.upper);
  EXPECT_NEAR(a, b, 1e-5 * b) << "outside " << a << ", linked " << b;
}

TEST_F(OutsideSolution, ZeroTapsGiveTheResidualAsNoiseExactly) {
  // y = 0 (all taps zero): w = 0, d = r, so δ² ≈ 0 and d_max² is ‖r‖²/(n·ny)
  // rounded up — whatever the solver, the certificate says only what holds.
  const std::string p = dir.file("p.dat-s"), sol = dir.file("zero.sol");
  write_zero_solution(p, sol);
  const CertifiedBounds b = certify_outside_solution(model, exp, options(), read_outside_solution(p, sol, SolutionFormat::kCsdp, 0));
  ASSERT_TRUE(b.verified()) << b.reason;
  EXPECT_LT(nearest_double(b.delta2), 1e-100);  // ‖T_Δ‖ = 0; certify.cc keeps δ² a tiny positive number
  const Mat<Rational> r = exp.y - simulate(model, exp).output;
  Rational r2(0);
  for (Eigen::Index i = 0; i < r.rows(); ++i)
    for (Eigen::Index j = 0; j < r.cols(); ++j) r2 += r(i, j) * r(i, j);
  const Rational exact = r2 / Rational(static_cast<long>(exp.n() * model.ny));
  EXPECT_GE(b.dmax2, exact);
  EXPECT_LE(nearest_double(b.dmax2), nearest_double(exact) * (1 + 1e-13));
}

TEST_F(OutsideSolution, InfeasibleStatusIsNotCertified) {
  const std::string p = dir.file("p.dat-s"), sol = dir.file("zero.sol");
  write_zero_solution(p, sol);
  const CertifiedBounds b = certify_outside_solution(model, exp, options(), read_outside_solution(p, sol, SolutionFormat::kCsdp, 1));
  EXPECT_FALSE(b.verified());
  EXPECT_NE(b.reason.find("infeasible"), std::string::npos) << b.reason;
  EXPECT_FALSE(b.certificate.has_value());
}

TEST_F(OutsideSolution, ProgramOfOtherDataOrOptionsIsRefused) {
  const std::string p = dir.file("p.dat-s"), sol = dir.file("p.sol");
  write_sdpa_with_sidecar(theorem21_program(model, exp, options()).delta.program, p);
  std::ofstream(sol) << "0\n";
  CertifyOptions more = options();
  more.max_taps = 7;
  try {
    (void)certify_outside_solution(model, exp, more, read_outside_solution(p, sol, SolutionFormat::kCsdp, 0));
    FAIL() << "a program with 6 taps was accepted for --max-taps 7";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("taps"), std::string::npos) << e.what();
  }
  Experiment<Rational> other = exp;
  other.y(5, 0) += Rational(1, 10);
  EXPECT_THROW((void)certify_outside_solution(model, other, options(), read_outside_solution(p, sol, SolutionFormat::kCsdp, 0)), InputError);
  // A program without lpvid's meaning lines.
  LmiProgram bare = theorem21_program(model, exp, options()).delta.program;
  bare.about.clear();
  write_sdpa_file(bare, p);
  EXPECT_THROW((void)certify_outside_solution(model, exp, options(), read_outside_solution(p, sol, SolutionFormat::kCsdp, 0)), InputError);
}

}  // namespace
}  // namespace lpvid
