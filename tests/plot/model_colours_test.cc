// The colours of a compare figure's models (plot/model_colours.h): the roles
// before and after keep their colours in any order and beside any other
// model, and no two models of a figure share a colour while the list lasts.
#include <gtest/gtest.h>

#include <set>

#include "plot/model_colours.h"
#include "plot/palette.h"

namespace lpvid {
namespace {

TEST(ModelColours, BeforeIsOrangeAndAfterIsBlueInEitherOrder) {
  const std::vector<std::string> ab = model_colours({"before", "after"});
  const std::vector<std::string> ba = model_colours({"after", "before"});
  EXPECT_EQ(ab, (std::vector<std::string>{palette::kModelBefore, palette::kModelAfter}));
  EXPECT_EQ(ba, (std::vector<std::string>{palette::kModelAfter, palette::kModelBefore}));
}

TEST(ModelColours, OtherModelsAvoidTheRolesColours) {
  const std::vector<std::string> c = model_colours({"arx", "after", "truth", "before", "oe"});
  EXPECT_EQ(c[1], palette::kModelAfter);
  EXPECT_EQ(c[3], palette::kModelBefore);
  const std::set<std::string> distinct(c.begin(), c.end());
  EXPECT_EQ(distinct.size(), c.size());
}

TEST(ModelColours, WithoutRolesTheListIsTakenInOrder) {
  const std::vector<std::string> c = model_colours({"m1", "m2", "m3"});
  for (size_t j = 0; j < c.size(); ++j) EXPECT_EQ(c[j], palette::kOtherModels[j]);
}

}  // namespace
}  // namespace lpvid
