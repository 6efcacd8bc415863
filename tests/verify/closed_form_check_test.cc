// The closed forms of verify/certificate/closed_form_check.h, on hand-made
// certificates. Known answers by construction (tests/support/noise_only_case.h):
// y = ŷ + e for a known diagonal model, so at δ = 0 the least d_max² is
// ‖e‖²/(n·ny) exactly. The claim at that value holds; every tampered copy —
// the claim 10⁻⁴⁰ above it, δ² ≠ 0, another objective, an invalidation at
// equality, a changed data byte, a lower end 0 of form "nonnegative" raised
// to 10⁻⁴⁰ — is refused. One record, two records (pooled over all samples),
// MIMO, and paper mode.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/file_io.h"
#include "core/input_error.h"
#include "data/data_reference.h"
#include "model/model_file.h"
#include "support/noise_only_case.h"
#include "support/scratch_dir.h"
#include "verify/certificate/certificate_check.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

const Rational kTiny = Rational(1) / rational_from_text("1e40");

class ClosedFormCheck : public ::testing::Test {
 protected:
  gen::ScratchDir dir{"closed-form-check"};
  std::vector<Rational> a{Rational(1, 2)};  // SISO: x⁺ = x/2 + u
  Rational exact;                           // ‖e‖²/(n·ny), by construction
  std::vector<DataReference> refs;

  /// Writes the model and one record per entry of `lengths`; `exact` is the pooled value.
  void make(const std::vector<Rational>& diagonal, const std::vector<long>& lengths) {
    a = diagonal;
    std::vector<std::string> text;
    for (const Rational& v : a) text.push_back(exact_decimal_or_fraction(v));
    write_text_file(dir.file("model.json"), gen::diagonal_model_json(text), "model");
    Rational energy(0);
    long samples = 0;
    refs.clear();
    for (size_t k = 0; k < lengths.size(); ++k) {
      const gen::NoiseOnlyRecord r = gen::noise_only_record(a, lengths[k], 7 + static_cast<long>(k));
      const std::string path = dir.file("data" + std::to_string(k) + ".csv");
      write_text_file(path, r.csv, "data");
      ASSERT_EQ(gen::residual_energy_of_text(r.csv, a), r.energy);  // the text holds y = ŷ + e exactly
      energy += r.energy;
      samples += r.samples;
      refs.push_back(read_data_table(path).reference);
    }
    exact = energy / Rational(samples * static_cast<long>(a.size()));
    ASSERT_GT(exact, 0);
  }
  /// A closed-form claim on the records: "lower_bound" of d_max² at δ² = 0, or "invalidated" at (0, dmax2).
  Certificate claim(CertificateClaim kind, const Rational& value, CertificateForm form = CertificateForm::kZeroDelta) {
    Certificate c;
    set_record_references(c, refs);
    c.model = read_model_file<Rational>(dir.file("model.json"));
    c.claim = kind;
    c.form = form;
    c.delta2 = Rational(0);
    if (kind == CertificateClaim::kLowerBound) {
      c.objective = DualClaim::kMinDmax2;
      c.lower_bound = value;
    } else {
      c.objective = DualClaim::kInvalidated;
      c.dmax2 = value;
    }
    return c;
  }
  /// Written as a file, read back and checked from the data files (placed beside it).
  CertificateVerdict check(const Certificate& c) {
    const std::string path = dir.file("c.cert.json");
    write_certificate(path, placed_at(c, path));
    return check_certificate_file(path);
  }
};

TEST_F(ClosedFormCheck, TheLeastDmaxAtDeltaZeroIsExactlyTheResidualEnergy) {
  make({Rational(1, 2)}, {30});
  const CertificateVerdict v = check(claim(CertificateClaim::kLowerBound, exact));
  EXPECT_TRUE(v.holds) << v.reason;
  EXPECT_EQ(v.claim_text.rfind("lower_bound", 0), 0u) << v.claim_text;
  EXPECT_TRUE(check(claim(CertificateClaim::kLowerBound, exact - kTiny)).holds);
  EXPECT_TRUE(check(claim(CertificateClaim::kLowerBound, Rational(-1))).holds);  // below: true, if useless
  const CertificateVerdict above = check(claim(CertificateClaim::kLowerBound, exact + kTiny));
  EXPECT_FALSE(above.holds);
  EXPECT_NE(above.reason.find("exceeds ||r||^2"), std::string::npos) << above.reason;
}

