// The real topay-canbridge in a private network namespace on the user-space udp:// CAN bus, with
// an in-test peer answering as the base and the seven drives: it starts them, passes
// CONTROL_COMMAND to the bus, publishes DRIVE_STATUS, stops on a stale command and on a drive
// fault, resets on DRIVE_COMMAND, records the bus, and exits 0 on SIGINT with its report.
#include <gtest/gtest.h>

#include <csignal>
#include <optional>

#include "drivers/can/can_url.h"
#include "tests/procs/canbridge/bus_peers.h"
#include "tests/procs/graph_test_support.h"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"
#include "topay/drive_status_t.hpp"

namespace topay::canbridge::test {
namespace {

using topay::test::Clock;
using topay::test::SecondsSince;

class Harness {
 public:
  Harness(can::CanBus* bus, lcm::LCM* lcm) : peers(bus, 16, {1, 2, 3, 4, 5, 6, 7}), lcm_(lcm) {
    lcm_->subscribe(std::string(channels::DRIVE_STATUS), &Harness::OnStatus, this);
  }
  // Steps the peers and LCM for `seconds` (publishing `command` at 50 Hz when given) or until pred().
  template <class Pred>
  bool Run(double seconds, const std::optional<control_command_t>& command, Pred pred) {
    const Clock::time_point start = Clock::now();
    double last_command = -1.0;
    while (SecondsSince(start) < seconds) {
      const double now = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
      peers.Step(now);
      if (command && now - last_command >= 0.02) {
        last_command = now;
        lcm_->publish(std::string(channels::CONTROL_COMMAND), &*command);
      }
      lcm_->handleTimeout(1);
      if (pred()) return true;
    }
    return pred();
  }
  void OnStatus(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    const auto msg = CheckedDecode<drive_status_t>(rbuf->data, rbuf->data_size, nullptr);
    if (msg) status = *msg, ++statuses;
  }
  Peers peers;
  std::optional<drive_status_t> status;
  int statuses = 0;

