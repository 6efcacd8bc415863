// The judging of `lpvid jobs merge` as a library (jobs/window_check.h):
// compared as typed values, a genuine window certificate matches its plan
// and each single change of what it claims does not.
#include <gtest/gtest.h>

#include <functional>

#include "jobs/plan.h"
#include "jobs/window_check.h"
#include "model/model_file.h"
#include "support/jobs_windows.h"
#include "verify/certificate/certificate_file.h"

namespace lpvid {
namespace {

using gen::JobsMerge;

TEST_F(JobsMerge, PlanMismatchNamesEachChangedValue) {
  plan_and_run("--delta 0.45 --dmax 0.05");
  const jobs::JobPlan plan = jobs::read_plan(file("J"));
  const jobs::PlannedClaim p = jobs::planned_claim(plan);
  const jobs::JobWindow& w = plan.windows[0];
  const LpvModel<Rational> model = jobs::window_model(read_model_file<Rational>(plan.model_path), w);
  const Certificate genuine = read_certificate(file("J/w00000.cert.json"));
  ASSERT_EQ(genuine.claim, CertificateClaim::kConsistent);
  EXPECT_EQ(jobs::plan_mismatch(p, w, model, genuine, jobs::WindowFile::kCertificate), "");
  const std::vector<std::pair<std::function<void(Certificate&)>, std::string>> changes = {
      {[](Certificate& c) { c.delta2 = Rational(4); }, "delta^2 = 4"},
      {[](Certificate& c) { c.dmax2 = Rational(1, 4); }, "dmax^2 = 1/4"},
      {[](Certificate& c) { c.model.x0(0) = Rational(25); }, "x0 = [25 "},
      {[](Certificate& c) { c.model.x0(1) = Rational(-1, 3); }, "x0 = [0 -1/3]"},
      {[](Certificate& c) { c.records.front().data.row_end = 59; }, "rows 0:59"},
      {[](Certificate& c) {
         std::string& sha = c.records.front().data.sha256;
         sha[0] = sha[0] == '0' ? '1' : '0';
       },
       "other data"},
      {[](Certificate& c) { c.mode = ToeplitzMode::kPaper; }, "toeplitz mode paper"},
      {[](Certificate& c) { c.claim = CertificateClaim::kNotAWitness; }, "not_a_witness"},
      // class claims are not window claims, whatever they prove (an allow-list)
      {[](Certificate& c) { c.claim = CertificateClaim::kClassInvalidated; }, "\"class_invalidated\" certificate in place"},
      {[](Certificate& c) { c.claim = CertificateClaim::kClassLowerBound; }, "\"class_lower_bound\" certificate in place"},
      {[](Certificate& c) { c.claim = CertificateClaim::kLowerBound; }, "\"lower_bound\" certificate in place"},
  };
  for (const auto& [change, words] : changes) {
    Certificate c = genuine;
    change(c);
    const std::string why = jobs::plan_mismatch(p, w, model, c, jobs::WindowFile::kCertificate);
    EXPECT_NE(why.find(words), std::string::npos) << words << " / " << why;
  }
  // as a lower end, a consistency claim is not one
  EXPECT_NE(jobs::plan_mismatch(p, w, model, genuine, jobs::WindowFile::kLowerEnd), "");
}

TEST_F(JobsMerge, APlanOfAnOlderLpvidIsRefusedNotMisread) {
  plan_and_run("--delta 0.45 --dmax 0.05");
  nlohmann::json plan = read_json(file("J/plan.json"));
  plan["windows"][0].erase("x0");
  write_text(file("J/plan.json"), plan.dump());
  int code = 0;
  merge(&code);
  EXPECT_EQ(code, 2) << output();
  EXPECT_NE(output().find("windows[0].x0: missing"), std::string::npos) << output();
}

}  // namespace
}  // namespace lpvid
