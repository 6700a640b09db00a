// topay-sim's CAN mode (`--plant-input actuators`, docs/simulator.md "CAN mode") as a real
// process over real LCM in a private network namespace (skipped, with the reason, where none
// can be made): no ROBOT_STATE; SIM_PLANT_STATE, GRIPPER_STATE and BASE_POSE present;
// ACTUATOR_COMMAND moves the plant while CONTROL_COMMAND is ignored; GRIPPER_COMMAND moves the
// gripper; without ACTUATOR_COMMAND the plant's own watchdog brakes it.

#include <gtest/gtest.h>

#include "graph_test_support.h"
#include "topay/control_command_t.hpp"
#include "topay/gripper_command_t.hpp"
#include "topay/joint_state_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

struct CanModeListener {
  int robot_states = 0, poses = 0;
  std::vector<robot_state_t> plant;
  std::vector<joint_state_t> gripper;
  void OnRobotState(const lcm::ReceiveBuffer*, const std::string&) { ++robot_states; }
  void OnPose(const lcm::ReceiveBuffer*, const std::string&) { ++poses; }
  void OnPlant(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { plant.push_back(*m); }
  void OnGripper(const lcm::ReceiveBuffer*, const std::string&, const joint_state_t* m) { gripper.push_back(*m); }
};

control_command_t Actuators(double v, double qdot1) {
  control_command_t c{};
  c.v_mps = v;
  c.num_joints = 7;
  c.qdot_radps.assign(7, 0.0);
  c.qdot_radps[0] = qdot1;
  c.gripper = 0.0;
  return c;
}

TEST(SimCanModeProcess, ActuatorCommandDrivesThePlantAndNoRobotStateIsPublished) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("sim_can_mode");
  WriteText(dir + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
  WriteText(dir + "/sim.yaml", "lidar: {enabled: false}\n");
  const pid_t pid = Spawn({BinDir() + "/topay-sim", "--config", dir + "/sim.yaml", "--scene", dir + "/empty.json",
                           "--plant-input", "actuators", "--name", "sim-can"},
                          dir + "/out.txt");
  HeartbeatWatcher watcher;
  CanModeListener l;
  watcher.lcm().subscribe(std::string(channels::ROBOT_STATE), &CanModeListener::OnRobotState, &l);
  watcher.lcm().subscribe(std::string(channels::BASE_POSE), &CanModeListener::OnPose, &l);
  watcher.lcm().subscribe(std::string(channels::SIM_PLANT_STATE), &CanModeListener::OnPlant, &l);
  watcher.lcm().subscribe(std::string(channels::GRIPPER_STATE), &CanModeListener::OnGripper, &l);
  ASSERT_TRUE(watcher.SpinUntil([&] { return watcher.last.contains("sim-can"); }, 10.0)) << ReadText(dir + "/out.txt");
  watcher.Spin(0.5);
  ASSERT_FALSE(l.plant.empty()) << ReadText(dir + "/out.txt");
  ASSERT_FALSE(l.gripper.empty());
  EXPECT_GT(l.poses, 0);
  EXPECT_EQ(l.plant.back().joints.num_joints, 7);
  EXPECT_EQ(l.gripper.back().num_joints, 1);
  EXPECT_EQ(l.gripper.back().names[0], "gripper");
  // SIM_PLANT_STATE every 4 ms of sim time (250 Hz: every 2nd plant step).
  const std::size_t n = l.plant.size();
  ASSERT_GT(n, 2u);
  EXPECT_EQ(l.plant[n - 1].utime - l.plant[n - 2].utime, 4000);
  const double x0 = l.plant.back().pose.x_m;
  const double q0 = l.plant.back().joints.position_rad[0];

  // ACTUATOR_COMMAND drives; a CONTROL_COMMAND backwards at the same time is ignored.
  const Clock::time_point start = Clock::now();
  while (SecondsSince(start) < 1.5) {
    const control_command_t a = Actuators(0.3, -0.2);  // q1 starts at 2.9 (stow), 0.2 below its limit
    watcher.lcm().publish(std::string(channels::ACTUATOR_COMMAND), &a);
    const control_command_t c = Actuators(-0.5, -0.5);
    watcher.lcm().publish(std::string(channels::CONTROL_COMMAND), &c);
    watcher.Spin(0.01);
  }
  EXPECT_GT(l.plant.back().pose.x_m - x0, 0.15) << "0.3 m/s for 1.5 s minus latency and lag";
  EXPECT_NEAR(l.plant.back().velocity.v_mps, 0.3, 0.03);
  EXPECT_LT(l.plant.back().joints.position_rad[0] - q0, -0.1);

  // GRIPPER_COMMAND closes the gripper (1 s stroke), without ACTUATOR_COMMAND: the drives brake.
  gripper_command_t g{};
  g.position = 1.0;
  g.source = "test";
  watcher.lcm().publish(std::string(channels::GRIPPER_COMMAND), &g);
  watcher.Spin(1.6);
  ASSERT_FALSE(l.gripper.empty());
  EXPECT_GT(l.gripper.back().position_rad[0], 0.9);
  EXPECT_NEAR(l.plant.back().velocity.v_mps, 0.0, 1e-3) << "the plant's command timeout braked it";
  EXPECT_EQ(l.robot_states, 0) << "ROBOT_STATE is the estimator's in CAN mode";

  kill(pid, SIGTERM);
  EXPECT_EQ(WaitFor(pid, 5.0), 0);
  const std::string out = ReadText(dir + "/out.txt");
  EXPECT_NE(out.find("CAN mode"), std::string::npos) << out;
}

TEST(SimCanModeProcess, RejectsAnUnknownPlantInput) {
  const std::string dir = TestDir("sim_can_mode_bad");
  const pid_t pid = Spawn({BinDir() + "/topay-sim", "--plant-input", "wishes"}, dir + "/out.txt");
  const int status = WaitFor(pid, 10.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  WriteText(dir + "/bad.yaml", "plant_input: wishes\n");
  const pid_t pid2 = Spawn({BinDir() + "/topay-sim", "--config", dir + "/bad.yaml"}, dir + "/out2.txt");
  const int status2 = WaitFor(pid2, 10.0);
  ASSERT_TRUE(WIFEXITED(status2));
  EXPECT_EQ(WEXITSTATUS(status2), 1);
  EXPECT_NE(ReadText(dir + "/out2.txt").find("plant_input"), std::string::npos);
}

}  // namespace
}  // namespace topay::test
