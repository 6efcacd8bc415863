// select-basis says "cannot explain the data" only with a class certificate
// (identify/basis_selection.h): on data made by a member of an additive class
// (Theorem 3.1 convex: the certificate covers every θ of the basis), a basis
// too small is certified unable to explain the data, while no basis that
// contains the true one may be (the truth is a member of its class and
// explains the data: a known answer); and from the command line, every step
// that says so names a certificate file the separate program
// `lpvid-verify certificate` accepts.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "cli/certificate_names.h"
#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "identify/basis_selection.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/cli_runner.h"
#include "support/gen_identify.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

using namespace gen;

/// x rounded up to 6 significant digits, exact decimal text (keeps the truth inside the bound).
std::string rounded_up(double x) { return exact_decimal_or_fraction(round_up_to_digits(exact_rational_of_double(x), 6)); }

/// Generated additive cases with a true correction θ on 1–2 basis functions.
std::vector<IdentCase> additive_member_cases(int count) {
  IdentCaseOptions o;
  o.model.min_rho = 1;
  o.model.max_rho = 2;
  o.model.min_correction = 1;
  o.model.max_correction = 2;
  o.model.lti = false;
  o.true_correction = true;
  o.min_n = 10;
  o.max_n = 20;
  std::vector<IdentCase> out;
  for (uint64_t seed = 1; seed < 400 && static_cast<int>(out.size()) < count; ++seed) {
    const IdentCase c = sample(ident_case(o), seed);
    if (c.model.uncertainty.structure == UncertaintyStructure::kAdditive && c.theta.size() > 0 &&
        c.model.offset.basis.empty())
      out.push_back(c);
  }
  return out;
}

bool contains_all(const std::vector<Monomial>& big, const std::vector<Monomial>& small) {
  return std::all_of(small.begin(), small.end(),
                     [&](const Monomial& m) { return std::find(big.begin(), big.end(), m) != big.end(); });
}

TEST(SelectBasisCertified, ATooSmallAdditiveBasisIsCertifiedUnableToExplainTheData) {
  const std::vector<IdentCase> cases = additive_member_cases(6);
  ASSERT_EQ(cases.size(), 6u);
  int certified_nonempty = 0;
  for (const IdentCase& c : cases) {
    ScratchDir dir("select-additive");
    const std::string data = dir.file("data.csv");
    write_experiment_csv(data, c.model, c.exp);
    const LpvModel<double> model_d = convert_model<double>(c.model);
    const Experiment<double> exp_d = read_experiment(data, model_d);
    BasisSelectionOptions o;
    o.delta = ExactBound::from_text(rounded_up(c.delta));
    o.dmax = ExactBound::from_text(rounded_up(c.dmax));
    o.unknowns.offset = false;
    o.prune = false;
    o.max_degree = 0;
    for (const Monomial& m : c.model.correction.basis) o.max_degree = std::max(o.max_degree, m.degree());
    o.certify.records = {read_data_table(data).reference};
    auto solver = make_solver("csdp");
    BasisSelectionResult r = select_basis(Problem{c.model, model_d, c.exp, exp_d}, o, *solver);
    cli::write_step_certificates(r, dir.file("sel"));
    for (const BasisStep& s : r.steps) {
      std::cout << "  n = " << c.exp.n() << " true basis {" << basis_text(c.model.correction.basis, c.model.scheduling)
                << "}: step " << s.index << " {" << s.basis_text << "} " << to_string(s.verdict) << "\n";
      SCOPED_TRACE("step " + std::to_string(s.index) + " {" + s.basis_text + "}: " + s.detail);
      // additive: every class certificate covers the whole class, never a box
      EXPECT_NE(s.verdict, BasisVerdict::kBoxInvalidated);
      // the truth is a member of every class that contains its basis
      if (contains_all(s.basis, c.model.correction.basis)) {
        EXPECT_NE(s.verdict, BasisVerdict::kCannotExplain);
      }
      if (s.verdict != BasisVerdict::kCannotExplain) continue;
      ASSERT_FALSE(s.class_certificate.empty());
      EXPECT_TRUE(check_certificate_file(s.class_certificate).holds);
      ASSERT_TRUE(s.klass && s.klass->whole_class);
      if (!s.basis.empty()) ++certified_nonempty;
    }
  }
  // a basis with free corrections (not only S_I) was certified unable at least once
  EXPECT_GE(certified_nonempty, 1);
}

struct SelectBasisCli : CliRunner {};

TEST_F(SelectBasisCli, EveryCannotExplainNamesAClassCertificateThatLpvidVerifyAccepts) {
  // Example 1 (multiplicative) at tight bounds: S_I (no unknown) is certified
  // unable; the grown bases only on a box around theta = 0 (the relaxation at
  // S_I finds no model): box_invalidated, never cannot_explain.
  const std::string src = LPVID_SOURCE_DIR;
  const int code = run("select-basis", "--quiet --data " + src + "/fixtures/example1/noise_free_n40.csv --model " + src +
                                           "/fixtures/example1/initial_model.json --delta 0.05 --dmax 0.01 --degree 1"
                                           " --report " + file("r.json") + " --certificate " + file("s.cert.json"));
  EXPECT_EQ(code, 5) << output();  // no consistent basis, and not certified for the largest one
  const nlohmann::json r = read_json(file("r.json"));
  EXPECT_EQ(r["status"], "not_decided");
  ASSERT_EQ(r["steps"].size(), 4u);
  int refuted = 0;
  for (const nlohmann::json& s : r["steps"]) {
    const std::string verdict = s["verdict"];
    const nlohmann::json& k = s["class_certificate"];
    if (verdict != "cannot_explain" && verdict != "box_invalidated") {
      EXPECT_TRUE(k.is_null() || !k["certified"].get<bool>()) << s.dump();
      continue;
    }
    ++refuted;
    ASSERT_TRUE(k["certified"].get<bool>()) << s.dump();
    EXPECT_EQ(k["region"], verdict == "cannot_explain" ? "whole_class" : "box") << s.dump();
    const std::string cert = k["certificate"];
    EXPECT_EQ(cert, file("s.step" + std::to_string(s["step"].get<int>()) + ".class.json"));
    EXPECT_EQ(run_program(verify_exe, "certificate " + cert), 0) << output();
    EXPECT_NE(output().find("class_invalidated"), std::string::npos) << output();
  }
  EXPECT_EQ(r["steps"][0]["verdict"], "cannot_explain");
  EXPECT_EQ(r["steps"][1]["verdict"], "box_invalidated");
  EXPECT_EQ(refuted, 4);
}

}  // namespace
}  // namespace lpvid
