// The replay clock (procs/viz/replay_clock.h): play, pause, speed, seek, the end.

#include "procs/viz/replay_clock.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::viz {
namespace {

constexpr std::int64_t kStart = 1'000'000'000, kEnd = kStart + 10'000'000;  // a 10 s log

TEST(ReplayClock, StartsPausedAtTheStartAndRunsAtItsSpeed) {
  ReplayClock clock(kStart, kEnd);
  EXPECT_FALSE(clock.playing());
  EXPECT_EQ(clock.Now(5'000'000), kStart);
  clock.Play(5'000'000);
  EXPECT_EQ(clock.Now(6'000'000), kStart + 1'000'000);
  clock.SetSpeed(2.0, 6'000'000);
  EXPECT_EQ(clock.Now(7'000'000), kStart + 3'000'000);
  clock.Pause(7'500'000);
  EXPECT_EQ(clock.Now(9'000'000), kStart + 4'000'000);
  EXPECT_FALSE(clock.playing());
}

TEST(ReplayClock, SeeksWithinTheLogAndStopsAtItsEnd) {
  ReplayClock clock(kStart, kEnd);
  clock.Seek(kStart - 5, 0);
  EXPECT_EQ(clock.Now(0), kStart);
  clock.Seek(kEnd - 1'000'000, 0);
  clock.Play(0);
  EXPECT_EQ(clock.Now(2'000'000), kEnd);
  EXPECT_FALSE(clock.playing());
  clock.Play(3'000'000);  // play at the end: from the start again
  EXPECT_EQ(clock.Now(3'500'000), kStart + 500'000);
}

TEST(ReplayClock, ClampsTheSpeed) {
  ReplayClock clock(kStart, kEnd);
  clock.SetSpeed(1e9, 0);
  EXPECT_DOUBLE_EQ(clock.speed(), 100.0);
  clock.SetSpeed(0.0, 0);
  EXPECT_DOUBLE_EQ(clock.speed(), 0.01);
  clock.SetSpeed(std::nan(""), 0);
  EXPECT_DOUBLE_EQ(clock.speed(), 1.0);
}

}  // namespace
}  // namespace topay::viz
