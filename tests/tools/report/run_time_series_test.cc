// Planned vs measured at every ROBOT_STATE of the crafted run: measured values as sent, planned
// NaN before the first trajectory is active, else the active trajectory at the state's time.

#include "tools/report/run_time_series.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/tools/report/crafted_run_log.h"

namespace topay::report {
namespace {

TEST(RunTimeSeries, PlannedIsTheActiveTrajectoryMeasuredIsTheRobotState) {
  const std::string path = test::FreshTestDir("time_series") + "/graph.lcmlog";
  test::WriteCraftedRunLog(path);
  const RunTimeSeries s = SampleRunTimeSeries(ReadRunLog(path));
  ASSERT_EQ(s.t_s.size(), static_cast<std::size_t>(test::kRobotStates));
  ASSERT_EQ(s.q_measured_rad.size(), static_cast<std::size_t>(test::kJoints));
  EXPECT_EQ(s.t0_utime, test::At(0.0));
  EXPECT_NEAR(s.t_s[20], 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.v_measured_mps[4], 0.5);
  EXPECT_DOUBLE_EQ(s.omega_measured_radps[4], 0.1);
  EXPECT_NEAR(s.q_measured_rad[6][4], 0.2, 1e-12);
  // Before 0.3 s nothing is active.
  EXPECT_TRUE(std::isnan(s.v_planned_mps[2]));
  EXPECT_TRUE(std::isnan(s.q_planned_rad[0][2]));
  // At 0.5 s trajectory 101 (start 0.3 s) at 0.2 s; at 1.1 s trajectory 103 (start 1.0 s) at 0.1 s.
  const ArcYawTrajectory trajectory = test::SmoothTrajectory();
  TrajectorySample point = trajectory.MakePoint();
  trajectory.Evaluate(0.2, &point);
  EXPECT_NEAR(s.v_planned_mps[5], point.v_mps, 1e-9);
  EXPECT_NEAR(s.omega_planned_radps[5], point.omega_radps, 1e-9);
  EXPECT_NEAR(s.q_planned_rad[3][5], point.state.q_rad(3), 1e-9);
  EXPECT_GT(s.v_planned_mps[5], 0.0);
  trajectory.Evaluate(0.1, &point);
  EXPECT_NEAR(s.v_planned_mps[11], point.v_mps, 1e-9);
  // Switches: 101 at 0.3 s, 103 at 1.05 s (published after its start); 102 did not rebuild.
  ASSERT_EQ(s.switch_t_s.size(), 2u);
  EXPECT_NEAR(s.switch_t_s[0], 0.3, 1e-12);
  EXPECT_NEAR(s.switch_t_s[1], 1.05, 1e-12);
}

}  // namespace
}  // namespace topay::report