TEST_F(ClosedFormCheck, InvalidatedOnlyStrictlyBelowTheResidualEnergy) {
  make({Rational(1, 2)}, {30});
  EXPECT_TRUE(check(claim(CertificateClaim::kInvalidated, exact - kTiny)).holds);
  const CertificateVerdict tie = check(claim(CertificateClaim::kInvalidated, exact));  // n·ny·d_max² = ‖r‖²: Δ = 0 is consistent
  EXPECT_FALSE(tie.holds);
  EXPECT_NE(tie.reason.find("is not below"), std::string::npos) << tie.reason;
  EXPECT_FALSE(check(claim(CertificateClaim::kInvalidated, exact + kTiny)).holds);
}

TEST_F(ClosedFormCheck, OnlyDeltaZeroAndTheDmaxObjective) {
  make({Rational(1, 2)}, {30});
  Certificate c = claim(CertificateClaim::kLowerBound, exact);
  c.delta2 = kTiny;  // at δ² > 0, Δ ≠ 0 may lower d_max²: the closed form says nothing
  EXPECT_FALSE(check(c).holds);
  Certificate inv = claim(CertificateClaim::kInvalidated, exact - kTiny);
  inv.delta2 = kTiny;
  EXPECT_FALSE(check(inv).holds);
  for (const DualClaim other : {DualClaim::kMinDelta2, DualClaim::kWeighted}) {
    Certificate o = claim(CertificateClaim::kLowerBound, exact);
    o.objective = other;
    o.dmax2 = exact;
    o.lambda = Rational(1, 2);
    const CertificateVerdict v = check(o);
    EXPECT_FALSE(v.holds);
    EXPECT_NE(v.reason.find("decides only dmax^2"), std::string::npos) << v.reason;
  }
}

TEST_F(ClosedFormCheck, AChangedDataByteIsRefused) {
  make({Rational(1, 2)}, {30});
  const Certificate c = claim(CertificateClaim::kLowerBound, exact);
  ASSERT_TRUE(check(c).holds);
  // The first noise value halved (y moves towards ŷ): a new file, and ‖r‖² falls below the claim.
  const std::string path = dir.file("data0.csv");
  std::string text = read_text_file(path);
  const gen::NoiseOnlyRecord r = gen::noise_only_record(a, 30, 7);
  ASSERT_EQ(text, r.csv);
  const size_t line = text.find('\n') + 1, comma = text.find(',', line), end = text.find('\n', line);
  const Rational y0 = rational_from_text(text.substr(comma + 1, end - comma - 1));  // ŷ_0 = 0: y_0 = e_0
  text.replace(comma + 1, end - comma - 1, exact_decimal_or_fraction(y0 / Rational(2)));
  write_text_file(path, text, "data");
  EXPECT_FALSE(check_certificate_file(dir.file("c.cert.json")).holds);  // the sha256 differs
  Certificate rehashed = c;
  set_record_references(rehashed, {read_data_table(path).reference});
  const CertificateVerdict v = check(rehashed);
  EXPECT_FALSE(v.holds);
  EXPECT_NE(v.reason.find("exceeds ||r||^2"), std::string::npos) << v.reason;
  rehashed.lower_bound = exact - y0 * y0 * Rational(3, 4) / Rational(30);  // the new ‖r‖²/n exactly
  EXPECT_TRUE(check(rehashed).holds);
  rehashed.lower_bound += kTiny;
  EXPECT_FALSE(check(rehashed).holds);
}

TEST_F(ClosedFormCheck, SeveralRecordsPoolEverySample) {
  make({Rational(1, 2)}, {30, 24});
  ASSERT_EQ(refs.size(), 2u);
  EXPECT_TRUE(check(claim(CertificateClaim::kLowerBound, exact)).holds);
  EXPECT_FALSE(check(claim(CertificateClaim::kLowerBound, exact + kTiny)).holds);
  EXPECT_TRUE(check(claim(CertificateClaim::kInvalidated, exact - kTiny)).holds);
  EXPECT_FALSE(check(claim(CertificateClaim::kInvalidated, exact)).holds);
}

