// The plant's checkpoint (procs/sim/plant_checkpoint.h): round trip through the file, clear
// errors for a malformed one, and a simulator assembled with it starts the robot where the
// checkpoint says (docs/reliability.md finding 6: kill -9 of topay-sim used to put the robot
// back at the scene's start).

#include "procs/sim/plant_checkpoint.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/common/error.h"
#include "procs/runtime/process_options.h"
#include "procs/sim/sim_options.h"
#include "procs/sim/sim_setup.h"

namespace topay::simproc {
namespace {

std::string Dir() {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/procs/plant_checkpoint";
  std::filesystem::create_directories(dir);
  return dir;
}

PlantCheckpoint Sample() {
  PlantCheckpoint c;
  c.utime = 1'700'000'000'123'456;
  c.x_m = 1.25;
  c.y_m = -0.5;
  c.yaw_rad = 0.1 + 1e-13;
  c.q_rad = {0.1, -0.2, 0.3, -1.2, 0.5, 0.6, -0.7};
  c.gripper = 0.75;
  return c;
}

void ExpectSame(const PlantCheckpoint& a, const PlantCheckpoint& b) {
  EXPECT_EQ(a.utime, b.utime);
  EXPECT_EQ(a.x_m, b.x_m);
  EXPECT_EQ(a.y_m, b.y_m);
  EXPECT_EQ(a.yaw_rad, b.yaw_rad);
  EXPECT_EQ(a.q_rad, b.q_rad);
  EXPECT_EQ(a.gripper, b.gripper);
}

TEST(PlantCheckpoint, RoundTripsThroughTheFileExactly) {
  const std::string path = Dir() + "/round_trip.json";
  std::filesystem::remove(path);
  EXPECT_FALSE(ReadPlantCheckpoint(path));  // the first start: none
  ASSERT_EQ(WritePlantCheckpoint(path, Sample()), "");
  const std::optional<PlantCheckpoint> read = ReadPlantCheckpoint(path);
  ASSERT_TRUE(read);
  ExpectSame(*read, Sample());
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

TEST(PlantCheckpoint, MalformedOnesAreErrorsNamingTheField) {
  struct Case {
    std::string text, field;
  };
  const Case cases[] = {
      {"{", ""},
      {R"({"utime": 1, "x_m": 0, "y_m": 0, "yaw_rad": 0, "q_rad": [0], "gripper": 2})", "gripper"},
      {R"({"utime": 1, "x_m": 0, "y_m": 0, "yaw_rad": 0, "q_rad": [0, "a"], "gripper": 0})", "q_rad[1]"},
      {R"({"utime": 1, "x_m": 0, "y_m": 0, "q_rad": [0], "gripper": 0})", "yaw_rad"},
      {R"({"utime": -5, "x_m": 0, "y_m": 0, "yaw_rad": 0, "q_rad": [0], "gripper": 0})", "utime"},
      {R"({"utime": 1, "x_m": 0, "y_m": 0, "yaw_rad": 0, "q_rad": [0], "gripper": 0, "z_m": 1})", "z_m"},
  };
  for (const Case& c : cases) {
    try {
      ParsePlantCheckpoint(c.text, "cp.json");
      ADD_FAILURE() << "no error for " << c.text;
    } catch (const ConfigError& e) {
      EXPECT_EQ(e.file(), "cp.json");
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos) << c.field << " in " << e.what();
    }
  }
}

TEST(PlantCheckpoint, TheCheckpointOfAPlantStateIsItsPoseJointsAndGripper) {
  sim::PlantState truth;
  truth.state.x_m = 2.0;
  truth.state.y_m = 3.0;
  truth.state.yaw_rad = -1.0;
  truth.state.q_rad = Eigen::VectorXd::LinSpaced(7, -0.3, 0.3);
  truth.gripper = 0.4;
  truth.v_mps = 0.8;
  const PlantCheckpoint c = CheckpointOf(truth, 42);
  EXPECT_EQ(c.utime, 42);
  EXPECT_EQ(c.x_m, 2.0);
  EXPECT_EQ(c.yaw_rad, -1.0);
  ASSERT_EQ(c.q_rad.size(), 7u);
  EXPECT_EQ(c.q_rad[6], 0.3);
  EXPECT_EQ(c.gripper, 0.4);
}

SimOptions Options() {
  SimOptions o = LoadSimOptions(std::string(TOPAY_SOURCE_DIR) + "/config/sim/sim.yaml");
  procs::DefaultRobotFiles(std::string(TOPAY_SOURCE_DIR) + "/config", &o.robot_urdf, &o.robot_yaml);
  return o;
}

TEST(PlantCheckpoint, ASimulatorStartsWhereItsCheckpointSays) {
  SimOptions o = Options();
  o.checkpoint_file = Dir() + "/assemble.json";
  std::filesystem::remove(o.checkpoint_file);
  const SimAssembly fresh = AssembleSim(o);
  EXPECT_TRUE(fresh.resumed_from.empty());
  EXPECT_EQ(fresh.core->plant().state().state.x_m, o.plant.initial.x_m);

  PlantCheckpoint c = Sample();
  ASSERT_EQ(WritePlantCheckpoint(o.checkpoint_file, c), "");
  const SimAssembly resumed = AssembleSim(o);
  EXPECT_NE(resumed.resumed_from.find("assemble.json (1.250, -0.500, 0.100 rad)"), std::string::npos)
      << resumed.resumed_from;
  const sim::PlantState& truth = resumed.core->plant().state();
  EXPECT_EQ(truth.state.x_m, 1.25);
  EXPECT_EQ(truth.state.y_m, -0.5);
  EXPECT_EQ(truth.state.q_rad(3), -1.2);
  EXPECT_EQ(truth.gripper, 0.75);
  EXPECT_EQ(truth.v_mps, 0.0);  // at rest

  c.q_rad.pop_back();  // a checkpoint of another robot: refused, naming the file
  ASSERT_EQ(WritePlantCheckpoint(o.checkpoint_file, c), "");
  try {
    AssembleSim(o);
    ADD_FAILURE() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), o.checkpoint_file);
  }
}

}  // namespace
}  // namespace topay::simproc
