// The real topay-motorsim and topay-sim (CAN mode) in a private network namespace (skipped, with
// the reason, where none can be made), on a udp:// CAN bus, with an in-test host made of the
// drivers' host helpers: start-up SDO writes to a drive answered, NMT start, every drive
// enabled from its TPDO1 (cia402_host), the base switched to CAN command mode; a commanded
// motion moves the plant (SIM_PLANT_STATE) as commanded and the feedback frames report it; a
// drive fault injected on MOTORSIM_FAULT gives EMCY + Fault and stops that joint; the final
// report counts it. No timed speed assertions: only loose bounds on distances.

#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_host.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/startup_sdo.h"
#include "drivers/arm/sync.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "drivers/can/can_url.h"
#include "graph_test_support.h"
#include "topay/motorsim_fault_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

constexpr const char* kBus = "udp://239.255.1.1:9000";
constexpr int kBaseNode = 16;

struct PlantListener {
  std::optional<robot_state_t> last;
  void On(const lcm::ReceiveBuffer*, const std::string&, const robot_state_t* m) { last = *m; }
};

// The host side: what the bridge will do, in a few lines of the drivers' helpers.
class TestHost {
 public:
  explicit TestHost(can::CanBus* bus) : bus_(bus) {}
  std::array<std::optional<cia402::DriveState>, 8> state{};
  std::array<double, 8> position{};
  std::array<double, 8> target{};
  std::array<int, 8> emcy{};
  std::optional<base::BaseMode> base_mode;
  double wheel_v = 0.0;
  double v = 0.0;
  bool reset_faults = true;  // false: a drive in a fault state gets no RPDO (the host leaves it)
  std::vector<can::CanFrame> sdo_replies;

  void Send(const std::optional<can::CanFrame>& f) {
    if (f) bus_->Send(*f);
  }
  void Drain() {
    can::ReceivedCanFrame r;
    while (bus_->Receive(0.0, &r).ok()) Handle(r.frame);
  }
  // One 5 ms cycle: RPDO1 per drive towards Operation enabled, SYNC, base request/command.
  void Cycle() {
    Drain();
    for (int j = 1; j <= 7; ++j) {
      if (!state[j]) continue;
      const bool faulted = state[j] == cia402::DriveState::kFault || state[j] == cia402::DriveState::kFaultReactionActive;
      if (faulted && !reset_faults) {  // a host keeps its setpoint stream (0x0000: no reset edge)
        Send(cia402::EncodeRpdo1({j, 0x0000, 0.0}, {}, nullptr));
        continue;
      }
      const cia402::HostStep step = cia402::NextStepTowardsOperationEnabled(*state[j], previous_[j]);
      previous_[j] = step.controlword;
      const bool enabled = state[j] == cia402::DriveState::kOperationEnabled;
      Send(cia402::EncodeRpdo1({j, step.controlword, enabled ? target[j] : 0.0}, {}, nullptr));
    }
    Send(canopen::EncodeSync({}, nullptr));
    if (cycle_ % 20 == 0) {
      Send(canopen::EncodeNmt({canopen::NmtCommand::kStartRemoteNode, 0}, nullptr));
      if (base_mode == base::BaseMode::kQuickStop) {  // a stalled test (loaded machine) tripped the watchdog
        Send(base::EncodeModeRequest(base::ModeRequest::kStandby, kBaseNode, nullptr));
      }
      if (base_mode != base::BaseMode::kCanCommand) {
        Send(base::EncodeModeRequest(base::ModeRequest::kCanCommand, kBaseNode, nullptr));
      }
    }
    Send(base::EncodeVelocityCommand({base_mode == base::BaseMode::kCanCommand ? v : 0.0, 0.0, counter_++}, kBaseNode,
                                     nullptr));
    ++cycle_;
  }

 private:
  void Handle(const can::CanFrame& f) {
    if (f.error) return;
    if (const auto s = base::DecodeStatus(f, kBaseNode, nullptr)) base_mode = s->mode;
    if (const auto w = base::DecodeWheelSpeeds(f, kBaseNode, nullptr)) {
      wheel_v = 0.1 * (w->left_rad_per_s + w->right_rad_per_s) / 2.0;  // default radius 0.1 m
    }
    const auto cob = canopen::ClassifyCobId(f.id, nullptr);
    if (!cob || cob->node_id < 1 || cob->node_id > 7) return;
    if (cob->function == canopen::CanopenFunction::kTpdo1) {
      if (const auto t = cia402::DecodeTpdo1(f, {}, nullptr)) {
        state[cob->node_id] = cia402::DecodeStatusword(t->statusword, nullptr);
        position[cob->node_id] = t->position_rad;
      }
    } else if (cob->function == canopen::CanopenFunction::kEmcy) {
      if (const auto e = canopen::DecodeEmcy(f, nullptr); e && e->error_code != 0) ++emcy[cob->node_id];
    } else if (cob->function == canopen::CanopenFunction::kSdoTx) {
      sdo_replies.push_back(f);
    }
  }