TEST_F(ClosedFormCheck, MimoSumsEveryOutput) {
  make({Rational(1, 2), Rational(-1, 2)}, {30});
  EXPECT_TRUE(check(claim(CertificateClaim::kLowerBound, exact)).holds);
  EXPECT_FALSE(check(claim(CertificateClaim::kLowerBound, exact + kTiny)).holds);
  EXPECT_FALSE(check(claim(CertificateClaim::kInvalidated, exact)).holds);
  make({Rational(1, 2), Rational(-1, 2)}, {30, 24});
  EXPECT_TRUE(check(claim(CertificateClaim::kLowerBound, exact)).holds);
  EXPECT_FALSE(check(claim(CertificateClaim::kLowerBound, exact + kTiny)).holds);
}

TEST_F(ClosedFormCheck, PaperModeToo) {
  make({Rational(1, 2)}, {30});
  Certificate c = claim(CertificateClaim::kLowerBound, exact);
  c.mode = ToeplitzMode::kPaper;
  EXPECT_TRUE(check(c).holds);
  c.lower_bound = exact + kTiny;
  EXPECT_FALSE(check(c).holds);
}

TEST_F(ClosedFormCheck, NonnegativeProvesOnlyLowerEndsAtMostZero) {
  make({Rational(1, 2)}, {30});
  for (const DualClaim objective : {DualClaim::kMinDelta2, DualClaim::kMinDmax2, DualClaim::kWeighted}) {
    Certificate c = claim(CertificateClaim::kLowerBound, Rational(0), CertificateForm::kNonnegative);
    c.objective = objective;
    c.delta2 = objective == DualClaim::kMinDmax2 ? Rational(1, 4) : Rational(0);
    c.dmax2 = objective == DualClaim::kMinDelta2 ? Rational(1, 4) : Rational(0);
    c.lambda = Rational(1, 2);
    EXPECT_TRUE(check(c).holds);
    c.lower_bound = kTiny;
    EXPECT_FALSE(check(c).holds);
  }
  const CertificateVerdict inv = check(claim(CertificateClaim::kInvalidated, Rational(0), CertificateForm::kNonnegative));
  EXPECT_FALSE(inv.holds);
  EXPECT_NE(inv.reason.find("never an invalidation"), std::string::npos) << inv.reason;
}

TEST_F(ClosedFormCheck, TheFileCarriesNoDualPoint) {
  make({Rational(1, 2)}, {30});
  const std::string text = certificate_json(placed_at(claim(CertificateClaim::kLowerBound, exact), dir.file("c.json")));
  EXPECT_NE(text.find("\"form\": \"zero_delta\""), std::string::npos);
  EXPECT_EQ(text.find("\"dual\""), std::string::npos);
  const Certificate back = parse_certificate(text, "c.json");
  EXPECT_EQ(back.form, CertificateForm::kZeroDelta);
  EXPECT_EQ(back.lower_bound, exact);
  std::string with_dual = text;
  with_dual.insert(with_dual.find("\"form\""), "\"dual\": {\"horizon\": 1, \"sigma\": 1, \"g\": [[0]]},\n  ");
  EXPECT_THROW(parse_certificate(with_dual, "c.json"), InputError);
}

// The primal point beside it: Δ = 0 as no taps, checked at δ² = 0 (T_Δ = 0);
// one tap at δ² = 0 makes (C1) fail.
TEST_F(ClosedFormCheck, DeltaZeroAsNoTaps) {
  make({Rational(1, 2)}, {30});
  Certificate c = claim(CertificateClaim::kConsistent, Rational(0));
  c.form = CertificateForm::kDelta;
  c.taps = Mat<Rational>(0, 1);
  c.horizon = 30;
  c.dmax2 = exact;
  const CertificateVerdict v = check(c);
  EXPECT_TRUE(v.holds) << v.reason;
  EXPECT_NE(v.details.find("T_Delta = 0"), std::string::npos) << v.details;
  c.dmax2 = exact - kTiny;
  EXPECT_FALSE(check(c).holds);
  c.dmax2 = exact;
  c.taps = Mat<Rational>::Constant(1, 1, Rational(1, 1000));
  EXPECT_FALSE(check(c).holds);
}

}  // namespace
}  // namespace lpvid
