#include "procs/planner/planner_clock.h"

#include <gtest/gtest.h>

namespace topay::planner {
namespace {

TEST(PlannerClockTest, TheWallClockIgnoresMessages) {
  PlannerClock clock(ClockSource::kWall);
  EXPECT_FALSE(clock.message_time());
  clock.OnMessage(42);  // a message from 1970: no effect on the wall clock
  const std::int64_t before = procs::NowUtime();
  const std::int64_t now = clock.Now();
  EXPECT_GE(now, before);
  EXPECT_LT(now - before, 1'000'000);
}

TEST(PlannerClockTest, MessageTimeIsTheNewestMessageAndNeverGoesBack) {
  PlannerClock clock(ClockSource::kMessages);
  EXPECT_TRUE(clock.message_time());
  EXPECT_EQ(clock.Now(), 0) << "no message yet";
  clock.OnMessage(1'000'000);
  EXPECT_EQ(clock.Now(), 1'000'000);
  clock.OnMessage(1'020'000);  // a ROBOT_STATE
  EXPECT_EQ(clock.Now(), 1'020'000);
  clock.OnMessage(990'000);  // a MAP_UPDATE stamped with its (older) scan
  EXPECT_EQ(clock.Now(), 1'020'000);
  clock.OnMessage(1'030'000);
  EXPECT_EQ(clock.Now(), 1'030'000);
}

}  // namespace
}  // namespace topay::planner
