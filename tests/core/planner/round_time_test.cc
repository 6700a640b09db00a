#include "core/planner/round_time.h"

#include <chrono>

#include <gtest/gtest.h>

namespace topay {
namespace {

using std::chrono::milliseconds;

const RoundClock::time_point kNow = RoundClock::time_point() + std::chrono::hours(1);

TEST(RoundShareEndTest, IsTheShareOfTheTimeLeft) {
  EXPECT_EQ(RoundShareEnd(kNow, kNow + milliseconds(2000), 0.6), kNow + milliseconds(1200));
  EXPECT_EQ(RoundShareEnd(kNow, kNow + milliseconds(2000), 1.0), kNow + milliseconds(2000));
}

TEST(RoundShareEndTest, NoLimitGivesNoShareAndAPastEndGivesNow) {
  EXPECT_EQ(RoundShareEnd(kNow, RoundClock::time_point::max(), 0.6),
            RoundClock::time_point::max());
  EXPECT_EQ(RoundShareEnd(kNow, kNow - milliseconds(5), 0.6), kNow);
}

TEST(RoundKeepsThePlanTimeTest, KeepsItWhenTheTimeAfterTheShareHoldsNoWholeRound) {
  const RoundClock::time_point plan_end = kNow + milliseconds(2000);
  const RoundClock::time_point round_end = kNow + milliseconds(1200);  // 800 ms after it
  // Another round needs its front end (as long as this one's) + 0.3 s to optimize.
  EXPECT_FALSE(RoundKeepsThePlanTime(round_end, plan_end, 0.4, 0.3));  // 700 ms: fits
  EXPECT_TRUE(RoundKeepsThePlanTime(round_end, plan_end, 0.6, 0.3));   // 900 ms: does not
  EXPECT_TRUE(RoundKeepsThePlanTime(round_end, plan_end, 0.0, 0.9));
}

TEST(RoundKeepsThePlanTimeTest, ALastRoundAlreadyHasThePlanTime) {
  const RoundClock::time_point plan_end = kNow + milliseconds(100);
  EXPECT_FALSE(RoundKeepsThePlanTime(plan_end, plan_end, 5.0, 0.3));
  EXPECT_FALSE(RoundKeepsThePlanTime(RoundClock::time_point::max(),
                                     RoundClock::time_point::max(), 5.0, 0.3));
}

}  // namespace
}  // namespace topay
