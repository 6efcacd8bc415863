// Basis selection, the paper's Appendix algorithm (identify/basis_selection.h).
//
// The growth order is checked exactly (and as a property for any nρ and
// degree). The algorithm runs on the paper's Example 1 (noise-free, n = 30):
// the initial model lacks the output factor ρ2², so with --iterate at
// δ = 0.05, d_max = 0.01 the selected basis must contain ρ2², every
// "consistent" must carry a certificate the exact verifier accepts, every
// "cannot explain" (or box invalidation) a class certificate it accepts, and
// the verdicts must be monotone (a consistent basis has no superset among the
// steps that is not).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "data/csv_reader.h"
#include "data/data_reference.h"
#include "data/csv_writer.h"
#include "data/experiment_builder.h"
#include "examples/paper_example1.h"
#include "cli/certificate_names.h"
#include "core/file_io.h"
#include "identify/basis_selection.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

#include "support/scratch_dir.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> texts(const std::vector<Monomial>& b, const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const Monomial& m : b) out.push_back(m.text(names));
  return out;
}

/// Example 1 written as CSV and read back (the CLI's path), both scalars
/// (the double model converted from the exact one).
struct Example1Data : Problem {
  gen::ScratchDir dir{"select"};
  std::string csv;
  explicit Example1Data(int n) {
    Example1Options o;
    o.n = n;
    const Experiment<Rational> e = example1_experiment(o);
    csv = dir.file("data.csv");
    write_csv(csv, {{"u1", column_text(e.u, 0)},
                    {"u2", column_text(e.u, 1)},
                    {"y1", column_text(e.y, 0)},
                    {"y2", column_text(e.y, 1)},
                    {"rho1", column_text(e.rho, 0)},
                    {"rho2", column_text(e.rho, 1)}});
    model_q = example1_initial_model();
    model_d = convert_model<double>(model_q);
    const TextTable t = read_table(csv);
    exp_q = make_experiment<Rational>(t, model_q.columns);
    exp_d = make_experiment<double>(t, model_d.columns);
  }
  BasisSelectionOptions options(const std::string& delta, const std::string& dmax) const {
    BasisSelectionOptions o;
    o.delta = ExactBound::from_text(delta);
    o.dmax = ExactBound::from_text(dmax);
    o.certify.records = {read_data_table(csv).reference};
    return o;
  }
};

TEST(BasisGrowthOrder, PaperOrderForTwoParameters) {
  const std::vector<std::string> names = {"rho1", "rho2"};
  EXPECT_EQ(texts(basis_growth_order(2, 2), names),
            (std::vector<std::string>{"1", "rho1", "rho2", "rho1*rho2", "rho1^2", "rho2^2"}));
  EXPECT_EQ(texts(basis_growth_order(2, 1), names), (std::vector<std::string>{"1", "rho1", "rho2"}));
  EXPECT_EQ(texts(basis_growth_order(2, 0), names), (std::vector<std::string>{"1"}));
  EXPECT_EQ(texts(basis_growth_order(0, 3), {}), (std::vector<std::string>{"1"}));
}

TEST(BasisGrowthOrder, ThreeParametersDegreeThree) {
  const std::vector<std::string> names = {"a", "b", "c"};
  EXPECT_EQ(texts(basis_growth_order(3, 3), names),
            (std::vector<std::string>{"1", "a", "b", "c",                              // LTI, affine
                                      "a*b", "a*c", "b*c", "a*b*c",                    // multilinear
                                      "a^2", "b^2", "c^2",                             // quadratic
                                      "a^3", "b^3", "c^3",                             // cubic, pure
                                      "a^2*b", "a^2*c", "a*b^2", "a*c^2", "b^2*c", "b*c^2"}));
  // The degree cap also applies to the multilinear terms.
  EXPECT_EQ(texts(basis_growth_order(3, 2), names),
            (std::vector<std::string>{"1", "a", "b", "c", "a*b", "a*c", "b*c", "a^2", "b^2", "c^2"}));
}

int binomial(int n, int k) {
  long r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return static_cast<int>(r);
}

