// The judgement of `lpvid jobs merge` as a library call (jobs/merge.h): one
// typed verdict for the plan's claims. Known answers by construction: on
// crafted window results the verdict follows from the statuses alone (one
// invalidated claim invalidates, else one missing or refused claim leaves it
// not verified); on a record whose window 0 is explained by the true model
// and window 1 is not (support/jobs_windows.h), a missing, an unreadable
// certificate and a changed data or model file each give their own verdict.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/exit_codes.h"
#include "jobs/merge.h"
#include "support/jobs_windows.h"

namespace lpvid {
namespace {

using gen::JobsMerge;
using jobs::MergedWindow;
using jobs::MergeVerdict;
using jobs::WindowResult;
using jobs::WindowStatus;

MergedWindow window_of(WindowStatus s, long begin = 0, long end = 10, Rational dmax2 = Rational(0)) {
  MergedWindow m;
  m.w.file_begin = begin;
  m.w.file_end = end;
  m.r.status = s;
  m.r.dmax2 = dmax2;
  return m;
}

WindowResult joint_of(WindowStatus s) {
  WindowResult r;
  r.status = s;
  return r;
}

TEST(MergeVerdict, FollowsFromTheStatusesOfWindowsAndJointClaim) {
  using S = WindowStatus;
  const auto verdict = [](std::vector<S> ws, std::optional<S> joint = std::nullopt) {
    std::vector<MergedWindow> windows;
    for (S s : ws) windows.push_back(window_of(s));
    return jobs::merge_verdict(windows, joint ? std::optional<WindowResult>(joint_of(*joint)) : std::nullopt);
  };
  EXPECT_EQ(verdict({S::kVerified, S::kVerified}), MergeVerdict::kConsistent);
  EXPECT_EQ(verdict({S::kVerified, S::kInvalidated}), MergeVerdict::kInvalidated);
  // an invalidated window decides even beside a missing one
  EXPECT_EQ(verdict({S::kMissing, S::kInvalidated}), MergeVerdict::kInvalidated);
  EXPECT_EQ(verdict({S::kVerified, S::kMissing}), MergeVerdict::kNotVerified);
  EXPECT_EQ(verdict({S::kRefused, S::kVerified}), MergeVerdict::kNotVerified);
  // the joint claim counts as one more claim
  EXPECT_EQ(verdict({S::kVerified, S::kVerified}, S::kInvalidated), MergeVerdict::kInvalidated);
  EXPECT_EQ(verdict({S::kVerified, S::kVerified}, S::kRefused), MergeVerdict::kNotVerified);
  EXPECT_EQ(verdict({S::kVerified, S::kVerified}, S::kVerified), MergeVerdict::kConsistent);
  EXPECT_STREQ(jobs::to_string(MergeVerdict::kNotVerified), "not_verified");
}

TEST(MergeVerdict, SummaryWeighsEachVerifiedWindowByItsRows) {
  // 60 rows at dmax^2 = 1/4 and 40 rows at 1/100: (15 + 2/5) / 100 = 77/500;
  // the invalidated window's numbers do not count
  const std::vector<MergedWindow> windows = {window_of(WindowStatus::kVerified, 0, 60, Rational(1, 4)),
                                             window_of(WindowStatus::kVerified, 60, 100, Rational(1, 100)),
                                             window_of(WindowStatus::kInvalidated, 100, 200, Rational(9))};
  const jobs::VerifiedSummary s = jobs::verified_summary(windows);
  EXPECT_EQ(s.samples, 100);
  EXPECT_EQ(s.record_dmax2, Rational(77, 500));
  EXPECT_EQ(s.worst_dmax2, Rational(1, 4));
}

TEST_F(JobsMerge, MergeJobsGivesEachCaseItsTypedVerdict) {
  plan_and_run("--delta 0.45 --dmax 0.05");
  const jobs::MergeResult honest = jobs::merge_jobs(file("J"));
  ASSERT_EQ(honest.windows.size(), 2u);
  EXPECT_EQ(honest.windows[0].r.status, WindowStatus::kVerified) << honest.windows[0].r.reason;
  EXPECT_EQ(honest.windows[1].r.status, WindowStatus::kInvalidated) << honest.windows[1].r.reason;
  EXPECT_EQ(honest.verdict, MergeVerdict::kInvalidated);

  // window 1 left no certificate: window 0 alone is verified, nothing invalidates
  std::filesystem::remove(file("J/w00001.cert.json"));
  const jobs::MergeResult missing = jobs::merge_jobs(file("J"));
  EXPECT_EQ(missing.windows[1].r.status, WindowStatus::kMissing);
  EXPECT_EQ(missing.verdict, MergeVerdict::kNotVerified);
  int code = -1;
  const nlohmann::json report = merge(&code);
  EXPECT_EQ(code, kExitNotVerified) << output();
  EXPECT_EQ(report["counts"]["missing"], 1);

  // window 0's certificate does not pass (not a certificate at all)
  write_text(file("J/w00000.cert.json"), "{\"format\": \"lpvid-certificate/1\"}\n");
  const jobs::MergeResult failing = jobs::merge_jobs(file("J"));
  EXPECT_EQ(failing.windows[0].r.status, WindowStatus::kRefused);
  EXPECT_EQ(failing.verdict, MergeVerdict::kNotVerified);
  EXPECT_EQ(failing.counts.verified, 0u);

  // the model, then the data, changed since the plan: nothing judged
  write_text(file("true.json"), read_text(file("true.json")) + "\n");
  const jobs::MergeResult model_changed = jobs::merge_jobs(file("J"));
  EXPECT_EQ(model_changed.verdict, MergeVerdict::kModelChanged);
  EXPECT_TRUE(model_changed.windows.empty());
  write_text(file("d.csv"), read_text(file("d.csv")) + "\n");
  const jobs::MergeResult data_changed = jobs::merge_jobs(file("J"));
  EXPECT_EQ(data_changed.verdict, MergeVerdict::kDataChanged);
  EXPECT_NE(data_changed.changed.find("d.csv: the data changed"), std::string::npos) << data_changed.changed;
}

}  // namespace
}  // namespace lpvid
