// --record and --replay: a bridge run recorded through RecordingCanBus is a candump -l log of
// every frame sent and received; replayed through ReplayCanBus (at the log's timing) into a
// listen-only bridge it gives the same feedback and sends nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "drivers/arm/arm_pdo.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "drivers/can/candump_log.h"
#include "procs/canbridge/recording_can_bus.h"
#include "procs/canbridge/replay_can_bus.h"
#include "tests/procs/canbridge/canbridge_rig.h"

namespace topay::canbridge::test {
namespace {

std::string OutDir() {
  const std::string dir = std::string(TOPAY_BINARY_DIR) + "/test_out/procs/canbridge";
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ReplayCanBusTest, HandsOutFramesAtTheLogsTiming) {
  std::int64_t now_ns = 5'000'000'000;
  std::vector<can::CandumpRecord> records = {
      {1700000000000000, "can0", can::CanFrame::Standard(0x181, {1})},
      {1700000000000000, "can0", can::CanFrame::Standard(0x182, {2})},
      {1700000000100000, "can0", can::CanFrame::Standard(0x183, {3})},
      {1700000000150000, "can0", can::MakeCanErrorFrame(0x40)},
  };
  ReplayCanBus bus(records, "x.log", 2.0, [&now_ns] { return now_ns; });
  can::ReceivedCanFrame received;
  ASSERT_TRUE(bus.Receive(0, &received).ok());
  EXPECT_EQ(received.frame.id, 0x181u);
  ASSERT_TRUE(bus.Receive(0, &received).ok());
  EXPECT_EQ(received.frame.id, 0x182u);
  EXPECT_EQ(bus.Receive(0, &received).code, can::CanResult::Code::kTimeout);
  now_ns += 49'000'000;  // 0.1 s of log at speed 2 is 50 ms
  EXPECT_EQ(bus.Receive(0, &received).code, can::CanResult::Code::kTimeout);
  now_ns += 1'000'000;
  ASSERT_TRUE(bus.Receive(0, &received).ok());
  EXPECT_EQ(received.frame.id, 0x183u);
  EXPECT_EQ(received.timestamp_ns, now_ns);
  EXPECT_FALSE(bus.finished());
  now_ns += 25'000'000;
  EXPECT_EQ(bus.Receive(0, &received).code, can::CanResult::Code::kTimeout);  // error frames: state only
  EXPECT_TRUE(bus.finished());
  EXPECT_EQ(bus.status().state, can::CanBusState::kBusOff);
  EXPECT_EQ(bus.Send(can::CanFrame::Standard(1)).code, can::CanResult::Code::kInvalidFrame);
  EXPECT_EQ(bus.status().frames_sent, 0u);
}

// A bridge the launcher restarts continues its run's log (twenty-seventh session: the log of a
// mission with kill-canbridge held only the traffic since the last restart).
TEST(CanbridgeRecordReplayTest, ARestartedRecorderAppendsToTheLog) {
  const std::string path = OutDir() + "/record_append.log";
  std::filesystem::remove(path);
  auto wire = std::make_shared<MemoryWire>();
  std::int64_t now_ns = 1'000'000'000;
  for (int run = 0; run < 2; ++run) {
    RecordingCanBus recorder(std::make_unique<MemoryCanBus>(wire, "bridge"), path, "can0", [&now_ns] { return now_ns; });
    const can::CanFrame frame =
        can::CanFrame::Standard(static_cast<std::uint32_t>(0x201 + run), {static_cast<std::uint8_t>(run)});
    ASSERT_TRUE(recorder.Send(frame).ok());
    now_ns += 1'000'000'000;
  }
  std::ifstream file(path);
  std::vector<can::CandumpRecord> records;
  std::string error;
  ASSERT_TRUE(can::ReadCandumpLog(file, &records, &error)) << error;
  ASSERT_EQ(records.size(), 2u) << "the second recorder kept the first one's line";
  EXPECT_EQ(records[0].frame.id, 0x201u);
  EXPECT_EQ(records[1].frame.id, 0x202u);
  EXPECT_LT(records[0].timestamp_us, records[1].timestamp_us);
}

TEST(CanbridgeRecordReplayTest, RecordedRunReplaysIntoTheSameFeedback) {
  const std::string path = OutDir() + "/record_replay.log";
  std::filesystem::remove(path);  // the recorder appends
  double t = 2000.0;
  auto wire = std::make_shared<MemoryWire>();
  wire->now_ns = [&t] { return static_cast<std::int64_t>(t * 1e9); };
  auto inner = std::make_unique<MemoryCanBus>(wire, "bridge");
  MemoryCanBus* inner_bus = inner.get();
  MemoryCanBus peer_bus(wire, "peers");
  const CanbridgeOptions options;
  const RobotModel model = ShippedRobot();
  std::int64_t lines = 0;
  std::uint64_t frames_sent = 0, frames_received = 0;
  {
    RecordingCanBus recorder(std::move(inner), path, "can0", [&t] { return static_cast<std::int64_t>(t * 1e9); });
    CanbridgeNode node(options, model, &recorder);
    Peers peers(&peer_bus, options.base.node_id, options.drives.node_ids);
    peers.PowerOn();
    for (int i = 0; i < 1200; ++i) {  // 6 s: start-up, then commands
      if (node.state() == BridgeState::kRunning && i % 4 == 0) {
        control_command_t msg{};
        msg.v_mps = 0.3;
        msg.omega_radps = 0.1;
        msg.num_joints = 7;
        msg.qdot_radps.assign(7, 0.2);
        node.OnCommand(msg, t);
      }
      node.Cycle(t, static_cast<std::int64_t>(t * 1e6));
      peers.Step(t);
      t += options.cycle_period_s;
    }
    ASSERT_EQ(node.state(), BridgeState::kRunning) << node.stop_reason();
    lines = recorder.lines_written();
    frames_sent = inner_bus->status().frames_sent;
    frames_received = inner_bus->status().frames_received;
  }
  std::ifstream file(path);
  std::vector<can::CandumpRecord> records;
  std::string error;
  ASSERT_TRUE(can::ReadCandumpLog(file, &records, &error)) << error;
  EXPECT_EQ(static_cast<std::int64_t>(records.size()), lines);
  EXPECT_EQ(records.size(), frames_sent + frames_received);
  int syncs = 0, rpdos = 0, tpdos = 0;
  std::optional<double> last_position, last_v;
  const cia402::JointUnits units;
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(records[i].interface, "can0");
    if (i > 0) {  // received frames carry their receive time, read up to a cycle later
      EXPECT_GE(records[i].timestamp_us, records[i - 1].timestamp_us - 5000);
    }
    const can::CanFrame& f = records[i].frame;
    syncs += f.id == 0x080;
    rpdos += f.id == 0x201;
    if (f.id == 0x181) {
      ++tpdos;
      last_position = cia402::DecodeTpdo1(f, units, nullptr)->position_rad;
    }
    if (f.id == 0x290) {
      const auto w = base::DecodeWheelSpeeds(f, 16, nullptr);
      last_v = base::WheelSpeedsToUnicycle({w->left_rad_per_s, w->right_rad_per_s}, {}).v_m_per_s;
    }
  }
  EXPECT_GT(syncs, 500);
  EXPECT_GT(rpdos, 500);
  EXPECT_GT(tpdos, 500);
  ASSERT_TRUE(last_position && last_v);
  EXPECT_NEAR(*last_v, 0.3, 2e-3);

