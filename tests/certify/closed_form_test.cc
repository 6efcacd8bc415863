// Theorem 2.1 in closed form (certify/closed_form.h): at δ = 0, Δ = 0 and
// d = r, so the least d_max² is ‖r‖²/(n·ny), exactly, with no solve. Known
// answers by construction (tests/support/noise_only_case.h): y = ŷ + e for a
// known diagonal model, and ‖r‖² is recomputed here from the data text with
// the test's own exact simulation, never through lpvid's. The interval's ends
// are equal, the fixed bounds are decided on either side of the exact value,
// several records pool every sample, MIMO every output; the cases whose
// optimum is 0 get the lower end 0; a record whose exact value is too long
// has its ends rounded outward; other objectives still solve.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "certify/certificate_files.h"
#include "certify/certify.h"
#include "certify/closed_form.h"
#include "core/file_io.h"
#include "data/data_reference.h"
#include "data/experiment_builder.h"
#include "model/model_file.h"
#include "solvers/solver_factory.h"
#include "support/gen_identify.h"
#include "support/noise_only_case.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"

namespace lpvid {
namespace {

class ClosedForm : public ::testing::Test {
 protected:
  gen::ScratchDir dir{"closed-form"};
  std::unique_ptr<SdpSolver> solver = make_solver("csdp");
  std::vector<Rational> a;
  LpvModel<Rational> model;
  Experiment<Rational> exp;
  CertifyOptions options;
  Rational exact;  ///< ‖r‖²/(n·ny) from the data text

