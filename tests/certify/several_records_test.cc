// Theorem 2.1 over several records (docs/several_records.md): one causal LTI
// Δ, at rest at the start of every record, and one noise bound (RMS over
// every sample of every record). Known answers by construction: records
// made by one Δ are consistent jointly; records made by Δ = +a and Δ = −a are
// each consistent at δ = a but cannot be explained by one Δ with ‖Δ‖∞ ≤ δ
// and tiny noise. Every certificate goes through the lpvid-verify program.
#include <gtest/gtest.h>

#include <cmath>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "core/file_io.h"
#include "core/number_text.h"
#include "core/sha256.h"
#include "data/csv_writer.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"
#include "model/simulate.h"
#include "solvers/sdp_solver.h"
#include "solvers/solver_factory.h"
#include "support/cli_runner.h"
#include "support/fixtures.h"
#include "support/gen_identify.h"
#include "toeplitz/fir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

/// The LTI SISO fixture: additive uncertainty, z = u/10.
LpvModel<Rational> siso_model() {
  return read_model_file<Rational>(std::string(LPVID_SOURCE_DIR) + "/fixtures/models/lti_siso.json");
}

/// n inputs from a fixed integer recurrence (exact decimals in ±1, never 0),
/// scaled by `amplitude`.
Experiment<Rational> input_record(Eigen::Index n, int seed, const Rational& amplitude) {
  Experiment<Rational> e;
  e.u = Mat<Rational>(n, 1);
  e.rho = Mat<Rational>(n, 0);
  long s = seed;
  for (Eigen::Index k = 0; k < n; ++k) {
    s = (s * 1103515245 + 12345) % 2147483648;
    const long v = (s / 65536) % 19 - 9;  // −9 … 9
    e.u(k, 0) = amplitude * Rational(v == 0 ? 5 : v) / Rational(10);
  }
  return e;
}

/// y = ŷ + Δ ∗ z + d along the record, exactly: Δ from rest (taps, one per
/// row), d = noise·(−1)^k.
Experiment<Rational> output_record(const LpvModel<Rational>& model, Experiment<Rational> e, const Mat<Rational>& taps,
                                   const Rational& noise) {
  e.y = Mat<Rational>::Zero(e.u.rows(), 1);
  const Simulation<Rational> sim = simulate(model, e);
  const Mat<Rational> w = apply_fir(taps, sim.z, 1, e.n());
  for (Eigen::Index k = 0; k < e.n(); ++k) e.y(k, 0) = sim.output(k, 0) + w(k, 0) + (k % 2 == 0 ? noise : -noise);
  return e;
}

Mat<Rational> one_tap(const Rational& a) {
  Mat<Rational> t(1, 1);
  t(0, 0) = a;
  return t;
}

struct SeveralRecords : gen::CliRunner {
  LpvModel<Rational> model = siso_model();

  std::string write_record(const std::string& name, const Experiment<Rational>& e) {
    const std::string path = file(name);
    write_csv(path, experiment_columns(model.columns, e));
    return path;
  }
  /// The records read back from their files, stacked, with their references.
  Experiment<Rational> stacked(const std::vector<std::string>& paths, std::vector<DataReference>& refs) {
    std::vector<Experiment<Rational>> parts;
    refs.clear();
    for (const std::string& p : paths) {
      const DataTable t = read_data_table(p);
      refs.push_back(t.reference);
      parts.push_back(make_experiment<Rational>(t.table, model.columns));
    }
    return stack_records(parts);
  }
  /// Fixed (δ, d_max): certify, write the certificate(s) beside the data, and
  /// check the main one with the lpvid-verify program (exit code returned).
  CertifiedBounds decide(const std::vector<std::string>& paths, double delta, double dmax, const std::string& cert,
                         int* verify_exit) {
    std::vector<DataReference> refs;
    const Experiment<Rational> exp = stacked(paths, refs);
    CertifyOptions o = gen::certify_options(gen::feasibility_objective(delta, dmax), paths.front());
    o.records = refs;
    const std::unique_ptr<SdpSolver> solver = make_solver("csdp");
    CertifiedBounds b = certify_fixed_model(model, exp, o, *solver);
    if (b.certificate) {
      write_certificates(b, file(cert));
      *verify_exit = run_program(verify_exe, "certificate " + file(cert));
    }
    return b;
  }
};

