// The simulator's message conversions (procs/sim/sim_messages.h).

#include "procs/sim/sim_messages.h"

#include <gtest/gtest.h>

#include <cmath>

namespace topay::simproc {
namespace {

TEST(SimMessages, CommandsStatesCloudsAndContacts) {
  control_command_t cmd{};
  cmd.v_mps = 0.4;
  cmd.omega_radps = -0.2;
  cmd.num_joints = 2;
  cmd.qdot_radps = {0.1, -0.3};
  cmd.gripper = 1.0;
  const sim::ActuatorCommand a = ToActuatorCommand(cmd);
  EXPECT_EQ(a.v_mps, 0.4);
  EXPECT_EQ(a.omega_radps, -0.2);
  ASSERT_EQ(a.qdot_radps.size(), 2);
  EXPECT_EQ(a.qdot_radps[1], -0.3);
  cmd.num_joints = 3;  // disagrees with the array: no joint rates (the plant rejects it)
  EXPECT_EQ(ToActuatorCommand(cmd).qdot_radps.size(), 0);

  StateSample s;
  s.t_s = 1.234567;
  s.pose = {1.0, 2.0, 0.5};
  s.measured.v_mps = 0.3;
  s.measured.omega_radps = 0.1;
  s.measured.q_rad = Eigen::VectorXd::Constant(2, 0.7);
  s.measured.qdot_radps = Eigen::VectorXd::Constant(2, -0.1);
  s.measured.gripper = 0.25;
  const robot_state_t rs = ToRobotState(s, 1'000'000'000'000'000, {"a", "b"});
  EXPECT_EQ(rs.utime, 1'000'000'001'234'567);
  EXPECT_EQ(rs.pose.utime, rs.utime);
  EXPECT_EQ(rs.pose.x_m, 1.0);
  EXPECT_EQ(rs.pose.yaw_rad, 0.5);
  EXPECT_EQ(rs.velocity.v_mps, 0.3);
  EXPECT_EQ(rs.joints.num_joints, 2);
  EXPECT_EQ(rs.joints.names, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(rs.joints.position_rad[1], 0.7);
  EXPECT_TRUE(std::isnan(rs.joints.effort_Nm[0]));
  EXPECT_EQ(rs.gripper, 0.25);

  ScanResult scan;
  scan.t_s = 0.1;
  scan.X_WS = Eigen::Translation3d(1, 2, 3) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ());
  scan.p_SP = {Eigen::Vector3f(1, 2, 3), Eigen::Vector3f(4, 5, 6)};
  const point_cloud_t cloud = ToPointCloud(scan, 0, "lidar");
  EXPECT_EQ(cloud.utime, 100'000);
  EXPECT_EQ(cloud.num_coords, 6);
  EXPECT_EQ(cloud.p_SP[4], 5.0f);
  EXPECT_EQ(cloud.p_WS[2], 3.0);
  EXPECT_NEAR(cloud.quat_WS[0], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(cloud.quat_WS[3], std::sqrt(0.5), 1e-12);

  const sim_contact_t contact = ToContactMessage({2.0, "sphere 4", 3, 0.02}, 17, 5);
  EXPECT_EQ(contact.utime, 2'000'005);
  EXPECT_EQ(contact.box_id, 17);
  EXPECT_EQ(contact.body, "sphere 4");
}

TEST(SimMessages, EventsRoundTripAndBadOnesAreRefused) {
  sim::SimEvent e;
  e.name = "x";
  e.action = sim::SimEvent::Action::kAppear;
  e.box_id = 1000;
  OrientedBox box;
  box.center_W_m = Eigen::Vector3d(1, 2, 0.5);
  box.size_m = Eigen::Vector3d(0.3, 0.4, 1.0);
  e.box = box;
  e.trigger = sim::SimEvent::Trigger::kNearPoint;
  e.point_W_m = Eigen::Vector2d(3, 4);
  e.distance_m = 1.5;
  std::string error;
  const std::optional<sim::SimEvent> back = FromEventMessage(ToEventMessage(e, 7), &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->box_id, 1000);
  EXPECT_EQ(back->box->size_m, box.size_m);
  EXPECT_EQ(back->trigger, sim::SimEvent::Trigger::kNearPoint);
  EXPECT_EQ(back->point_W_m, e.point_W_m);

  sim_event_t bad = ToEventMessage(e, 7);
  bad.action = 9;
  EXPECT_FALSE(FromEventMessage(bad, &error));
  EXPECT_NE(error.find("action"), std::string::npos);
  bad = ToEventMessage(e, 7);
  bad.size_m[1] = -1.0;
  EXPECT_FALSE(FromEventMessage(bad, &error));
  EXPECT_NE(error.find("box"), std::string::npos);
  bad = ToEventMessage(e, 7);
  bad.distance_m = NAN;
  EXPECT_FALSE(FromEventMessage(bad, &error));
  bad = ToEventMessage(e, 7);
  bad.trigger = 5;
  EXPECT_FALSE(FromEventMessage(bad, &error));
  EXPECT_NE(error.find("trigger"), std::string::npos);
  bad = ToEventMessage(e, 7);
  bad.box_id = -2;
  EXPECT_FALSE(FromEventMessage(bad, &error));
}

}  // namespace
}  // namespace topay::simproc
