// Tracking errors and solve times over the TRACKING statuses only.

#include "tools/report/tracking_summary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::report {
namespace {

tracker_status_t Status(std::int8_t state, double position_m, double yaw_rad, double joint_rad, double solve_ms) {
  tracker_status_t t{};
  t.state = state;
  t.position_error_m = position_m;
  t.yaw_error_rad = yaw_rad;
  t.joint_error_rad = joint_rad;
  t.solve_ms = solve_ms;
  return t;
}

TEST(TrackingSummary, OnlyTrackingCyclesCount) {
  using T = tracker_status_t;
  const TrackingSummary t = SummarizeTracking({Status(T::TRACKING, 0.03, -0.3, 0.1, 1.0),
                                               Status(T::STOPPING, 9.0, 9.0, 9.0, 99.0),
                                               Status(T::TRACKING, 0.04, 0.4, 0.0, 3.0),
                                               Status(T::IDLE, 9.0, 9.0, 9.0, 99.0)});
  EXPECT_EQ(t.position_m.count, 2);
  EXPECT_DOUBLE_EQ(t.position_m.rms, std::sqrt((9e-4 + 16e-4) / 2.0));
  EXPECT_DOUBLE_EQ(t.position_m.max, 0.04);
  EXPECT_DOUBLE_EQ(t.yaw_rad.rms, std::sqrt((0.09 + 0.16) / 2.0));
  EXPECT_DOUBLE_EQ(t.yaw_rad.max, 0.4);
  EXPECT_DOUBLE_EQ(t.joint_rad.max, 0.1);
  EXPECT_DOUBLE_EQ(t.solve_ms.median, 2.0);
  EXPECT_DOUBLE_EQ(t.solve_ms.max, 3.0);
}

TEST(TrackingSummary, NoTrackingIsAllZero) {
  const TrackingSummary t = SummarizeTracking({Status(tracker_status_t::FINISHED, 1.0, 1.0, 1.0, 1.0)});
  EXPECT_EQ(t.position_m.count, 0);
  EXPECT_DOUBLE_EQ(t.position_m.rms, 0.0);
  EXPECT_EQ(t.solve_ms.count, 0);
}

}  // namespace
}  // namespace topay::report
