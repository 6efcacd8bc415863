// Finished work survives a later failure: in diagnose, a bound window whose
// certification fails is that window's "not verified" with the reason, and
// a failure of the optional Theorem 3.1 stage is that stage's failure; the
// caller keeps everything else. Constructed failure: a model whose free run
// diverges along the data (A = 1000·I leaves double precision after about
// 103 samples), which both stages must refuse before any solver.
#include <gtest/gtest.h>

#include "data/experiment_builder.h"
#include "diagnose/window_bounds.h"
#include "diagnose/window_identification.h"
#include "examples/random_case.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/gen_models.h"

namespace lpvid {
namespace {

struct Diverging {
  LpvModel<double> model;
  ExperimentViews est;  ///< the double view converted from the exact one
};

Diverging diverging_case(uint64_t seed) {
  RandomCaseOptions o;
  o.min_n = o.max_n = 150;
  SeededDraw draw(seed);
  RandomCase c = random_case(o, draw);
  c.model.A = ParamMatrix<Rational>(c.model.nx, c.model.nx);
  c.model.A.add(constant_monomial(c.model.scheduling.size()),
                Mat<Rational>(Mat<Rational>::Identity(c.model.nx, c.model.nx) * Rational(1000)));
  return {convert_model<double>(c.model), {c.exp, gen::to_double_experiment(c.exp)}};
}

CertifyOptions weighted() {
  CertifyOptions o;
  o.objective.kind = BoundObjective::Kind::kWeighted;  // lambda 0.5
  return o;
}

TEST(FinishedWork, AWindowThatCannotBeCertifiedIsNotVerifiedWithItsReason) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Diverging c = diverging_case(seed);
    auto solver = make_solver("csdp");
    WindowBounds w;
    ASSERT_NO_THROW(w = certify_window(c.model, c.est, 0, c.est.exp_d.n(), weighted(), *solver));
    EXPECT_FALSE(w.bounds.verified());
    EXPECT_NE(w.bounds.reason.find("certification failed on this window"), std::string::npos) << w.bounds.reason;
    EXPECT_NE(w.bounds.reason.find("no solver was called"), std::string::npos) << w.bounds.reason;
  }
}

TEST(FinishedWork, AFailedTheorem31StageIsThatStagesFailure) {
  for (uint64_t seed : {1u, 2u, 3u}) {
    const Diverging c = diverging_case(seed);
    auto solver = make_solver("csdp");
    EXPECT_ANY_THROW(identify_on_window(c.model, c.est, 0, c.est.exp_d.n(), weighted(), *solver));
    WindowIdentification id;
    ASSERT_NO_THROW(id = try_identify_on_window(c.model, c.est, 0, c.est.exp_d.n(), weighted(), *solver));
    EXPECT_TRUE(id.applicable);
    EXPECT_NE(id.failed.find("optional Theorem 3.1 stage failed"), std::string::npos) << id.failed;
    EXPECT_NE(id.failed.find("Theorem 3.1"), std::string::npos);
    EXPECT_FALSE(id.bounds.bounds.verified());
  }
}

}  // namespace
}  // namespace lpvid