  can::CanBus* bus_;
  std::array<std::uint16_t, 8> previous_{};
  int cycle_ = 0;
  std::uint8_t counter_ = 0;
};

class MotorsimProcess : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir("motorsim");
    WriteText(dir_ + "/empty.json", R"({"boxes": [{"center": [30, 30, 0.5], "size": [1, 1, 1], "yaw": 0}]})");
    WriteText(dir_ + "/sim.yaml", "lidar: {enabled: false}\nplant_input: actuators\n");
    sim_ = Spawn({BinDir() + "/topay-sim", "--config", dir_ + "/sim.yaml", "--scene", dir_ + "/empty.json", "--name",
                  "sim-can"},
                 dir_ + "/sim.txt");
    motorsim_ = Spawn({BinDir() + "/topay-motorsim", "--can", kBus, "--config",
                       std::string(TOPAY_SOURCE_DIR) + "/config/sim/motorsim.yaml", "--name", "motorsim-under-test"},
                      dir_ + "/motorsim.txt");
    watcher_ = std::make_unique<HeartbeatWatcher>();
    watcher_->lcm().subscribe(std::string(channels::SIM_PLANT_STATE), &PlantListener::On, &plant_);
    std::string error;
    bus_ = can::OpenCanBus(kBus, can::CanBusOptions{}, &error);
    ASSERT_NE(bus_, nullptr) << error;
    host_ = std::make_unique<TestHost>(bus_.get());
    ASSERT_TRUE(watcher_->SpinUntil(
        [&] { return watcher_->last.contains("sim-can") && watcher_->last.contains("motorsim-under-test"); }, 10.0))
        << ReadText(dir_ + "/sim.txt") << ReadText(dir_ + "/motorsim.txt");
  }
  void TearDown() override { StopProcesses({motorsim_, sim_}); }

  // Runs host cycles every 5 ms for `seconds` (LCM handled in between).
  void Run(double seconds) {
    const Clock::time_point start = Clock::now();
    while (SecondsSince(start) < seconds) {
      host_->Cycle();
      watcher_->lcm().handleTimeout(5);
    }
  }
  // Startup SDO writes to `node`, one at a time; the number confirmed. RPDO1's deadline 0.5 s:
  // this test's host is the test itself, which a loaded machine may stall for more than the
  // bridge's 50 ms (the deadline has its own tests: drive_node_test).
  static cia402::StartupOptions HostStartup() {
    cia402::StartupOptions options;
    options.rpdo_deadline_ms = 500;
    return options;
  }
  int StartupWrites(int node) {
    const auto writes = cia402::StartupSdoWrites(node, HostStartup(), nullptr);
    int confirmed = 0;
    for (const cia402::SdoWrite& w : *writes) {
      host_->sdo_replies.clear();
      host_->Send(canopen::EncodeSdoDownloadRequest(cia402::ToDownloadRequest(node, w), nullptr));
      const Clock::time_point sent = Clock::now();
      while (host_->sdo_replies.empty() && SecondsSince(sent) < 1.0) {
        host_->Drain();
        watcher_->lcm().handleTimeout(2);
      }
      if (host_->sdo_replies.empty()) break;
      const auto reply = canopen::DecodeSdoServerReply(host_->sdo_replies.front(), nullptr);
      if (!reply || !std::holds_alternative<canopen::SdoDownloadResponse>(*reply)) break;
      ++confirmed;
    }
    return confirmed;
  }

  std::string dir_;
  pid_t sim_ = -1, motorsim_ = -1;
  std::unique_ptr<HeartbeatWatcher> watcher_;
  PlantListener plant_;
  std::unique_ptr<can::CanBus> bus_;
  std::unique_ptr<TestHost> host_;
};

