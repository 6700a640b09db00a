// RobotStateHistory (core/robot/robot_state_history.h): interpolation at the scan time,
// gaps, order, bad states.
#include "core/robot/robot_state_history.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

namespace topay {
namespace {

WholeBodyState StateAt(double x, double yaw, double q0) {
  WholeBodyState s;
  s.x_m = x;
  s.y_m = -x;
  s.yaw_rad = yaw;
  s.q_rad = Eigen::VectorXd::Constant(7, q0);
  return s;
}

TEST(RobotStateHistoryTest, InterpolatesBetweenNeighbours) {
  RobotStateHistory history;
  ASSERT_TRUE(history.Add(1'000'000, StateAt(0.0, 0.0, 0.0)));
  ASSERT_TRUE(history.Add(1'010'000, StateAt(1.0, 0.2, 1.0)));
  const auto s = history.At(1'002'500);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->x_m, 0.25, 1e-12);
  EXPECT_NEAR(s->y_m, -0.25, 1e-12);
  EXPECT_NEAR(s->yaw_rad, 0.05, 1e-12);
  EXPECT_NEAR(s->q_rad(3), 0.25, 1e-12);
}

TEST(RobotStateHistoryTest, YawTakesTheShorterArc) {
  RobotStateHistory history;
  const double pi = std::numbers::pi;
  history.Add(0, StateAt(0.0, pi - 0.1, 0.0));
  history.Add(10'000, StateAt(0.0, -pi + 0.1, 0.0));
  const auto s = history.At(5'000);
  ASSERT_TRUE(s);
  EXPECT_NEAR(std::abs(s->yaw_rad), pi, 1e-9);
}

TEST(RobotStateHistoryTest, OutOfOrderStatesAreSorted) {
  RobotStateHistory history;
  history.Add(20'000, StateAt(2.0, 0.0, 0.0));
  history.Add(0, StateAt(0.0, 0.0, 0.0));
  history.Add(10'000, StateAt(1.0, 0.0, 0.0));
  EXPECT_NEAR(history.At(15'000)->x_m, 1.5, 1e-12);
  EXPECT_NEAR(history.At(5'000)->x_m, 0.5, 1e-12);
}

TEST(RobotStateHistoryTest, BeyondTheGapThereIsNoState) {
  RobotStateHistory history({.horizon_s = 2.0, .max_gap_s = 0.1});
  EXPECT_FALSE(history.At(0));
  history.Add(1'000'000, StateAt(1.0, 0.0, 0.0));
  EXPECT_NEAR(history.At(1'050'000)->x_m, 1.0, 1e-12);  // nearest, within the gap
  EXPECT_NEAR(history.At(950'000)->x_m, 1.0, 1e-12);
  EXPECT_FALSE(history.At(1'200'000));
  EXPECT_FALSE(history.At(800'000));
  // A hole of 1 s in the stream: only a time near one of its ends has a state.
  history.Add(2'000'000, StateAt(2.0, 0.0, 0.0));
  EXPECT_FALSE(history.At(1'500'000));
  EXPECT_NEAR(history.At(1'950'000)->x_m, 2.0, 1e-12);
}

TEST(RobotStateHistoryTest, OldStatesLeaveTheHorizon) {
  RobotStateHistory history({.horizon_s = 0.5, .max_gap_s = 0.1});
  for (int k = 0; k <= 100; ++k) history.Add(k * 10'000, StateAt(k, 0.0, 0.0));
  EXPECT_EQ(history.size(), 51u);
  EXPECT_FALSE(history.At(0));
}

TEST(RobotStateHistoryTest, NonFiniteOrResizedStatesAreRejected) {
  RobotStateHistory history;
  WholeBodyState bad = StateAt(0.0, 0.0, 0.0);
  bad.q_rad(2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(history.Add(0, bad));
  ASSERT_TRUE(history.Add(0, StateAt(0.0, 0.0, 0.0)));
  WholeBodyState six = StateAt(0.0, 0.0, 0.0);
  six.q_rad.resize(6);
  EXPECT_FALSE(history.Add(1, six));
  EXPECT_EQ(history.rejected(), 2);
  EXPECT_EQ(history.size(), 1u);
}

}  // namespace
}  // namespace topay
