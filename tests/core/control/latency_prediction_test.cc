// Latency compensation: the measured state predicted with the commands in flight.

#include "core/control/latency_prediction.h"

#include <gtest/gtest.h>

#include "core/robot/unicycle_motion.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::StateAt;

ControlCommand Command(double v, double omega, double qd) {
  ControlCommand c = ControlCommand::Zero(kJoints);
  c.v_mps = v;
  c.omega_radps = omega;
  c.qd_radps.setConstant(qd);
  return c;
}

TEST(LatencyPredictionTest, CommandsActOneLatencyAfterSending) {
  CommandHistory history(8, kJoints);
  history.Push(0.00, Command(0.5, 0.2, 1.0));
  history.Push(0.02, Command(0.6, -0.1, -1.0));
  // State measured at 0.03; prediction to 0.05 with latency 0.02: command 1 acts over
  // [0.03, 0.04), command 2 over [0.04, 0.05).
  WholeBodyState predicted = StateAt(1, 2, 0.3, 0.5);
  PredictState(history, 0.02, 0.03, 0.05, &predicted);
  WholeBodyState expected = StateAt(1, 2, 0.3, 0.5);
  AdvanceUnicycle(0.5, 0.2, 0.01, &expected);
  AdvanceUnicycle(0.6, -0.1, 0.01, &expected);
  EXPECT_NEAR(predicted.x_m, expected.x_m, 1e-12);
  EXPECT_NEAR(predicted.y_m, expected.y_m, 1e-12);
  EXPECT_NEAR(predicted.yaw_rad, expected.yaw_rad, 1e-12);
  EXPECT_NEAR(predicted.q_rad(0), 0.5 + 0.01 * 1.0 - 0.01 * 1.0, 1e-12);
  EXPECT_GT(predicted.x_m, 1.0);  // it did move
}

TEST(LatencyPredictionTest, BeforeAnyCommandActsTheRobotRests) {
  CommandHistory history(8, kJoints);
  history.Push(0.10, Command(1.0, 0.0, 1.0));
  WholeBodyState predicted = StateAt(0, 0, 0, 0);
  PredictState(history, 0.02, 0.0, 0.11, &predicted);  // acts from 0.12
  EXPECT_EQ(predicted.x_m, 0.0);
  PredictState(history, 0.02, 0.11, 0.13, &predicted);  // acts over [0.12, 0.13)
  EXPECT_NEAR(predicted.x_m, 0.01, 1e-12);
  EXPECT_NEAR(predicted.q_rad(3), 0.01, 1e-12);
}

TEST(LatencyPredictionTest, HistoryKeepsTheNewestWhenFull) {
  CommandHistory history(3, kJoints);
  for (int i = 0; i < 5; ++i) history.Push(0.02 * i, Command(i, 0, 0));
  ASSERT_EQ(history.size(), 3);
  EXPECT_EQ(history.command(0).v_mps, 2.0);
  EXPECT_EQ(history.command(2).v_mps, 4.0);
  EXPECT_DOUBLE_EQ(history.time_s(2), 0.08);
  history.Push(0.0, Command(9, 0, 0));  // time went back: starts again
  EXPECT_EQ(history.size(), 1);
}

}  // namespace
}  // namespace topay
