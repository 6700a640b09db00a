// MapPublishSchedule (procs/msgs/map_publish_schedule.h): a snapshot first, then every
// snapshot_period_s with deltas in between, on request and after a clock jump back; map_seq
// counts every update.

#include "procs/msgs/map_publish_schedule.h"

#include <gtest/gtest.h>

#include <limits>

namespace topay::msgs {
namespace {

TEST(MapPublishSchedule, SnapshotFirstThenEveryPeriodWithDeltasBetween) {
  MapPublishSchedule schedule;  // 5 s
  int snapshots = 0;
  std::int64_t expected_seq = 1;
  for (int scan = 0; scan <= 150; ++scan) {  // 15 s at 10 Hz
    const double now_s = 100.0 + 0.1 * scan;
    const MapPublishStep step = schedule.Next(now_s);
    EXPECT_EQ(step.map_seq, expected_seq++);
    // Snapshots at scans 0, 50, 100, 150 (within rounding of 0.1 s steps: at most one late).
    if (step.is_full) {
      ++snapshots;
      EXPECT_TRUE(scan % 50 == 0 || scan % 50 == 1) << scan;
    }
  }
  EXPECT_EQ(snapshots, 4);
}

TEST(MapPublishSchedule, RequestAndClockJumpBackGiveASnapshot) {
  MapPublishScheduleOptions options;
  options.snapshot_period_s = 2.0;
  options.first_map_seq = 40;
  MapPublishSchedule schedule(options);
  EXPECT_EQ(schedule.Next(10.0).map_seq, 40);
  EXPECT_FALSE(schedule.Next(10.5).is_full);
  schedule.RequestSnapshot();
  EXPECT_TRUE(schedule.Next(10.6).is_full);
  EXPECT_FALSE(schedule.Next(11.0).is_full);
  EXPECT_TRUE(schedule.Next(3.0).is_full);  // the clock went back
  EXPECT_FALSE(schedule.Next(4.9).is_full);
  EXPECT_TRUE(schedule.Next(5.0).is_full);  // exactly one period
  EXPECT_EQ(schedule.Next(5.1).map_seq, 47);
}

TEST(MapPublishSchedule, BadInputThrows) {
  for (double period : {0.0, -1.0, std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::quiet_NaN()}) {
    MapPublishScheduleOptions options;
    options.snapshot_period_s = period;
    EXPECT_THROW(MapPublishSchedule{options}, std::invalid_argument) << period;
  }
  MapPublishSchedule schedule;
  EXPECT_THROW(schedule.Next(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

}  // namespace
}  // namespace topay::msgs
