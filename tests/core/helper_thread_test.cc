// HelperThread: both halves of a fork-join run, on two threads, and a
// throwing half is rethrown after both finished.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>

#include "core/helper_thread.h"

namespace lpvid {
namespace {

TEST(HelperThread, RunsTheSideJobOnAnotherThreadAndJoins) {
  HelperThread helper;
  for (int round = 0; round < 100; ++round) {
    std::thread::id side_id, main_id;
    int side_value = 0, main_value = 0;
    helper.run([&] { side_id = std::this_thread::get_id(), side_value = round; },
               [&] { main_id = std::this_thread::get_id(), main_value = round + 1; });
    EXPECT_EQ(side_value, round);
    EXPECT_EQ(main_value, round + 1);
    EXPECT_NE(side_id, main_id);
    EXPECT_EQ(main_id, std::this_thread::get_id());
  }
}

TEST(HelperThread, RethrowsAfterBothHalvesFinished) {
  HelperThread helper;
  std::atomic<int> finished{0};
  EXPECT_THROW(helper.run([&] { throw std::runtime_error("side"); }, [&] { ++finished; }), std::runtime_error);
  EXPECT_EQ(finished.load(), 1);
  try {
    helper.run([&] { ++finished; throw std::logic_error("side"); }, [&] { throw std::runtime_error("main"); });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "main");  // the caller's half first
  }
  EXPECT_EQ(finished.load(), 2);
  int after = 0;
  helper.run([&] { after += 1; }, [] {});  // still usable
  EXPECT_EQ(after, 1);
}

TEST(HelperThread, ForkJoinWithoutAHelperRunsBothInOrder) {
  std::string order;
  fork_join(nullptr, [&] { order += "side"; }, [&] { order += "main,"; });
  EXPECT_EQ(order, "main,side");
}

}  // namespace
}  // namespace lpvid