  // Replay into a listen-only bridge on a simulated clock.
  double now = 0.0;
  ReplayCanBus replay(ReplayCanBus::ReadLog(path), path, 1.0, [&now] { return static_cast<std::int64_t>(now * 1e9); });
  CanbridgeNode node(options, model, &replay, /*listen_only=*/true);
  joint_state_t joints{};
  base_velocity_t base{};
  drive_status_t status{};
  int joint_messages = 0;
  while (!replay.finished() && now < 10.0) {
    const CanbridgeOutputs& out = node.Cycle(now, static_cast<std::int64_t>(now * 1e6));
    if (out.joint_state) joints = *out.joint_state, ++joint_messages;
    if (out.base_velocity) base = *out.base_velocity;
    if (out.status) status = *out.status;
    now += options.cycle_period_s;
  }
  node.Cycle(now, 0);
  ASSERT_TRUE(replay.finished());
  EXPECT_GT(joint_messages, 500);
  EXPECT_NEAR(joints.position_rad[0], *last_position, 1e-9);
  EXPECT_NEAR(joints.velocity_radps[0], 0.2, 1e-4);
  EXPECT_NEAR(base.v_mps, *last_v, 1e-9);
  EXPECT_EQ(node.state(), BridgeState::kReplay);
  EXPECT_EQ(status.state, drive_status_t::REPLAY);
  EXPECT_EQ(status.drive_state[0], "Operation enabled");
  EXPECT_EQ(node.frame_counters().malformed(), 0);
  EXPECT_EQ(node.frame_counters().unknown(), 0);
  EXPECT_GT(node.frame_counters().host_frames(), 1000);  // the bridge's own frames in the log
  EXPECT_EQ(replay.status().frames_sent, 0u);
  EXPECT_EQ(node.tx_refused(), 0);
}

}  // namespace
}  // namespace topay::canbridge::test
