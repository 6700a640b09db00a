// topay-motorsim's message conversions (procs/motorsim/motorsim_messages.h): SIM_PLANT_STATE in,
// MOTORSIM_FAULT in, ACTUATOR_COMMAND out.

#include "procs/motorsim/motorsim_messages.h"

#include <gtest/gtest.h>

#include <cmath>

#include "procs/msgs/convert_robot_state.h"

namespace topay::motorsim {
namespace {

robot_state_t PlantMessage(int joints) {
  msgs::RobotStateEstimate e;
  e.utime = 5;
  e.state.x_m = 1.0;
  e.state.q_rad = Eigen::VectorXd::LinSpaced(joints, 0.1, 0.7);
  e.qdot_radps = Eigen::VectorXd::Constant(joints, 0.2);
  e.v_mps = 0.3;
  e.omega_radps = -0.1;
  e.gripper = 0.5;
  return msgs::ToMessage(e);
}

TEST(MotorsimMessagesTest, PlantStateFromMessage) {
  std::string error;
  const auto state = PlantStateFromMessage(PlantMessage(7), 7, &error);
  ASSERT_TRUE(state) << error;
  EXPECT_EQ(state->state.x_m, 1.0);
  EXPECT_EQ(state->v_mps, 0.3);
  EXPECT_EQ(state->omega_radps, -0.1);
  EXPECT_NEAR(state->state.q_rad[6], 0.7, 1e-12);
  EXPECT_EQ(state->qdot_radps[3], 0.2);
  EXPECT_FALSE(PlantStateFromMessage(PlantMessage(6), 7, &error));
  EXPECT_NE(error.find("6 joints"), std::string::npos);
  robot_state_t bad = PlantMessage(7);
  bad.velocity.v_mps = std::nan("");
  EXPECT_FALSE(PlantStateFromMessage(bad, 7, &error));
}

TEST(MotorsimMessagesTest, FaultEventFromMessage) {
  motorsim_fault_t msg{};
  msg.kind = motorsim_fault_t::HEARTBEAT_LOSS;
  msg.joint = 3;
  msg.duration_s = 1.5;
  std::string error;
  auto event = FaultEventFromMessage(msg, &error);
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, sim::motors::FaultKind::kHeartbeatLoss);
  EXPECT_EQ(event->joint, 3);
  EXPECT_EQ(event->duration_s, 1.5);
  msg.kind = motorsim_fault_t::BASE_FAULT;
  msg.code = 4;
  event = FaultEventFromMessage(msg, &error);
  ASSERT_TRUE(event);
  EXPECT_EQ(event->kind, sim::motors::FaultKind::kBaseFault);
  EXPECT_EQ(event->code, 4);
  msg.kind = 42;
  EXPECT_FALSE(FaultEventFromMessage(msg, &error));
  EXPECT_NE(error.find("42"), std::string::npos);
}

TEST(MotorsimMessagesTest, ActuatorMessage) {
  sim::ActuatorCommand command;
  command.v_mps = 0.4;
  command.omega_radps = 0.1;
  command.qdot_radps = Eigen::VectorXd::Constant(7, -0.3);
  const control_command_t msg = ToActuatorMessage(command, 123);
  EXPECT_EQ(msg.utime, 123);
  EXPECT_EQ(msg.v_mps, 0.4);
  EXPECT_EQ(msg.omega_radps, 0.1);
  ASSERT_EQ(msg.num_joints, 7);
  EXPECT_EQ(msg.qdot_radps[6], -0.3);
  EXPECT_EQ(msg.gripper, 0.0);
}

}  // namespace
}  // namespace topay::motorsim
