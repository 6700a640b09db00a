// topay-sim's options (procs/sim/sim_options.h) and assembly (sim_setup.h): the shipped config,
// clear errors for bad keys, a malformed scene, an unknown robot, a malformed event file.

#include "procs/sim/sim_options.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "procs/sim/sim_setup.h"

namespace topay::simproc {
namespace {

std::string Dir() {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/procs/sim_options";
  std::filesystem::create_directories(dir);
  return dir;
}

std::string Write(const std::string& name, const std::string& text) {
  const std::string path = Dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(SimOptions, LoadsTheShippedConfig) {
  const std::string path = std::string(TOPAY_SOURCE_DIR) + "/config/sim/sim.yaml";
  const SimOptions o = LoadSimOptions(path);
  EXPECT_EQ(o.plant.step_s, 0.002);
  EXPECT_EQ(o.plant.base.latency_s, 0.02);
  EXPECT_EQ(o.state_rate_hz, 100.0);
  EXPECT_EQ(o.lidar_file, std::string(TOPAY_SOURCE_DIR) + "/config/sim/lidar.yaml");
  EXPECT_EQ(o.scene, "tables");
  EXPECT_TRUE(std::filesystem::exists(o.robot_urdf)) << o.robot_urdf;
  EXPECT_TRUE(std::filesystem::exists(o.robot_yaml)) << o.robot_yaml;
  const SimAssembly sim = AssembleSim(o);
  EXPECT_EQ(sim.model->num_joints(), 7);
  EXPECT_NE(sim.scene_description.find("tables seed 1"), std::string::npos);
  EXPECT_TRUE(sim.core->has_lidar());
  EXPECT_NE(sim.core->contact_sensor(), nullptr);
  EXPECT_FALSE(o.follow);
  EXPECT_EQ(o.follower.max_start_offset_m, 0.3);
  EXPECT_EQ(o.follower.rebuild.trajectory.integrator.panels_per_piece, 12);
}

TEST(SimOptions, ReadsTheFollowerOptions) {
  const SimOptions o = LoadSimOptions(Write(
      "follow.yaml", "follow: true\nfollower: {max_start_offset_m: 0.5, max_start_offset_rad: 0.2, panels_per_piece: 8, "
                     "coefficient_tolerance: 1.0e-8, yaw0_tolerance_rad: 1.0e-5}\n"));
  EXPECT_TRUE(o.follow);
  EXPECT_EQ(o.follower.max_start_offset_m, 0.5);
  EXPECT_EQ(o.follower.max_start_offset_rad, 0.2);
  EXPECT_EQ(o.follower.rebuild.trajectory.integrator.panels_per_piece, 8);
  EXPECT_EQ(o.follower.rebuild.coefficient_tolerance, 1e-8);
  EXPECT_EQ(o.follower.rebuild.yaw0_tolerance_rad, 1e-5);
}

TEST(SimOptions, ReadsTheCanMode) {
  const SimOptions o = LoadSimOptions(Write("can.yaml", "plant_input: actuators\nplant_state_rate_hz: 100\n"));
  EXPECT_EQ(o.plant_input, "actuators");
  EXPECT_EQ(o.plant_state_rate_hz, 100.0);
  EXPECT_EQ(SimOptions{}.plant_input, "control_command");
}

TEST(SimOptions, NamesTheFileAndKeyOfBadOptions) {
  const auto expect_error = [](const std::string& text, const std::string& field) {
    const std::string path = Write("bad.yaml", text);
    try {
      LoadSimOptions(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(e.field(), field) << e.what();
    }
  };
  expect_error("plant: {base: {latency_s: -1}}\n", "plant.base.latency_s");
  expect_error("plant: {joints: {tau: 1}}\n", "plant.joints.tau");
  expect_error("state: {rate_hz: 0}\n", "state.rate_hz");
  expect_error("lidar: {enabled: maybe}\n", "lidar.enabled");
  expect_error("lidar: {file: lidar.yaml, options: {range_max_m: 20}}\n", "lidar");
  expect_error("speed: 3\n", "speed");
  expect_error("plant: {initial: {q_rad: [0, nan]}}\n", "plant.initial.q_rad[1]");
  expect_error("follow: yes please\n", "follow");
  expect_error("plant_input: wishes\n", "plant_input");
  expect_error("plant_input: actuators\nfollow: true\n", "plant_input");
  expect_error("plant_state_rate_hz: 0\n", "plant_state_rate_hz");
  expect_error("follower: {max_start_offset_m: 0}\n", "follower.max_start_offset_m");
  expect_error("follower: {panels_per_piece: 0}\n", "follower.panels_per_piece");
  expect_error("follower: {tolerance: 1}\n", "follower.tolerance");
  expect_error("start_utime: -1\n", "start_utime");
  // Beyond int64 (.inf, 1e300, 2^63) the conversion to start_utime was undefined behaviour
  // (config_yaml fuzz target, tests/fuzz/regressions/config_yaml/sim_start_utime_in_int64).
  expect_error("start_utime: .inf\n", "start_utime");
  expect_error("start_utime: 1e300\n", "start_utime");
  expect_error("start_utime: 9223372036854775808\n", "start_utime");
  EXPECT_EQ(LoadSimOptions(Write("utime.yaml", "start_utime: 1700000000000000\n")).start_utime, 1700000000000000);
}

SimOptions Base() {
  SimOptions o;
  o.robot_urdf = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf";
  o.robot_yaml = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml";
  o.lidar_enabled = false;
  return o;
}

TEST(SimSetup, MalformedSceneUnknownRobotAndBadEventsAreConfigErrors) {
  SimOptions scene = Base();
  scene.scene = Write("scene.json", R"({"boxes": [{"center": [0, 0, 0], "size": [1, -1, 1], "yaw": 0}]})");
  EXPECT_THROW(AssembleSim(scene), ConfigError);
  SimOptions robot = Base();
  robot.robot_urdf = Dir() + "/no_such_robot.urdf";
  try {
    AssembleSim(robot);
    ADD_FAILURE();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), robot.robot_urdf);
  }
  SimOptions events = Base();
  events.events_file = Write("events.yaml", "events:\n  - {at_s: 1, appear: {id: 5, size: [1, 1, 1]}}\n");
  try {
    AssembleSim(events);
    ADD_FAILURE();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), events.events_file);
    EXPECT_EQ(e.field(), "events[0].appear.center");
  }
  SimOptions lidar = Base();
  lidar.lidar_enabled = true;
  lidar.lidar_file = Write("lidar.yaml", "range_max_m: -3\n");
  try {
    AssembleSim(lidar);
    ADD_FAILURE();
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), lidar.lidar_file);
  }
  SimOptions joints = Base();
  joints.plant.initial.q_rad = {0.0, 0.0};
  EXPECT_THROW(AssembleSim(joints), ConfigError);
}

}  // namespace
}  // namespace topay::simproc
