// The effect parameters a diagnose report prints are the FINAL model's:
// effect_parameters (diagnose/effect_ranking.h) with a later model as
// `fitted` reads the effect's own terms (what the model right after the
// effect has and the model before it has not) with the later values.
// Known answers by construction.
#include <gtest/gtest.h>

#include "diagnose/effect_ranking.h"

namespace lpvid {
namespace {

LpvModel<double> one_state(const std::vector<std::string>& scheduling) {
  LpvModel<double> m;
  m.nx = m.nu = m.ny = 1;
  m.scheduling = scheduling;
  m.columns = {{"u"}, {"y"}, scheduling};
  const Monomial one = constant_monomial(scheduling.size());
  for (ParamMatrix<double>* pm : {&m.A, &m.B, &m.C, &m.D}) {
    *pm = ParamMatrix<double>(1, 1);
    pm->add(one, Mat<double>::Constant(1, 1, 0.5));
  }
  return m;
}

Monomial power(size_t n, size_t j, int p) {
  Monomial f = constant_monomial(n);
  f.powers[j] = p;
  return f;
}

// Round 1 adds ρ·C_ρ with C_ρ = 0.383; round 2 adds ρ² and re-fits C_ρ to
// 0.078. Reported from the final model: C_ρ = 0.078, and the ρ² term is not
// round 1's.
TEST(EffectParameters, ReadFromTheFinalModelWithoutLaterTerms) {
  const LpvModel<double> before = one_state({"rho"});
  LpvModel<double> round1 = before;
  round1.C.add(power(1, 0, 1), Mat<double>::Constant(1, 1, 0.383));
  round1.D.add(power(1, 0, 1), Mat<double>::Constant(1, 1, -0.2));
  LpvModel<double> final_model = round1;
  final_model.C.terms[1].value(0, 0) = 0.078;
  final_model.D.terms[1].value(0, 0) = -0.1;
  final_model.C.add(power(1, 0, 2), Mat<double>::Constant(1, 1, 0.9));

  const auto at_round = effect_parameters("basis_term", "basis_term rho", round1, before);
  EXPECT_DOUBLE_EQ(at_round["C"][0][0].get<double>(), 0.383);
  const auto final_params = effect_parameters("basis_term", "basis_term rho", final_model, before, &round1);
  EXPECT_EQ(final_params["basis"], "rho");
  EXPECT_DOUBLE_EQ(final_params["C"][0][0].get<double>(), 0.078);
  EXPECT_DOUBLE_EQ(final_params["D"][0][0].get<double>(), -0.1);
}

// A static input map re-fitted later: the final limits.
TEST(EffectParameters, StaticMapValuesAreTheFinalOnes) {
  const LpvModel<double> before = one_state({});
  LpvModel<double> round1 = before;
  round1.statics.input.kind = StaticKind::kPolynomial;
  round1.statics.input.coefficients = {0, 1, 0, -0.383};
  LpvModel<double> final_model = round1;
  final_model.statics.input.coefficients = {0, 1, 0, -0.078};
  final_model.statics.input_delay = 2;  // a later round's effect
  const auto p = effect_parameters("input_polynomial", "input_polynomial degree 3", final_model, before, &round1);
  EXPECT_DOUBLE_EQ(p["input_map"]["coefficients"][3].get<double>(), -0.078);
  EXPECT_FALSE(p.contains("delay_samples"));
}

// Scheduling variables appended by a later round pad every monomial: the
// effect's term is still found (and named with the final model's names).
TEST(EffectParameters, LaterSchedulingVariablesDoNotHideTheTerm) {
  const LpvModel<double> before = one_state({"rho"});
  LpvModel<double> round1 = before;
  round1.B.add(power(1, 0, 1), Mat<double>::Constant(1, 1, 0.25));
  LpvModel<double> final_model = one_state({"rho", "xhat1"});
  final_model.B.add(power(2, 0, 1), Mat<double>::Constant(1, 1, 0.125));
  final_model.A.add(power(2, 1, 1), Mat<double>::Constant(1, 1, 0.01));
  const auto p = effect_parameters("basis_term", "basis_term rho in B", final_model, before, &round1);
  EXPECT_EQ(p["basis"], "rho");
  EXPECT_DOUBLE_EQ(p["B"][0][0].get<double>(), 0.125);
  EXPECT_FALSE(p.contains("A"));
}

}  // namespace
}  // namespace lpvid
