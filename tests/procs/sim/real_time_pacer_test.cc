// Real-time pacing (procs/sim/real_time_pacer.h) on a synthetic clock.

#include "procs/sim/real_time_pacer.h"

#include <gtest/gtest.h>

namespace topay::simproc {
namespace {

using Clock = RealTimePacer::Clock;
using std::chrono::microseconds;

TEST(RealTimePacer, RunsTheStepsDueAtTheRateAndCapsTheCatchUp) {
  RealTimePacer pacer(0.002, 1.0, 50);
  const Clock::time_point t0{};
  pacer.Start(t0);
  EXPECT_EQ(pacer.StepsDue(t0 + microseconds(1999), 0), 0);
  EXPECT_EQ(pacer.StepsDue(t0 + microseconds(2000), 0), 1);
  EXPECT_EQ(pacer.StepsDue(t0 + microseconds(10'500), 1), 4);   // 5 due, 1 done
  EXPECT_EQ(pacer.NextDue(5), t0 + microseconds(12'000));
  // 1 s late: 500 due, only 50 run, the schedule moves by the rest.
  EXPECT_EQ(pacer.StepsDue(t0 + microseconds(1'010'000), 5), 50);
  EXPECT_EQ(pacer.schedule_resets(), 1);
  EXPECT_EQ(pacer.slipped_steps(), 450);  // 505 due at 1.01 s, 5 done, 50 run now
  EXPECT_EQ(pacer.StepsDue(t0 + microseconds(1'010'000), 55), 0);
  EXPECT_EQ(pacer.StepsDue(t0 + microseconds(1'012'000), 55), 1);
}

TEST(RealTimePacer, FasterRateAndAsFastAsPossible) {
  RealTimePacer double_speed(0.002, 2.0, 50);
  const Clock::time_point t0{};
  double_speed.Start(t0);
  EXPECT_EQ(double_speed.StepsDue(t0 + microseconds(10'000), 0), 10);
  RealTimePacer max_speed(0.002, 0.0, 50, 100);
  max_speed.Start(t0);
  EXPECT_EQ(max_speed.StepsDue(t0, 12345), 100);
}

TEST(RealTimePacer, MeasuresLateness) {
  RealTimePacer pacer(0.002, 1.0, 50);
  const Clock::time_point t0{};
  pacer.Start(t0);
  for (int k = 1; k <= 100; ++k) pacer.RecordStep(t0 + microseconds(2000 * k + (k == 50 ? 3000 : 100)), k);
  EXPECT_EQ(pacer.late_steps(), 1);  // only step 50 ran more than a period late
  const RealTimePacer::Lateness l = pacer.TakeLateness();
  EXPECT_EQ(l.count, 100);
  EXPECT_NEAR(l.p50_us, 100.0, 1e-6);
  EXPECT_NEAR(l.max_us, 3000.0, 1e-6);
  EXPECT_EQ(pacer.TakeLateness().count, 0);
}

}  // namespace
}  // namespace topay::simproc
