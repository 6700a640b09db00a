// Determinism from a recorded command log (procs/sim/command_replay.h): the same scene, seeds
// and log give the same states and scans (digests) in two runs; another seed does not.

#include "procs/sim/command_replay.h"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <cmath>
#include <filesystem>

#include "core/common/random.h"
#include "procs/sim/output_digest.h"
#include "procs/sim/sim_setup.h"
#include "topay_msgs/channels.h"

namespace topay::simproc {
namespace {

// A 6 s log of 50 Hz commands with jittered times (as a real tracker's), a few bad ones, a 0.5 s
// gap (the drives brake), and other traffic on other channels.
std::string WriteCommandLog(const std::string& name) {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/procs/command_replay";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  lcm::LogFile log(path, "w");
  EXPECT_TRUE(log.good());
  Rng rng(3);
  std::int64_t event_number = 0;
  const std::int64_t t0 = 1'800'000'000'000'000;
  for (int i = 0; i < 300; ++i) {
    if (i >= 150 && i < 175) continue;  // gap
    control_command_t cmd{};
    cmd.utime = t0 + i * 20'000 + rng.UniformInt(0, 1500);
    cmd.v_mps = 0.6 * std::sin(0.02 * i);
    cmd.omega_radps = 0.4 * std::cos(0.03 * i);
    cmd.num_joints = 7;
    cmd.qdot_radps.assign(7, 0.2 * std::sin(0.05 * i));
    cmd.gripper = i > 200 ? 1.0 : 0.0;
    if (i == 100) cmd.v_mps = NAN;  // rejected
    std::vector<std::uint8_t> bytes(cmd.getEncodedSize());
    cmd.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    lcm::LogEvent event;
    event.eventnum = event_number++;
    event.timestamp = cmd.utime;
    event.channel = std::string(channels::CONTROL_COMMAND);
    event.datalen = static_cast<std::int32_t>(bytes.size());
    event.data = bytes.data();
    log.writeEvent(&event);
    if (i % 50 == 0) {
      lcm::LogEvent other = event;
      other.eventnum = event_number++;
      other.channel = "OTHER";
      log.writeEvent(&other);
    }
  }
  return path;
}

SimOptions Options(std::uint64_t seed) {
  SimOptions o;
  o.robot_urdf = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf";
  o.robot_yaml = std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml";
  o.scene = "cuboids";
  o.scene_seed = 2;
  o.seed = seed;
  o.plant.wheels.slip_stddev = 0.03;
  o.pose_noise.xy_stddev_m = 0.01;
  o.pose_noise.yaw_stddev_rad = 0.005;
  o.events_file = std::string(TOPAY_SOURCE_DIR) + "/config/sim/events_example.yaml";
  o.lidar_file = std::string(TOPAY_SOURCE_DIR) + "/config/sim/lidar.yaml";
  return o;
}

struct ReplayRun {
  OutputDigest digest;
  std::int64_t rejected = 0;
  double final_x_m = 0.0;
};

ReplayRun Replay(const std::vector<TimedCommand>& commands, std::uint64_t seed) {
  SimAssembly sim = AssembleSim(Options(seed));
  ReplayRun run;
  sim.core->SetListener(&run.digest);
  run.rejected = ReplayCommands(sim.core.get(), commands, commands.front().utime, 7.0);
  run.final_x_m = sim.core->plant().state().state.x_m;
  EXPECT_NEAR(sim.core->time_s(), 7.0, 1e-9);
  return run;
}

TEST(CommandReplay, ReadsOnlyTheCommandsOfTheLog) {
  std::int64_t skipped = 0;
  const std::vector<TimedCommand> commands =
      ReadCommandLog(WriteCommandLog("read.lcmlog"), std::string(channels::CONTROL_COMMAND), &skipped);
  EXPECT_EQ(commands.size(), 275u);
  EXPECT_EQ(skipped, 0);
  EXPECT_TRUE(std::isnan(commands[100].command.v_mps));
}

TEST(CommandReplay, SameLogSameSeedsGiveTheSameStatesAndScans) {
  const std::vector<TimedCommand> commands =
      ReadCommandLog(WriteCommandLog("same.lcmlog"), std::string(channels::CONTROL_COMMAND));
  const ReplayRun a = Replay(commands, 11);
  const ReplayRun b = Replay(commands, 11);
  const ReplayRun c = Replay(commands, 12);
  EXPECT_EQ(a.rejected, 1);
  EXPECT_EQ(a.digest.num_states, 700);
  EXPECT_EQ(a.digest.num_scans, 70);  // 10 Hz LiDAR
  EXPECT_EQ(a.digest.states(), b.digest.states());
  EXPECT_EQ(a.digest.scans(), b.digest.scans());
  EXPECT_EQ(a.digest.contacts(), b.digest.contacts());
  EXPECT_EQ(a.digest.events(), b.digest.events());
  EXPECT_EQ(a.digest.num_scans, b.digest.num_scans);
  EXPECT_EQ(a.final_x_m, b.final_x_m);
  EXPECT_NE(a.digest.states(), c.digest.states()) << "the seed must change the slip and the pose noise";
  EXPECT_NE(a.final_x_m, 0.0) << "the robot must have moved";
}

}  // namespace
}  // namespace topay::simproc
