// lpvid jobs merge trusts no job: each scenario runs the plan's jobs
// honestly, then one job misbehaves (other bounds, another x0, a lower end
// of another objective, an unreadable file) and merge must refuse exactly
// that window, with the reason, and still report the others.
//
// Known answers by construction: the data come from the true Example 1
// system with noise of RMS 0.01, and rows 60–119 of y1 are shifted by 0.3.
// Window 0 (rows 0–59) is then explained by the true model within
// (δ, d_max) = (0.45, 0.05); window 1 is not, and the honest merge
// must say so (checked first in every scenario, so a wrong premise fails
// the test instead of passing it vacuously).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>
#include <vector>

#include "support/jobs_windows.h"

namespace lpvid {
namespace {

using gen::JobsMerge;

struct Scenario {
  const char* name;
  const char* objective;
  std::vector<const char*> honest;  ///< the windows' statuses before the job misbehaves
  std::function<void(JobsMerge&)> tamper;
  int window;           ///< the window that must be refused
  const char* reason;   ///< a part of its reason
  const char* other;    ///< the other window's status after
  int exit_code;
};

TEST_F(JobsMerge, EveryMisbehavingJobIsRefusedWithItsReasonAndTheRestIsReported) {
  const std::vector<Scenario> scenarios = {
      // today: "verified 2 (of 2)", exit 0
      {"consistent at a larger (delta, dmax)", "--delta 0.45 --dmax 0.05", {"verified", "invalidated"},
       [](JobsMerge& t) { EXPECT_EQ(t.rerun_job(1, {{"--delta '0.45' --dmax '0.05'", "--delta '2' --dmax '0.5'"}}), 0); },
       1, "claims \"consistent\" at delta^2 = 4, the plan's is 81/400", "verified", 4},
      // today: INVALIDATED on a window that is consistent at the plan
      {"invalidated at a smaller dmax", "--delta 0.45 --dmax 0.05", {"verified", "invalidated"},
       [](JobsMerge& t) { EXPECT_EQ(t.rerun_job(0, {{"--dmax '0.05'", "--dmax '0.0001'"}}), 1); },
       0, "claims \"invalidated\" at dmax^2 = 1/100000000, the plan's is 1/400", "invalidated", 1},
      // today: a δ² lower bound counted as the window's d_max² lower end
      {"a lower end from --dmax", "--delta 0.45", {"verified", "verified"},
       [](JobsMerge& t) {
         EXPECT_EQ(t.rerun_job(0, {{"--delta '0.45'", "--dmax '0.001'"}, {"w00000.cert.json", "x.cert.json"}}), 0);
         std::filesystem::copy_file(t.file("J/x.cert.lower.json"), t.file("J/w00000.cert.lower.json"),
                                    std::filesystem::copy_options::overwrite_existing);
       },
       0, "lower end: the lower-end file bounds delta^2 (objective min_delta), the plan's objective is dmax^2", "verified", 4},
      // today: "largest certified lower end ... " of the x0 = 25 model
      {"x0 edited to 25", "--delta 0.45", {"verified", "verified"},
       [](JobsMerge& t) {
         const std::string m = t.file("J/w00001.model.json");
         nlohmann::json j = read_json(m);
         j["x0"][0] = "25";
         write_text(m, j.dump());
         EXPECT_EQ(t.rerun_job(1, {}), 0);
       },
       1, "certifies the model with x0 = [25 ", "verified", 4},
      // today: exit 3, no report
      {"an unreadable certificate", "--delta 0.45 --dmax 0.05", {"verified", "invalidated"},
       [](JobsMerge& t) {
         std::filesystem::remove(t.file("J/w00000.cert.json"));
         std::filesystem::create_symlink("w00000.cert.json", t.file("J/w00000.cert.json"));
       },
       0, "unreadable: ", "invalidated", 1},
  };
  for (const Scenario& s : scenarios) {
    SCOPED_TRACE(s.name);
    TearDown();
    SetUp();
    plan_and_run(s.objective);
    int code = 0;
    nlohmann::json m = merge(&code);
    ASSERT_EQ(m["windows"].size(), 2u) << output();
    for (int k = 0; k < 2; ++k) ASSERT_EQ(m["windows"][k]["status"], s.honest[k]) << output();
    s.tamper(*this);
    std::filesystem::remove(file("J/merged.json"));
    m = merge(&code);
    EXPECT_EQ(code, s.exit_code) << output();
    ASSERT_EQ(m["windows"].size(), 2u) << output();
    const auto& w = m["windows"][s.window];
    EXPECT_EQ(w["status"], "refused") << w.dump();
    EXPECT_NE(w.value("reason", "").find(s.reason), std::string::npos) << w.dump();
    EXPECT_EQ(m["windows"][1 - s.window]["status"], s.other) << m.dump();
    EXPECT_EQ(m["counts"]["refused"], 1) << m.dump();
    EXPECT_NE(output().find("refused 1 (of 2)"), std::string::npos) << output();
  }
}

}  // namespace
}  // namespace lpvid