TEST_F(MotorsimProcess, HostEnablesTheDrivesAndTheCommandedMotionMovesThePlant) {
  // The drives answer the start-up writes (in pre-operational, before any NMT start).
  const int expected = static_cast<int>(cia402::StartupSdoWrites(1, HostStartup(), nullptr)->size());
  EXPECT_EQ(StartupWrites(1), expected) << ReadText(dir_ + "/motorsim.txt");

  Run(1.0);  // NMT start, enable sequence, CAN command mode
  for (int j = 1; j <= 7; ++j) {
    ASSERT_EQ(host_->state[j], cia402::DriveState::kOperationEnabled) << "joint " << j << "\n"
                                                                      << ReadText(dir_ + "/motorsim.txt");
  }
  ASSERT_EQ(host_->base_mode, base::BaseMode::kCanCommand);
  ASSERT_TRUE(plant_.last);
  const robot_state_t before = *plant_.last;

  host_->v = 0.25;
  host_->target[1] = -0.3;  // q1 starts at 2.9 (stow), 0.2 below its upper limit
  host_->target[7] = -0.2;  // the wrist: turning it moves no sphere into the chassis
  Run(2.0);
  ASSERT_TRUE(plant_.last);
  const robot_state_t& after = *plant_.last;
  EXPECT_GT(after.pose.x_m - before.pose.x_m, 0.2) << "0.25 m/s for 2 s minus latency and lag";
  EXPECT_LT(after.pose.x_m - before.pose.x_m, 0.55);
  EXPECT_NEAR(after.velocity.v_mps, 0.25, 0.03);
  EXPECT_LT(after.joints.position_rad[0] - before.joints.position_rad[0], -0.25);
  EXPECT_LT(after.joints.position_rad[6] - before.joints.position_rad[6], -0.15);
  EXPECT_NEAR(after.joints.position_rad[1], before.joints.position_rad[1], 1e-3) << "joint 2 not commanded";
  // The feedback frames report the plant: TPDO1 positions and the wheel speeds.
  EXPECT_NEAR(host_->position[1], after.joints.position_rad[0], 0.05);
  EXPECT_NEAR(host_->wheel_v, 0.25, 0.03);

  // A drive fault on joint 1 from MOTORSIM_FAULT: EMCY, Fault, the joint stops; the others go on.
  motorsim_fault_t fault{};
  fault.kind = motorsim_fault_t::DRIVE_FAULT;
  fault.joint = 1;
  watcher_->lcm().publish(std::string(channels::MOTORSIM_FAULT), &fault);
  host_->reset_faults = false;  // joint 1 keeps its -0.3 rad/s target: the faulted drive must not follow it
  Run(1.0);
  EXPECT_EQ(host_->emcy[1], 1);
  EXPECT_EQ(host_->state[1], cia402::DriveState::kFault);
  EXPECT_EQ(host_->state[7], cia402::DriveState::kOperationEnabled);

  // Bus-off from MOTORSIM_FAULT: the host's bus sees the error frame (bus-off: its sends are
  // refused), then the restart frame (error-active again).
  motorsim_fault_t bus_off{};
  bus_off.kind = motorsim_fault_t::BUS_OFF;
  bus_off.duration_s = 0.5;
  watcher_->lcm().publish(std::string(channels::MOTORSIM_FAULT), &bus_off);
  Run(0.25);
  EXPECT_EQ(bus_->status().state, can::CanBusState::kBusOff);
  EXPECT_EQ(bus_->status().bus_off_count, 1u);
  Run(0.6);
  EXPECT_EQ(bus_->status().state, can::CanBusState::kErrorActive);
  ASSERT_TRUE(plant_.last);
  EXPECT_NEAR(plant_.last->joints.velocity_radps[0], 0.0, 0.01);
  EXPECT_NEAR(plant_.last->joints.velocity_radps[6], -0.2, 0.02);

  kill(motorsim_, SIGTERM);
  EXPECT_EQ(WaitFor(motorsim_, 5.0), 0);
  motorsim_ = -1;
  const std::string report = ReadText(dir_ + "/motorsim.txt");
  EXPECT_NE(report.find("faults injected: drive 1, base 0, heartbeat losses 0, bus-off 1"), std::string::npos) << report;
  EXPECT_NE(report.find("SDO writes " + std::to_string(expected)), std::string::npos) << report;
}

TEST(MotorsimProcessFlags, BadBusAndConfigExitWithOne) {
  const std::string dir = TestDir("motorsim_flags");
  pid_t pid = Spawn({BinDir() + "/topay-motorsim", "--can", "udp://10.0.0.1:9000"}, dir + "/bus.txt");
  int status = WaitFor(pid, 10.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(ReadText(dir + "/bus.txt").find("multicast"), std::string::npos);
  WriteText(dir + "/bad.yaml", "base: {node_id: 3}\n");
  pid = Spawn({BinDir() + "/topay-motorsim", "--config", dir + "/bad.yaml"}, dir + "/config.txt");
  status = WaitFor(pid, 10.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_NE(ReadText(dir + "/config.txt").find("bad.yaml"), std::string::npos);
  pid = Spawn({BinDir() + "/topay-motorsim", "--no-such-flag"}, dir + "/usage.txt");
  status = WaitFor(pid, 10.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
}

}  // namespace
}  // namespace topay::test
