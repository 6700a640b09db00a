#include "core/common/stopwatch.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

#include <gtest/gtest.h>

namespace topay {
namespace {

using Clock = Stopwatch::Clock;
using std::chrono::milliseconds;

TEST(StopwatchTest, ElapsedAtAGivenTimeIsExact) {
  const Clock::time_point t0 = Clock::now();
  const Stopwatch watch(t0);
  EXPECT_EQ(watch.start(), t0);
  EXPECT_DOUBLE_EQ(watch.ElapsedMsAt(t0 + milliseconds(1500)), 1500.0);
  EXPECT_DOUBLE_EQ(watch.ElapsedSAt(t0 + milliseconds(1500)), 1.5);
  EXPECT_DOUBLE_EQ(watch.ElapsedMsAt(t0 - milliseconds(20)), -20.0);
  EXPECT_DOUBLE_EQ(Stopwatch::MillisecondsBetween(t0, t0 + milliseconds(7)), 7.0);
  EXPECT_DOUBLE_EQ(Stopwatch::SecondsBetween(t0 + milliseconds(7), t0), -0.007);
}

// Lower bounds only: sleep_for waits at least its duration on the steady clock.
TEST(StopwatchTest, MeasuresAtLeastTheTimeSlept) {
  Stopwatch watch;
  std::this_thread::sleep_for(milliseconds(20));
  const double ms = watch.ElapsedMs();
  EXPECT_GE(ms, 20.0);
  EXPECT_GE(watch.ElapsedS(), 0.02);
  EXPECT_GE(watch.ElapsedMs(), ms);  // monotone
}

TEST(StopwatchTest, RestartMovesTheStart) {
  Stopwatch watch(Clock::now() - milliseconds(5000));
  EXPECT_GE(watch.ElapsedMs(), 5000.0);
  watch.Restart();
  EXPECT_LT(watch.ElapsedMs(), 5000.0);
}

TEST(DeadlineAfterTest, AddsFiniteSecondsAndSaturates) {
  const Clock::time_point t0 = Clock::now();
  EXPECT_EQ(DeadlineAfter(t0, 0.25), t0 + milliseconds(250));
  EXPECT_EQ(DeadlineAfter(t0, 0.0), t0);
  EXPECT_EQ(DeadlineAfter(t0, -0.25), t0 - milliseconds(250));
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(DeadlineAfter(t0, inf), Clock::time_point::max());
  EXPECT_EQ(DeadlineAfter(t0, std::nan("")), Clock::time_point::max());
  EXPECT_EQ(DeadlineAfter(t0, 1e30), Clock::time_point::max());
  EXPECT_EQ(DeadlineAfter(t0, -inf), Clock::time_point::min());
  EXPECT_EQ(DeadlineAfter(t0, -1e30), Clock::time_point::min());
}

TEST(CpuStopwatchTest, CountsWorkNotSleep) {
  CpuStopwatch cpu;
  // Work: at least 5 ms of CPU (bounded by a wall-clock guard so the test cannot hang).
  const Stopwatch guard;
  volatile double sink = 0.0;
  while (cpu.ElapsedMs() < 5.0 && guard.ElapsedS() < 30.0) {
    for (int i = 0; i < 10000; ++i) sink = sink + std::sqrt(static_cast<double>(i));
  }
  EXPECT_GE(cpu.ElapsedMs(), 5.0);
  EXPECT_GE(cpu.ElapsedS(), 0.005);
  // Sleep: 200 ms of wall-clock time costs (almost) no CPU time.
  cpu.Restart();
  std::this_thread::sleep_for(milliseconds(200));
  EXPECT_LT(cpu.ElapsedMs(), 100.0);
  EXPECT_GE(cpu.ElapsedMs(), 0.0);
}

}  // namespace
}  // namespace topay