// The verifier, with a hand-made primal point: two records made by ONE Δ
// (taps 0.3, −0.2) with noise ±0.001 are consistent at δ = 0.5 ≥ ‖T_Δ‖
// (ℓ1 norm of the taps) and d_max = 0.001 exactly; the same point fails when
// the noise bound is lowered, when Δ runs across the seam of the concatenated
// records, and when a record file changes.
TEST_F(SeveralRecords, OneDeltaExplainsBothRecordsExactly) {
  Mat<Rational> taps(2, 1);
  taps << Rational(3, 10), Rational(-2, 10);
  const Rational noise(1, 1000);
  const std::string a = write_record("a.csv", output_record(model, input_record(40, 1, Rational(1)), taps, noise));
  const std::string b = write_record("b.csv", output_record(model, input_record(30, 7, Rational(3)), taps, noise));
  std::vector<DataReference> refs;
  stacked({a, b}, refs);
  Certificate c;
  set_record_references(c, refs);
  ASSERT_EQ(c.records.size(), 2u);
  c.model = model;
  c.form = CertificateForm::kDelta;
  c.taps = taps;
  c.horizon = 40;  // the longest record; z = u/10 has no leading zeros
  c.delta2 = Rational(1, 4);
  c.dmax2 = noise * noise;
  write_certificate(file("joint.cert.json"), placed_at(c, file("joint.cert.json")));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("joint.cert.json")), 0) << output();
  EXPECT_NE(output().find("2 records under one Delta"), std::string::npos) << output();

  // The order of the records changes nothing.
  Certificate swapped = c;
  std::swap(swapped.records[0], swapped.records[1]);
  write_certificate(file("swapped.cert.json"), placed_at(swapped, file("swapped.cert.json")));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("swapped.cert.json")), 0) << output();

  // d_max² below the pooled noise energy: (C2) fails.
  Certificate lower = c;
  lower.dmax2 = noise * noise * Rational(999, 1000);
  write_certificate(file("lower.cert.json"), placed_at(lower, file("lower.cert.json")));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("lower.cert.json")), 1) << output();
  EXPECT_NE(output().find("(C2) fails"), std::string::npos) << output();

  // One record of both, concatenated: Δ's memory crosses the seam, w differs
  // at the second record's first sample, and the same point no longer explains it.
  const std::string ab = file("ab.csv");
  write_text(ab, read_text(a) + read_text(b).substr(read_text(b).find('\n') + 1));
  Certificate one = c;
  one.records.clear();
  set_data_reference(one, read_data_table(ab).reference);
  one.horizon = 70;
  write_certificate(file("one.cert.json"), placed_at(one, file("one.cert.json")));
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("one.cert.json")), 1) << output();

  // A record file that changed after certification.
  write_text(b, read_text(b) + "\n");
  EXPECT_EQ(run_program(verify_exe, "certificate " + file("joint.cert.json")), 1) << output();
  EXPECT_NE(output().find("has changed"), std::string::npos) << output();
}

// Each record alone is consistent at δ = 0.2 (its own Δ = ±0.2, tiny noise);
// jointly the claim is invalidated at the same (δ, d_max): one Δ cannot be
// +0.2 on one record and −0.2 on the other. Both verdicts come from the
// solver and are certified; lpvid-verify checks every certificate.
TEST_F(SeveralRecords, JointClaimIsInvalidatedWhereEachRecordAloneIsConsistent) {
  const Rational noise(1, 100000);
  const std::string a = write_record("a.csv", output_record(model, input_record(40, 3, Rational(1)), one_tap(Rational(2, 10)), noise));
  const std::string b = write_record("b.csv", output_record(model, input_record(40, 11, Rational(1)), one_tap(Rational(-2, 10)), noise));
  const double delta = 0.2 * 1.01, dmax = 2e-5;
  int exit_a = -1, exit_b = -1, exit_joint = -1;
  const CertifiedBounds alone_a = decide({a}, delta, dmax, "a.cert.json", &exit_a);
  const CertifiedBounds alone_b = decide({b}, delta, dmax, "b.cert.json", &exit_b);
  EXPECT_EQ(alone_a.outcome, CertifyOutcome::kVerified) << alone_a.reason;
  EXPECT_EQ(alone_b.outcome, CertifyOutcome::kVerified) << alone_b.reason;
  EXPECT_EQ(exit_a, 0);
  EXPECT_EQ(exit_b, 0);
  const CertifiedBounds joint = decide({a, b}, delta, dmax, "joint.cert.json", &exit_joint);
  ASSERT_EQ(joint.outcome, CertifyOutcome::kInvalidated) << joint.reason;
  EXPECT_EQ(exit_joint, 0) << output();
  EXPECT_NE(output().find("invalidated"), std::string::npos) << output();
  const nlohmann::json cert = read_json(file("joint.cert.json"));
  ASSERT_TRUE(cert.contains("records"));
  EXPECT_EQ(cert["records"].size(), 2u);
  EXPECT_FALSE(cert.contains("data"));
}