RC_GTEST_PROP(BasisGrowthOrder, EveryMonomialOnceInStageOrder, ()) {
  const int n = *rc::gen::inRange(0, 5);
  const int d = *rc::gen::inRange(0, 5);
  const std::vector<Monomial> order = basis_growth_order(n, d);
  RC_ASSERT(static_cast<int>(order.size()) == binomial(n + d, d));  // all monomials of degree ≤ d
  std::set<std::vector<int>> seen;
  int last_stage = 0, last_degree = 0;
  for (size_t i = 0; i < order.size(); ++i) {
    const Monomial& m = order[i];
    RC_ASSERT(static_cast<int>(m.powers.size()) == n);
    RC_ASSERT(m.degree() <= d);
    RC_ASSERT(seen.insert(m.powers).second);
    const bool ml = std::all_of(m.powers.begin(), m.powers.end(), [](int p) { return p <= 1; });
    const int st = m.degree() <= 1 ? m.degree() : (ml ? 2 : 3);
    if (i == 0) RC_ASSERT(m.is_constant());
    RC_ASSERT(st >= last_stage);                                  // LTI → affine → multilinear → the rest
    if (st == last_stage) RC_ASSERT(m.degree() >= last_degree);   // by increasing degree within a stage
    last_stage = st;
    last_degree = m.degree();
  }
}

TEST(WithCorrectionBasis, KeepsDeclaredFixedMatricesAndZerosNewOnes) {
  LpvModel<double> m = convert_model<double>(example1_initial_model());
  m.correction.A[5] = Mat<double>::Constant(2, 2, 0.25);  // rho2^2 has a fixed A_i
  const std::vector<Monomial> b = {Monomial{{0, 2}}, Monomial{{3, 0}}};
  const LpvModel<double> r = with_correction_basis(m, b);
  ASSERT_EQ(r.correction.basis.size(), 2u);
  EXPECT_EQ(r.correction.A[0], Mat<double>::Constant(2, 2, 0.25));
  EXPECT_TRUE(r.correction.A[1].isZero(0.0));
  EXPECT_TRUE(r.correction.B[0].isZero(0.0));
  EXPECT_EQ(basis_text(b, m.scheduling), "rho2^2, rho1^3");
  EXPECT_EQ(basis_text({}, m.scheduling), "(none)");
}

TEST(MonotonicityViolation, FindsAConsistentSubsetOfABasisThatIsNot) {
  BasisStep a, b;
  a.index = 0;
  a.basis = {Monomial{{0, 0}}};
  a.verdict = BasisVerdict::kConsistent;
  b.index = 1;
  b.basis = {Monomial{{0, 0}}, Monomial{{1, 0}}};
  b.verdict = BasisVerdict::kNotDecided;
  EXPECT_NE(monotonicity_violation({a, b}).find("not decided"), std::string::npos);
  b.verdict = BasisVerdict::kCannotExplain;  // two exact certificates contradicting each other
  EXPECT_NE(monotonicity_violation({a, b}).find("contradict"), std::string::npos);
  b.verdict = BasisVerdict::kBoxInvalidated;  // only a box: the consistent theta may lie outside it
  EXPECT_NE(monotonicity_violation({a, b}).find("box only"), std::string::npos);
  b.verdict = BasisVerdict::kUnverified;
  EXPECT_EQ(monotonicity_violation({a, b}), "");
  a.verdict = BasisVerdict::kCannotExplain;
  b.verdict = BasisVerdict::kConsistent;
  EXPECT_EQ(monotonicity_violation({a, b}), "");  // adding terms may turn "cannot explain" into consistent
}

/// The steps' certificates written as `lpvid select-basis` writes them.
BasisSelectionResult with_files(BasisSelectionResult r, const std::string& stem) {
  cli::write_step_certificates(r, stem);
  return r;
}

/// Checks shared by the runs: steps well formed, consistent ⇔ verified
/// certificate on disk accepted again by the verifier, "cannot explain" and
/// box invalidations ⇔ a class certificate on disk that the verifier accepts
/// (over the whole class, resp. a box), monotone verdicts.
void check_steps(const BasisSelectionResult& r) {
  ASSERT_FALSE(r.steps.empty());
  EXPECT_EQ(r.steps.front().phase, "initial");
  EXPECT_TRUE(r.steps.front().basis.empty());
  for (const BasisStep& s : r.steps) {
    SCOPED_TRACE("step " + std::to_string(s.index) + " {" + s.basis_text + "}: " + s.detail);
    if (s.verdict == BasisVerdict::kConsistent) {
      EXPECT_TRUE(s.bounds.verified());
      ASSERT_FALSE(s.certificate.empty());
      EXPECT_TRUE(check_certificate_file(s.certificate).holds);
    } else {
      EXPECT_TRUE(s.certificate.empty());
    }
    const bool refuted = s.verdict == BasisVerdict::kCannotExplain || s.verdict == BasisVerdict::kBoxInvalidated;
    EXPECT_EQ(refuted, !s.class_certificate.empty());
    if (!refuted) continue;
    const CertificateVerdict v = check_certificate_file(s.class_certificate);
    EXPECT_TRUE(v.holds) << v.reason;
    const Certificate c = parse_certificate(read_text_file(s.class_certificate), s.class_certificate);
    EXPECT_EQ(c.claim, CertificateClaim::kClassInvalidated);
    EXPECT_EQ(c.region.free.size() == c.region.parameters.size(), s.verdict == BasisVerdict::kCannotExplain);
  }
  EXPECT_EQ(monotonicity_violation(r.steps), "");
}