 private:
  lcm::LCM* lcm_;
};

control_command_t Command(double v, double qdot) {
  control_command_t msg{};
  msg.v_mps = v;
  msg.num_joints = 7;
  msg.qdot_radps.assign(7, qdot);
  return msg;
}

TEST(CanbridgeProcessTest, DrivesPeersOnTheUdpBus) {
  std::string why;
  if (!topay::test::EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = topay::test::TestDir("bridge");
  const std::string url = "udp://239.255.1.1:9000";
  std::string error;
  std::unique_ptr<can::CanBus> bus = can::OpenCanBus(url, can::CanBusOptions{}, &error);
  ASSERT_TRUE(bus) << error;
  lcm::LCM lcm;
  ASSERT_TRUE(lcm.good());
  Harness h(bus.get(), &lcm);
  h.peers.PowerOn();
  const pid_t pid = topay::test::Spawn(
      {topay::test::BinDir() + "/topay-canbridge", "--can", url, "--record", dir + "/bus.log", "--config",
       std::string(TOPAY_SOURCE_DIR) + "/config/canbridge/canbridge.yaml"},
      dir + "/out.txt");
  const auto state_is = [&h](std::int8_t state) { return [&h, state] { return h.status && h.status->state == state; }; };
  ASSERT_TRUE(h.Run(15.0, std::nullopt, state_is(drive_status_t::RUNNING)))
      << (h.status ? h.status->stop_reason : "no DRIVE_STATUS") << "\n" << topay::test::ReadText(dir + "/out.txt");
  EXPECT_EQ(h.status->can_url, url);
  EXPECT_EQ(h.status->num_drives, 7);
  EXPECT_EQ(h.status->node_id[6], 7);
  EXPECT_EQ(h.status->drive_state[0], "Operation enabled");
  for (const DrivePeer& drive : h.peers.drives) EXPECT_EQ(drive.model.state(), cia402::DriveState::kOperationEnabled);
  EXPECT_EQ(h.peers.base.mode(), base::BaseMode::kCanCommand);

  // Commands reach the bus (clamped: 3 m/s -> 1 m/s).
  h.Run(2.5, Command(3.0, 0.4), [] { return false; });
  ASSERT_FALSE(h.peers.base.commands.empty());
  EXPECT_NEAR(h.peers.base.commands.back().v_m_per_s, 1.0, 1e-9);
  EXPECT_NEAR(h.peers.drives[3].target_velocity, 0.4, 1e-4);
  EXPECT_EQ(h.status->state, drive_status_t::RUNNING);
  EXPECT_GT(h.status->clamp_count, 0);
  EXPECT_GT(h.status->commands_received, 50);

  // Commands stop: zero + quick stop, reported.
  ASSERT_TRUE(h.Run(2.0, std::nullopt, state_is(drive_status_t::STOPPED)));
  EXPECT_NE(h.status->stop_reason.find("stale"), std::string::npos) << h.status->stop_reason;
  h.Run(0.3, std::nullopt, [] { return false; });
  EXPECT_EQ(h.peers.base.commands.back().v_m_per_s, 0.0);
  EXPECT_EQ(h.peers.base.mode(), base::BaseMode::kQuickStop);
  // Zero commands: back to running.
  ASSERT_TRUE(h.Run(5.0, Command(0.0, 0.0), state_is(drive_status_t::RUNNING))) << h.status->stop_reason;

  // A drive fault: FAULT until a fault reset on DRIVE_COMMAND.
  std::vector<can::CanFrame> out;
  h.peers.drives[4].Fault(0x4310, &out);
  h.peers.Send(out);
  ASSERT_TRUE(h.Run(2.0, Command(0.0, 0.0), state_is(drive_status_t::FAULT)));
  EXPECT_EQ(h.status->last_emcy_code[4], 0x4310);
  drive_command_t reset{};
  reset.command = drive_command_t::FAULT_RESET;
  reset.source = "test";
  lcm.publish(std::string(channels::DRIVE_COMMAND), &reset);
  ASSERT_TRUE(h.Run(5.0, Command(0.0, 0.0), state_is(drive_status_t::RUNNING))) << h.status->stop_reason;
  EXPECT_GE(h.statuses, 30);

  kill(pid, SIGINT);
  const int status = topay::test::WaitFor(pid, 10.0);
  ASSERT_NE(status, -1);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  const std::string output = topay::test::ReadText(dir + "/out.txt");
  EXPECT_NE(output.find("command -> CAN frame latency: median"), std::string::npos) << output;
  EXPECT_NE(output.find("cycle jitter: median"), std::string::npos) << output;
  const std::string log = topay::test::ReadText(dir + "/bus.log");
  EXPECT_NE(log.find(" can0 080#\n"), std::string::npos);       // SYNC sent
  EXPECT_NE(log.find(" can0 185#"), std::string::npos);          // TPDO1 of node 5 received
  EXPECT_NE(log.find(" can0 605#2F606000"), std::string::npos);  // SDO write 0x6060 to node 5

  // The recorded run replayed (5x): feedback on LCM, nothing sent, exit 0 at the end.
  int joint_states = 0;
  lcm.subscribeFunction(
      std::string(channels::JOINT_STATE),
      +[](const lcm::ReceiveBuffer*, const std::string&, int* count) { ++*count; }, &joint_states);
  h.Run(0.2, std::nullopt, [] { return false; });  // frames of the first bridge still queued
  const std::size_t frames_before = h.peers.received_frames.size();
  const pid_t replay = topay::test::Spawn({topay::test::BinDir() + "/topay-canbridge", "--replay", dir + "/bus.log",
                                           "--replay-speed", "5", "--can", url},
                                          dir + "/replay.txt");
  int replay_status = -1;
  h.Run(20.0, std::nullopt, [&] {
    int s = 0;
    if (waitpid(replay, &s, WNOHANG) == replay) replay_status = s;
    return replay_status != -1;
  });
  ASSERT_NE(replay_status, -1) << topay::test::ReadText(dir + "/replay.txt");
  EXPECT_TRUE(WIFEXITED(replay_status) && WEXITSTATUS(replay_status) == 0) << topay::test::ReadText(dir + "/replay.txt");
  h.Run(0.2, std::nullopt, [] { return false; });
  EXPECT_GT(joint_states, 50);  // one per cycle with new TPDOs: ~0.7 s of cycles
  EXPECT_EQ(h.status->state, drive_status_t::REPLAY);
  EXPECT_EQ(h.peers.received_frames.size(), frames_before);  // the replay sent nothing on the bus
  EXPECT_NE(topay::test::ReadText(dir + "/replay.txt").find("replay://"), std::string::npos);
}

TEST(CanbridgeProcessTest, BadUsageAndConfig) {
  std::string why;
  if (!topay::test::EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = topay::test::TestDir("bad");
  const std::string bin = topay::test::BinDir() + "/topay-canbridge";
  int status = topay::test::WaitFor(topay::test::Spawn({bin, "--no-such-flag"}, dir + "/usage.txt"), 10.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2);
  status = topay::test::WaitFor(topay::test::Spawn({bin, "--can", "udp://10.0.0.1:9000"}, dir + "/url.txt"), 10.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
  EXPECT_NE(topay::test::ReadText(dir + "/url.txt").find("not an IPv4 multicast"), std::string::npos);
  status = topay::test::WaitFor(topay::test::Spawn({bin, "--replay", dir + "/missing.log"}, dir + "/replay.txt"), 10.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1);
}

}  // namespace
}  // namespace topay::canbridge::test