// The order of the records changes no bound: the certified interval of the
// minimal d_max at a fixed δ is the same for (a, b) and (b, a) up to the
// solver's accuracy, and both intervals contain the other's upper end's
// neighbourhood (they overlap).
TEST_F(SeveralRecords, RecordOrderDoesNotChangeTheBounds) {
  Mat<Rational> taps(2, 1);
  taps << Rational(1, 10), Rational(1, 20);
  const std::string a = write_record("a.csv", output_record(model, input_record(50, 5, Rational(1)), taps, Rational(1, 200)));
  const std::string b = write_record("b.csv", output_record(model, input_record(35, 9, Rational(2)), taps, Rational(1, 100)));
  const auto bounds = [&](const std::vector<std::string>& paths) {
    std::vector<DataReference> refs;
    const Experiment<Rational> exp = stacked(paths, refs);
    CertifyOptions o = gen::certify_options(gen::min_dmax_objective(0.12), paths.front());
    o.records = refs;
    const std::unique_ptr<SdpSolver> solver = make_solver("csdp");
    return certify_fixed_model(model, exp, o, *solver);
  };
  const CertifiedBounds ab = bounds({a, b}), ba = bounds({b, a});
  ASSERT_TRUE(ab.verified() && ba.verified()) << ab.reason << " / " << ba.reason;
  ASSERT_TRUE(ab.lower.verified() && ba.lower.verified()) << ab.lower.reason << " / " << ba.lower.reason;
  const double u1 = nearest_double(ab.upper), u2 = nearest_double(ba.upper);
  EXPECT_NEAR(u1, u2, 1e-4 * u1);
  EXPECT_LE(ab.lower.value, ba.upper);
  EXPECT_LE(ba.lower.value, ab.upper);
  // The pooled noise bound lies between the records' own: the noise of ±0.005
  // and ±0.01 pooled over 50 and 35 samples.
  const double pooled = (50 * 0.005 * 0.005 + 35 * 0.01 * 0.01) / 85;
  EXPECT_LE(nearest_double(ab.lower.value), pooled * (1 + 1e-6));
}

// One record through stack_records is the one-record experiment: the
// certified bounds are the same rationals.
TEST_F(SeveralRecords, OneRecordIsTheOneRecordTheorem) {
  const std::string a = write_record("a.csv", output_record(model, input_record(30, 2, Rational(1)), one_tap(Rational(1, 10)), Rational(1, 100)));
  std::vector<DataReference> refs;
  const Experiment<Rational> one = stacked({a}, refs);
  EXPECT_TRUE(one.records.empty());
  const Experiment<Rational> plain = make_experiment<Rational>(read_data_table(a).table, model.columns);
  const std::unique_ptr<SdpSolver> solver = make_solver("csdp");
  const CertifyOptions o = gen::certify_options(gen::weighted_objective(0.5), a);
  const CertifiedBounds x = certify_fixed_model(model, one, o, *solver), y = certify_fixed_model(model, plain, o, *solver);
  ASSERT_TRUE(x.verified() && y.verified());
  EXPECT_EQ(x.delta2, y.delta2);
  EXPECT_EQ(x.dmax2, y.dmax2);
  EXPECT_EQ(x.lower.value, y.lower.value);
}

}  // namespace
}  // namespace lpvid
