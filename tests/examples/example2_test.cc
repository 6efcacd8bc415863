// The Example-2-flavoured data set (examples/paper_example2.h, paper eq. 20):
// exact generation, the fixture files, and identification of the offset φ.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/decimal_rounding.h"
#include "core/number_text.h"
#include "certify/certificate_files.h"
#include "data/csv_reader.h"
#include "data/data_reference.h"
#include "data/csv_writer.h"
#include "data/experiment_builder.h"
#include "examples/paper_example2.h"
#include "certify/certify.h"
#include "identify/identify.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "verify/certificate/certificate_check.h"

#include "support/scratch_dir.h"

namespace lpvid {
namespace {

namespace fs = std::filesystem;

std::vector<TextColumn> columns(const Experiment<Rational>& e) {
  return {{"u1", column_text(e.u, 0)}, {"y1", column_text(e.y, 0)}, {"rho1", column_text(e.rho, 0)}};
}

std::string read_file(const std::string& p) {
  std::ifstream f(p);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

Rational abs_q(const Rational& q) { return q < 0 ? Rational(-q) : q; }

// Noise-free y is the exact simulation of the true system (with Φ) rounded
// to 10 decimals; u and ρ are the stated short decimals.
RC_GTEST_PROP(Example2, DataIsTheExactTruthRounded, ()) {
  Example2Options o;
  o.n = *rc::gen::inRange(2, 25);
  o.seed = *rc::gen::inRange<uint64_t>(0, 1000000);
  const Experiment<Rational> e = example2_experiment(o);
  RC_ASSERT(e.n() == o.n);
  const Simulation<Rational> sim = simulate(example2_true_model(), e);
  const Rational half_ulp = rational_from_text("0.00000000005");
  for (int k = 0; k < o.n; ++k) {
    RC_ASSERT((e.u(k, 0) == rational_from_text("0.5") || e.u(k, 0) == rational_from_text("-0.5")));
    RC_ASSERT(e.rho(k, 0) >= rational_from_text("0.05"));
    RC_ASSERT(e.rho(k, 0) <= rational_from_text("0.95"));
    const Rational scaled = e.rho(k, 0) * 10000;  // at most 4 decimals
    RC_ASSERT(mpz_cmp_ui(mpq_denref(scaled.mpq()), 1) == 0);
    const Rational rho = e.rho(k, 0);
    const Rational phi = rational_from_text("0.5") + rational_from_text("0.8") * rho - rational_from_text("0.3") * rho * rho;
    RC_ASSERT(sim.offset(k, 0) == phi);
    RC_ASSERT(abs_q(e.y(k, 0) - sim.yhat(k, 0) - phi) <= half_ulp);
  }
  // Deterministic.
  const Experiment<Rational> again = example2_experiment(o);
  RC_ASSERT(again.y == e.y);
  RC_ASSERT(again.u == e.u);
}

TEST(Example2, FixturesAreTheGeneratorOutput) {
  const std::string dir = std::string(LPVID_SOURCE_DIR) + "/fixtures/example2/";
  Example2Options o;
  o.n = 40;
  EXPECT_EQ(read_file(dir + "data.csv"), csv_text(columns(example2_experiment(o))));
  EXPECT_EQ(read_file(dir + "initial_model.json"), write_model_json(example2_initial_model()));
  EXPECT_EQ(read_file(dir + "true_model.json"), write_model_json(example2_true_model()));
  const LpvModel<Rational> m = read_model_file<Rational>(dir + "initial_model.json");
  ASSERT_EQ(m.offset.basis.size(), 3u);
  EXPECT_TRUE(m.offset.values.empty());  // unknown: identified
}

TEST(Example2, IdentifiesTheOffsetAndCertifies) {
  gen::ScratchDir dir("select");
  Example2Options o;
  o.n = 40;
  const std::string csv = dir.file("data.csv");
  write_csv(csv, columns(example2_experiment(o)));
  const LpvModel<Rational> mq = example2_initial_model();
  const LpvModel<double> md = convert_model<double>(mq);
  const TextTable t = read_table(csv);
  const Experiment<Rational> xq = make_experiment<Rational>(t, mq.columns);
  const Experiment<double> xd = make_experiment<double>(t, md.columns);

  IdentifyOptions io;  // the CLI default: minimise 0.5 delta^2 + 0.5 dmax^2
  auto solver = make_solver("csdp");
  const IdentifyResult res = identify(md, xd, io, *solver);
  ASSERT_TRUE(has_solution(res.status)) << res.message;
  ASSERT_EQ(res.layout.n_phi, 3);
  ASSERT_EQ(res.p.size(), 3);
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(res.p(j), kExample2Phi[j], 1e-3) << "phi_" << j;

  Vec<Rational> pq(3);
  for (int j = 0; j < 3; ++j) pq(j) = round_to_digits(res.p(j), 12);
  const LpvModel<Rational> fixed = apply_parameters(mq, res.layout, pq);
  CertifyOptions co;
  co.objective = io.objective;
  co.records = {read_data_table(csv).reference};
  const CertifiedBounds b = certify_fixed_model(fixed, xq, co, *solver);
  ASSERT_TRUE(b.verified()) << b.reason;
  EXPECT_TRUE(check_certificate_file(write_certificates(b, dir.file("ex2.cert.json")).certificate).holds);
  EXPECT_LT(b.dmax, 1e-6);  // noise-free: the offset explains the output exactly
  EXPECT_LT(b.delta, 1e-3);
}

}  // namespace
}  // namespace lpvid
