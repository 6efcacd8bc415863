// The progress lines of a long check (verify/psd/check_progress.h): a step
// estimated at kAnnouncedWork or more is announced under lpvid-verify's
// limits; a small step within 5 s of the last line is not; an unlimited
// check (the library's own callers) never talks.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/progress_sink.h"
#include "verify/psd/check_progress.h"

namespace lpvid {
namespace {

/// The progress lines written while `body` runs.
template <class Body>
std::vector<std::string> lines_of(Body body) {
  std::vector<std::string> lines;
  set_progress_sink([&lines](const std::string& line) { lines.push_back(line); });
  body();
  set_progress_sink({});
  return lines;
}

TEST(CheckProgress, LargeStepsAreAnnouncedUnderTheLimitsOnly) {
  const std::vector<std::string> talking = lines_of([] {
    start_check_progress(true);
    check_progress(kAnnouncedWork, "the large step");
    check_progress(kAnnouncedWork / 2, "a small step right after it");
  });
  ASSERT_EQ(talking.size(), 1u);
  EXPECT_NE(talking[0].find("[lpvid-verify"), std::string::npos) << talking[0];
  EXPECT_NE(talking[0].find("the large step"), std::string::npos) << talking[0];
  const std::vector<std::string> quiet = lines_of([] {
    start_check_progress(false);
    check_progress(1e15, "a huge step of an unlimited check");
  });
  EXPECT_TRUE(quiet.empty());
}

}  // namespace
}  // namespace lpvid