  /// The model with diagonal `diagonal` and one record per entry of `lengths`
  /// (noise-free when `noise` is false); `exact` recomputed from the texts.
  void make(const std::vector<Rational>& diagonal, const std::vector<long>& lengths, bool noise = true) {
    a = diagonal;
    std::vector<std::string> text;
    for (const Rational& v : a) text.push_back(exact_decimal_or_fraction(v));
    write_text_file(dir.file("model.json"), gen::diagonal_model_json(text), "model");
    model = read_model_file<Rational>(dir.file("model.json"));
    std::vector<Experiment<Rational>> parts;
    options.records.clear();
    Rational energy(0);
    long samples = 0;
    for (size_t k = 0; k < lengths.size(); ++k) {
      const gen::NoiseOnlyRecord r = gen::noise_only_record(a, lengths[k], 11 + static_cast<long>(k), noise);
      const std::string path = dir.file("data" + std::to_string(k) + ".csv");
      write_text_file(path, r.csv, "data");
      energy += gen::residual_energy_of_text(r.csv, a);
      samples += r.samples;
      const DataTable t = read_data_table(path);
      options.records.push_back(t.reference);
      parts.push_back(make_experiment<Rational>(t.table, model.columns));
    }
    exp = stack_records(parts);
    exact = energy / Rational(samples * static_cast<long>(a.size()));
  }
  CertifiedBounds certify(const BoundObjective& objective, ToeplitzMode mode = ToeplitzMode::kSignal) {
    options.objective = objective;
    return certify_fixed(model, exp, mode, options, *solver);
  }
  /// Both certificates written and checked from their files.
  void expect_files_hold(const CertifiedBounds& b) {
    const CertificateFiles files = write_certificates(b, dir.file("c.cert.json"));
    ASSERT_FALSE(files.certificate.empty());
    EXPECT_TRUE(check_certificate_file(files.certificate).holds);
    if (!files.lower.empty()) {
      EXPECT_TRUE(check_certificate_file(files.lower).holds);
    }
  }
};

TEST_F(ClosedForm, TheLeastDmaxAtDeltaZeroIsTheResidualEnergyExactly) {
  make({Rational(1, 2)}, {30});
  const CertifiedBounds b = certify(gen::min_dmax_objective(0.0));
  ASSERT_TRUE(b.verified()) << b.reason;
  ASSERT_TRUE(b.lower.verified()) << b.lower.reason;
  EXPECT_EQ(b.closed_form, "closed form (delta = 0)");
  EXPECT_FALSE(b.solve_status.has_value());  // no solve
  EXPECT_EQ(b.delta2, 0);
  EXPECT_EQ(b.dmax2, exact);
  EXPECT_EQ(b.upper, exact);
  EXPECT_EQ(b.lower.value, exact);
  EXPECT_EQ(relative_gap(b), 0.0);
  ASSERT_TRUE(b.certificate && b.lower.certificate);
  EXPECT_EQ(b.certificate->form, CertificateForm::kDelta);
  EXPECT_EQ(b.certificate->taps.rows(), 0);
  EXPECT_EQ(b.lower.certificate->form, CertificateForm::kZeroDelta);
  EXPECT_EQ(b.lower.certificate->lower_bound, exact);
  expect_files_hold(b);
}

TEST_F(ClosedForm, FixedBoundsAtDeltaZeroAreDecidedOnEitherSide) {
  make({Rational(1, 2)}, {30});
  const double root = std::sqrt(nearest_double(exact));
  const double above = std::nextafter(root, 1.0) * (1 + 1e-12), below = root * (1 - 1e-12);
  BoundObjective consistent = gen::feasibility_objective(0.0, above), invalid = gen::feasibility_objective(0.0, below);
  ASSERT_GE(consistent.dmax.exact * consistent.dmax.exact, exact);
  ASSERT_LT(invalid.dmax.exact * invalid.dmax.exact, exact);
  const CertifiedBounds yes = certify(consistent);
  EXPECT_EQ(yes.outcome, CertifyOutcome::kVerified) << yes.reason;
  EXPECT_EQ(yes.dmax2, consistent.dmax.exact * consistent.dmax.exact);
  expect_files_hold(yes);
  const CertifiedBounds no = certify(invalid);
  EXPECT_EQ(no.outcome, CertifyOutcome::kInvalidated) << no.reason;
  ASSERT_TRUE(no.certificate.has_value());
  EXPECT_EQ(no.certificate->claim, CertificateClaim::kInvalidated);
  EXPECT_EQ(no.certificate->form, CertificateForm::kZeroDelta);
  expect_files_hold(no);
}

TEST_F(ClosedForm, SeveralRecordsAndMimoPoolEverySampleAndOutput) {
  for (const std::vector<Rational>& diagonal : {std::vector<Rational>{Rational(1, 2)},
                                                std::vector<Rational>{Rational(1, 2), Rational(-1, 2)}}) {
    make(diagonal, {30, 24});
    const CertifiedBounds b = certify(gen::min_dmax_objective(0.0));
    ASSERT_TRUE(b.verified() && b.lower.verified()) << b.reason << b.lower.reason;
    EXPECT_EQ(b.dmax2, exact);
    EXPECT_EQ(b.lower.value, exact);
    EXPECT_EQ(b.lower.certificate->records.size(), 2u);
    expect_files_hold(b);
  }
}

TEST_F(ClosedForm, PaperModeWithWZero) {
  make({Rational(1, 2), Rational(-1, 2)}, {30});
  const CertifiedBounds b = certify(gen::min_dmax_objective(0.0), ToeplitzMode::kPaper);
  ASSERT_TRUE(b.verified() && b.lower.verified()) << b.reason << b.lower.reason;
  EXPECT_EQ(b.dmax2, exact);
  EXPECT_EQ(b.lower.value, exact);
  EXPECT_EQ(b.certificate->form, CertificateForm::kW);
  EXPECT_TRUE(b.certificate->w.isZero());
  expect_files_hold(b);
}

TEST_F(ClosedForm, ObjectivesWhoseOptimumIsZeroGetTheLowerEndZero) {
  make({Rational(1, 2)}, {30});
  const double enough = 2 * std::sqrt(nearest_double(exact));
  for (const BoundObjective& objective : {gen::min_delta_objective(enough), gen::weighted_objective(1.0)}) {
    const CertifiedBounds b = certify(objective);
    ASSERT_TRUE(b.verified() && b.lower.verified()) << b.reason << b.lower.reason;
    EXPECT_EQ(b.closed_form, "closed form (objective 0 at Delta = 0)");
    EXPECT_EQ(b.upper, 0);
    EXPECT_EQ(b.lower.value, 0);
    EXPECT_EQ(b.lower.certificate->form, CertificateForm::kNonnegative);
    expect_files_hold(b);
  }
  make({Rational(1, 2)}, {30}, false);  // y = ŷ: r = 0
  ASSERT_EQ(exact, 0);
  const CertifiedBounds b = certify(gen::min_dmax_objective(0.3));
  ASSERT_TRUE(b.verified() && b.lower.verified());
  EXPECT_EQ(b.closed_form, "closed form (r = 0)");
  EXPECT_EQ(b.dmax2, 0);
  EXPECT_EQ(b.lower.value, 0);
  EXPECT_EQ(certify(gen::feasibility_objective(0.3, 0.0)).outcome, CertifyOutcome::kVerified);
  // (0, 0) with r = 0: n·ny·d_max² = ‖r‖² = 0, a tie, consistent, and said so
  const CertifiedBounds tie = certify(gen::feasibility_objective(0.0, 0.0));
  ASSERT_EQ(tie.outcome, CertifyOutcome::kVerified) << tie.reason;
  ASSERT_TRUE(tie.certificate->info.contains("note"));
  EXPECT_NE(tie.certificate->info["note"].get<std::string>().find("a tie"), std::string::npos);
  expect_files_hold(tie);
}

TEST_F(ClosedForm, OtherObjectivesStillSolve) {
  make({Rational(1, 2)}, {30});
  const double scarce = 0.5 * std::sqrt(nearest_double(exact));
  for (const BoundObjective& objective :
       {gen::min_dmax_objective(0.1), gen::weighted_objective(0.5), gen::min_delta_objective(scarce)}) {
    const CertifiedBounds b = certify(objective);
    EXPECT_TRUE(b.closed_form.empty()) << b.closed_form;
    EXPECT_TRUE(b.solve_status.has_value());
  }
}

// 400 samples with 16-digit model numbers: the exact ‖r‖²/(n·ny) has more
// than kMaxExactDigits digits, so the ends are rounded outward (30 digits).
TEST_F(ClosedForm, ALongRecordRoundsTheEndsOutward) {
  const std::string a_text = "0.5123456789012345";
  a = {rational_from_text(a_text)};
  write_text_file(dir.file("model.json"), gen::diagonal_model_json({a_text}), "model");
  model = read_model_file<Rational>(dir.file("model.json"));
  std::string csv = "u1,y1\n";
  for (long k = 0, s = 5; k < 400; ++k) {
    s = (s * 1103515245 + 12345) % 2147483648;
    csv += std::to_string((s / 65536) % 19 - 9) + "." + std::to_string(1000 + s % 9000) + "," +
           std::to_string((s / 1024) % 7 - 3) + "." + std::to_string(1000 + s % 8999) + "\n";
  }
  write_text_file(dir.file("long.csv"), csv, "data");
  const DataTable t = read_data_table(dir.file("long.csv"));
  options.records = {t.reference};
  exp = make_experiment<Rational>(t.table, model.columns);
  exact = gen::residual_energy_of_text(csv, a) / Rational(400);
  const CertifiedBounds b = certify(gen::min_dmax_objective(0.0));
  ASSERT_TRUE(b.verified() && b.lower.verified()) << b.reason << b.lower.reason;
  EXPECT_LE(b.lower.value, exact);
  EXPECT_GE(b.upper, exact);
  EXPECT_LT(b.lower.value, b.upper);
  EXPECT_LT(relative_gap(b), 1e-28);
  ASSERT_TRUE(b.lower.certificate->info.contains("note"));
  EXPECT_NE(b.lower.certificate->info["note"].get<std::string>().find("rounded outward"), std::string::npos);
  expect_files_hold(b);
}

}  // namespace
}  // namespace lpvid