TEST(SelectBasis, Example1IteratedFindsTheMissingRho2Squared) {
  const Example1Data data(30);
  BasisSelectionOptions o = data.options("0.05", "0.01");
  o.iterate = true;
  auto solver = make_solver("csdp");
  const BasisSelectionResult r =
      with_files(select_basis(data, o, *solver), data.dir.file("sel"));
  for (const BasisStep& s : r.steps)
    std::cout << "  step " << s.index << " " << s.phase << " {" << s.basis_text << "} " << to_string(s.verdict)
              << (s.dmax_relaxation >= 0 ? "  dmax_relax = " + std::to_string(s.dmax_relaxation) : "") << "\n";
  check_steps(r);
  // S_I lacks the rho2^2 factor; with no unknown, its "class" is S_I itself: certified
  EXPECT_EQ(r.steps.front().verdict, BasisVerdict::kCannotExplain);
  ASSERT_TRUE(r.found());
  const Monomial rho2sq{{0, 2}};
  EXPECT_NE(std::find(r.basis.begin(), r.basis.end(), rho2sq), r.basis.end());
  // Growth stops at the first consistent basis: the full paper basis (rho2^2 is last).
  int grown = 0;
  for (const BasisStep& s : r.steps)
    if (s.phase == "grow") ++grown;
  EXPECT_EQ(grown, 6);
  // Pruning removed at least the terms the truth does not need.
  EXPECT_LT(r.basis.size(), 6u);
  const BasisStep& f = r.steps[static_cast<size_t>(r.final_step)];
  EXPECT_TRUE(f.bounds.verified());
  EXPECT_EQ(f.basis, r.basis);
}

TEST(SelectBasis, Example1PaperRelaxationAtLooserBounds) {
  // Without --iterate (one relaxation at S_I), tight bounds reject every
  // basis; at d_max = 0.3 the affine class is consistent.
  const Example1Data data(30);
  const BasisSelectionOptions o = data.options("0.05", "0.3");
  auto solver = make_solver("csdp");
  const BasisSelectionResult r =
      with_files(select_basis(data, o, *solver), data.dir.file("sel"));
  check_steps(r);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.steps.front().verdict, BasisVerdict::kCannotExplain);
  EXPECT_FALSE(r.basis.empty());
  EXPECT_LE(r.basis.size(), 2u);
}

TEST(SelectBasis, SolverInfeasibleWithoutAClassCertificateIsNotDecided) {
  // The relaxation at S_I finds every grown basis infeasible at these tight
  // bounds (a solver verdict). Over a box of half-width ||z|| per parameter
  // around theta = 0 the first-order class bound cannot be positive (3
  // leaves): no certificate, so "not decided", the solver's verdict and the
  // reason in the detail. S_I itself (no unknown) is still certified.
  const Example1Data data(30);
  BasisSelectionOptions o = data.options("0.05", "0.01");
  o.max_degree = 1;
  o.klass.box_fraction = 1;
  o.klass.max_leaves = 3;
  auto solver = make_solver("csdp");
  const BasisSelectionResult r =
      with_files(select_basis(data, o, *solver), data.dir.file("sel"));
  check_steps(r);
  ASSERT_EQ(r.steps.size(), 4u);
  EXPECT_EQ(r.steps[0].verdict, BasisVerdict::kCannotExplain);
  for (size_t i = 1; i < r.steps.size(); ++i) {
    const BasisStep& s = r.steps[i];
    EXPECT_EQ(s.verdict, BasisVerdict::kNotDecided) << s.detail;
    EXPECT_NE(s.detail.find("the solver found"), std::string::npos) << s.detail;
    EXPECT_NE(s.detail.find("no class certificate: "), std::string::npos) << s.detail;
    ASSERT_TRUE(s.klass.has_value());
    EXPECT_FALSE(s.klass->certified());
    EXPECT_TRUE(s.class_certificate.empty());
  }
  EXPECT_FALSE(r.found());
  EXPECT_NE(r.outcome, SelectionOutcome::kCannotExplain);
}

}  // namespace
}  // namespace lpvid
