// topay-canbridge's node on an in-memory bus with the base and drive peers (simulated clock):
// start-up to Operation enabled, commands encoded and clamped (also over random command
// streams), the stops (command loss, drive fault, lost heartbeat, bus-off, base fault) with
// DRIVE_STATUS and the documented recovery, malformed frames counted.
#include "procs/canbridge/canbridge_node.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/cia402_drive_model.h"
#include "drivers/arm/emcy.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/can/can_error.h"
#include <linux/can/error.h>
#include "tests/procs/canbridge/canbridge_rig.h"
#include "topay/heartbeat_t.hpp"

namespace topay::canbridge::test {
namespace {

using cia402::DriveState;

constexpr std::uint32_t kBaseVelocityId = 0x200 + 16;
constexpr std::uint32_t kBaseModeRequestId = 0x100 + 16;

// The frames the bridge sent at or after `since_s`.
std::vector<std::pair<double, can::CanFrame>> SentSince(const Rig& rig, double since_s) {
  std::vector<std::pair<double, can::CanFrame>> frames;
  for (const auto& [ns, frame] : rig.bridge_bus.sent) {
    if (ns * 1e-9 >= since_s - 1e-9) frames.emplace_back(ns * 1e-9, frame);
  }
  return frames;
}

TEST(CanbridgeNodeTest, StartupReachesOperationEnabled) {
  Rig rig;
  EXPECT_EQ(rig.node.state(), BridgeState::kStarting);
  ASSERT_TRUE(rig.Running()) << rig.node.stop_reason();
  EXPECT_EQ(rig.peers.base.mode(), base::BaseMode::kCanCommand);
  for (const DrivePeer& drive : rig.peers.drives) {
    EXPECT_EQ(drive.model.state(), DriveState::kOperationEnabled);
    EXPECT_EQ(drive.nmt, canopen::NmtState::kOperational);
    EXPECT_GE(drive.resets, 1);
    EXPECT_EQ(drive.starts, 1);
    EXPECT_EQ(drive.Object(0x6060, 0), 9u);                  // cyclic synchronous velocity
    EXPECT_EQ(drive.Object(0x1017, 0), 100u);                // producer heartbeat 100 ms
    EXPECT_EQ(drive.Object(0x1016, 1), (127u << 16) | 300u);  // the host's heartbeat, 300 ms
    EXPECT_EQ(drive.Object(0x60C2, 1), 5u);                  // the SYNC period: 5 ms
    EXPECT_EQ(drive.Object(0x1600, 1), 0x60400010u);         // RPDO1: controlword
    EXPECT_EQ(drive.Object(0x1A00, 1), 0x60410010u);         // TPDO1: statusword
  }
  rig.TickFor(0.2);
  EXPECT_EQ(rig.last_status.state, drive_status_t::RUNNING);
  EXPECT_EQ(rig.last_status.num_drives, 7);
  EXPECT_EQ(rig.last_status.drive_state[2], "Operation enabled");
  EXPECT_EQ(rig.last_status.nmt_state[2], "operational");
  EXPECT_EQ(rig.last_status.joint_name[0], rig.model.joint_names[0]);
  EXPECT_GE(rig.last_status.heartbeat_age_s[0], 0.0);
  EXPECT_LE(rig.last_status.heartbeat_age_s[0], 0.11);
  EXPECT_EQ(rig.last_status.base_mode, 1);
  EXPECT_GT(rig.last_status.bus_load_percent, 5.0);
  EXPECT_LT(rig.last_status.bus_load_percent, 80.0);
  EXPECT_EQ(rig.last_status.frames_malformed, 0);
  EXPECT_EQ(rig.last_status.frames_unknown, 0);
  EXPECT_EQ(rig.last_joint_state.num_joints, 7);
  EXPECT_NEAR(rig.last_joint_state.position_rad[0], 0.1, 1e-6);
}

TEST(CanbridgeNodeTest, StartupWaitsForAZeroCommand) {
  Rig rig;
  rig.CommandFor(rig.Command(0.3, 0.0, 0.0), 2.0);  // a tracker already commanding motion
  EXPECT_NE(rig.node.state(), BridgeState::kRunning);
  EXPECT_NE(rig.node.stop_reason().find("waiting for a zero CONTROL_COMMAND"), std::string::npos)
      << rig.node.stop_reason();
  EXPECT_EQ(rig.peers.base.v(), 0.0);
  EXPECT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kRunning; }, 3.0))
      << rig.node.stop_reason();
}

TEST(CanbridgeNodeTest, SyncAndHostHeartbeatEveryCycle) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  const double since = rig.t;
  rig.TickFor(1.0);
  int syncs = 0, heartbeats = 0, rpdos = 0, base_commands = 0;
  for (const auto& [time, frame] : SentSince(rig, since)) {
    syncs += frame.id == 0x080 && frame.dlc == 0;
    heartbeats += frame.id == 0x77F && frame.dlc == 1 && frame.data[0] == 0x05;
    rpdos += frame.id == 0x203;
    base_commands += frame.id == kBaseVelocityId;
  }
  EXPECT_NEAR(syncs, 200, 2);
  EXPECT_NEAR(rpdos, 200, 2);
  EXPECT_NEAR(base_commands, 200, 2);
  EXPECT_NEAR(heartbeats, 1.0 / CanbridgeOptions{}.drives.host_heartbeat_period_s, 1);  // 20 at 50 ms
}

TEST(CanbridgeNodeTest, CommandsAreEncodedAndClamped) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.3, -0.2, 0.5), 1.5);
  EXPECT_NEAR(rig.peers.base.commands.back().v_m_per_s, 0.3, 1e-3);
  EXPECT_NEAR(rig.peers.base.commands.back().omega_rad_per_s, -0.2, 1e-3);
  EXPECT_NEAR(rig.peers.drives[4].target_velocity, 0.5, 1e-4);
  EXPECT_NEAR(rig.last_base_velocity.v_mps, 0.3, 2e-3);
  EXPECT_NEAR(rig.last_joint_state.velocity_radps[4], 0.5, 1e-4);
  // Beyond the limits (1.0 m/s, 0.9 rad/s, 2.35 rad/s): held at the limits.
  rig.CommandFor(rig.Command(5.0, -3.0, 9.0), 4.0);
  EXPECT_NEAR(rig.peers.base.commands.back().v_m_per_s, 1.0, 1e-9);
  EXPECT_NEAR(rig.peers.base.commands.back().omega_rad_per_s, -0.9, 1e-9);
  EXPECT_NEAR(rig.peers.drives[0].target_velocity, 2.35, 1e-9);
  EXPECT_GT(rig.node.limiter().clamp_count(), 0);
  // A command sent on receipt, before the next cycle: latency measured.
  EXPECT_GT(rig.node.command_latency().Summary().count, 0);
}

TEST(CanbridgeNodeTest, MalformedCommandsAreRejected) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  control_command_t bad = rig.Command(0.2, 0.0, 0.0);
  bad.v_mps = std::nan("");
  rig.node.OnCommand(bad, rig.t);
  control_command_t short_one = rig.Command(0.2, 0.0, 0.0);
  short_one.num_joints = 3;
  short_one.qdot_radps.resize(3);
  rig.node.OnCommand(short_one, rig.t);
  rig.TickFor(0.05);
  EXPECT_EQ(rig.node.commands_rejected(), 2);
  EXPECT_EQ(rig.node.commands_received(), 0);
  EXPECT_EQ(rig.peers.base.commands.back().v_m_per_s, 0.0);
}

// Property: over random command streams (any values, NaNs, any timing, sent on receipt and
// repeated every cycle) no frame on the bus is outside the limits, and no two consecutive
// frames differ by more than the acceleration limit over one cycle (+ one unit of rounding).
TEST(CanbridgeNodeTest, NothingSentOutsideTheLimits) {
  for (const int seed : {1, 2, 3}) {
    Rig rig;
    ASSERT_TRUE(rig.Running());
    const double since = rig.t;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> value(-4.0, 4.0);
    std::uniform_int_distribution<int> gap(0, 6);
    for (int cycle = 0; cycle < 600; ++cycle) {
      if (gap(rng) < 5) {
        control_command_t msg = rig.Command(value(rng), value(rng), 0.0);
        for (double& q : msg.qdot_radps) q = value(rng);
        if (gap(rng) == 0) msg.qdot_radps[2] = std::nan("");
        rig.node.OnCommand(msg, rig.t - 0.0005 * gap(rng));  // since the last cycle
      }
      rig.Tick();
    }
    ASSERT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
    const cia402::JointUnits units;
    std::optional<base::VelocityCommand> previous_base;
    std::map<std::uint32_t, double> previous_qdot;
    int checked = 0;
    for (const auto& [time, frame] : SentSince(rig, since)) {
      if (frame.id == kBaseVelocityId) {
        const auto command = base::DecodeVelocityCommand(frame, 16, std::nullopt, nullptr);
        ASSERT_TRUE(command);
        EXPECT_LE(std::abs(command->v_m_per_s), 1.0 + 1e-9);
        EXPECT_LE(std::abs(command->omega_rad_per_s), 0.9 + 1e-9);
        if (previous_base) {
          EXPECT_LE(std::abs(command->v_m_per_s - previous_base->v_m_per_s), 0.8 * 0.005 + 1e-3 + 1e-9);
          EXPECT_LE(std::abs(command->omega_rad_per_s - previous_base->omega_rad_per_s), 1.0 * 0.005 + 1e-3 + 1e-9);
        }
        previous_base = command;
        ++checked;
      } else if (frame.id >= 0x201 && frame.id <= 0x207) {
        const auto pdo = cia402::DecodeRpdo1(frame, units, nullptr);
        ASSERT_TRUE(pdo);
        EXPECT_LE(std::abs(pdo->target_velocity_rad_per_s), 2.35 + 1e-9);
        if (previous_qdot.count(frame.id)) {
          EXPECT_LE(std::abs(pdo->target_velocity_rad_per_s - previous_qdot[frame.id]), 6.28 * 0.005 + 1e-4 + 1e-9);
        }
        previous_qdot[frame.id] = pdo->target_velocity_rad_per_s;
        ++checked;
      }
    }
    EXPECT_GT(checked, 600 * 8);
    EXPECT_GT(rig.node.limiter().clamp_count(), 100);
  }
}

TEST(CanbridgeNodeTest, CommandLossStopsWithin100msAndRecoversOnZero) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.5, 0.0, 0.3), 2.0);
  const double last_command = rig.t;
  rig.node.OnCommand(rig.Command(0.5, 0.0, 0.3), last_command);
  ASSERT_TRUE(rig.TickUntil([&] { return rig.node.state() == BridgeState::kStopped; }, 0.5));
  EXPECT_NE(rig.node.stop_reason().find("CONTROL_COMMAND stale"), std::string::npos) << rig.node.stop_reason();
  rig.Tick();
  // The first zero velocity command, quick stop request and quick stop controlword.
  double zero_at = -1, quick_stop_at = -1, controlword_at = -1;
  for (const auto& [time, frame] : SentSince(rig, last_command)) {
    if (frame.id == kBaseVelocityId && zero_at < 0 && frame.data[0] == 0 && frame.data[1] == 0) zero_at = time;
    if (frame.id == kBaseModeRequestId && quick_stop_at < 0 && frame.data[0] == 2) quick_stop_at = time;
    if (frame.id == 0x201 && controlword_at < 0 && frame.data[0] == 0x02) controlword_at = time;
  }
  ASSERT_GE(zero_at, 0);
  ASSERT_GE(quick_stop_at, 0);
  ASSERT_GE(controlword_at, 0);
  // The stop frames are on the bus within 100 ms of the last command.
  EXPECT_LE(zero_at - last_command, 0.1 + 1e-9);
  EXPECT_LE(quick_stop_at - last_command, 0.1 + 1e-9);
  EXPECT_LE(controlword_at - last_command, 0.1 + 1e-9);
  rig.TickFor(0.2);
  EXPECT_EQ(rig.peers.base.mode(), base::BaseMode::kQuickStop);
  EXPECT_EQ(rig.peers.drives[0].model.state(), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(rig.last_status.state, drive_status_t::STOPPED);
  // A non-zero command does not restart the robot; zero commands for the hold time do.
  rig.CommandFor(rig.Command(0.5, 0.0, 0.0), 1.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kStopped);
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
  EXPECT_EQ(rig.peers.base.mode(), base::BaseMode::kCanCommand);
  EXPECT_EQ(rig.peers.drives[6].model.state(), DriveState::kOperationEnabled);
}

TEST(CanbridgeNodeTest, DriveFaultStopsAndNeedsAFaultReset) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.4, 0.0, 0.2), 1.0);
  std::vector<can::CanFrame> out;
  rig.peers.drives[2].Fault(0x2310, &out);  // over-current
  rig.peers.Send(out);
  const double fault_at = rig.t;
  const std::size_t controlwords_before = rig.peers.drives[0].controlwords.size();
  rig.node.OnCommand(rig.Command(0.4, 0.0, 0.2), rig.t);
  ASSERT_TRUE(rig.TickUntil([&] { return rig.node.state() == BridgeState::kFault; }, 0.1));
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.1);
  EXPECT_LE(rig.t - fault_at, 0.2);
  EXPECT_EQ(rig.last_status.state, drive_status_t::FAULT);
  EXPECT_NE(rig.last_status.stop_reason.find("node 3"), std::string::npos) << rig.last_status.stop_reason;
  EXPECT_EQ(rig.last_status.last_emcy_code[2], 0x2310);
  EXPECT_EQ(rig.last_status.drive_state[2], "Fault");
  EXPECT_EQ(rig.peers.base.mode(), base::BaseMode::kQuickStop);
  EXPECT_EQ(rig.peers.base.commands.back().v_m_per_s, 0.0);
  const std::vector<std::uint16_t>& words = rig.peers.drives[0].controlwords;  // the others quick-stopped
  EXPECT_NE(std::find(words.begin() + controlwords_before, words.end(), 0x0002), words.end());
  EXPECT_EQ(words.back(), 0x0000);  // then disabled in Switch on disabled
  EXPECT_EQ(rig.peers.drives[0].model.state(), DriveState::kSwitchOnDisabled);
  EXPECT_EQ(rig.node.Health(), heartbeat_t::ERROR);
  // No automatic recovery, even with zero commands.
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kFault);
  EXPECT_EQ(rig.peers.drives[2].model.state(), DriveState::kFault);
  // A reset while the command is not zero is refused; with zero it recovers.
  drive_command_t reset{};
  reset.command = drive_command_t::FAULT_RESET;
  reset.source = "test";
  rig.node.OnCommand(rig.Command(0.3, 0.0, 0.0), rig.t);
  EXPECT_FALSE(rig.node.OnDriveCommand(reset, rig.t).empty());
  rig.node.OnCommand(rig.Command(0.0, 0.0, 0.0), rig.t);
  EXPECT_EQ(rig.node.OnDriveCommand(reset, rig.t), "");
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
  EXPECT_EQ(rig.peers.drives[2].model.state(), DriveState::kOperationEnabled);
}

// DRIVE_STATUS goes out at its period while nothing changes, and in the very cycle the bridge's
// state or a drive's EMCY code changes (procs/canbridge/status_key.h).
TEST(CanbridgeNodeTest, DriveStatusGoesOutAtItsPeriodAndAtOnceOnAChange) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  const control_command_t zero = rig.Command(0.0, 0.0, 0.0);
  rig.CommandFor(zero, 0.5);
  int published = 0;
  const int cycles = 200;  // 1 s
  for (int i = 0; i < cycles; ++i) {
    if (i % 4 == 0) rig.node.OnCommand(zero, rig.t);
    if (rig.Tick().status) ++published;
  }
  EXPECT_NEAR(published, cycles * rig.options.cycle_period_s / rig.options.status_period_s, 1.0);
  std::vector<can::CanFrame> out;
  rig.peers.drives[4].Fault(0x2310, &out);  // over-current, with its EMCY
  rig.peers.Send(out);
  for (int i = 0; i < 40 && rig.node.state() != BridgeState::kFault; ++i) {
    if (i % 4 == 0) rig.node.OnCommand(zero, rig.t);
    const CanbridgeOutputs& outputs = rig.Tick();
    if (rig.node.state() != BridgeState::kFault) continue;
    ASSERT_TRUE(outputs.status.has_value()) << "the cycle that entered FAULT published no DRIVE_STATUS";
    EXPECT_EQ(outputs.status->state, drive_status_t::FAULT);
    EXPECT_EQ(outputs.status->last_emcy_code[4], 0x2310);
  }
  EXPECT_EQ(rig.node.state(), BridgeState::kFault);
}

// A drive that lost the bridge's heartbeat while the bus was off faults with 0x8130 and its
// EMCY is lost with the bus: the bridge reads 0x603F, sees a communication error only, and
// resets it itself at a zero command (no operator). A fault of the drive itself read the same
// way stays for the operator.
TEST(CanbridgeNodeTest, CommunicationFaultWithoutEmcyIsReadAndResetByTheBridge) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.2);
  rig.peers.drives[3].Fault(canopen::emcy_code::kHeartbeatError, nullptr);  // no EMCY on the bus
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kFault; }, 0.2));
  EXPECT_EQ(rig.last_status.last_emcy_code[3], 0);
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kRunning; }, 3.0))
      << rig.node.stop_reason();
  EXPECT_GE(rig.peers.drives[3].uploads, 1);
  EXPECT_EQ(rig.peers.drives[3].model.state(), DriveState::kOperationEnabled);
}

// A drive whose setpoints stopped for its RPDO deadline (the bridge killed and restarted)
// faults with 0x8250, its EMCY sent while no bridge listened: reset by the bridge like 0x8130.
TEST(CanbridgeNodeTest, AnRpdoTimeoutWithoutEmcyIsReadAndResetByTheBridge) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.2);
  rig.peers.drives[5].Fault(canopen::emcy_code::kRpdoTimeout, nullptr);
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kFault; }, 0.2));
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kRunning; }, 3.0))
      << rig.node.stop_reason();
  EXPECT_GE(rig.peers.drives[5].uploads, 1);
  EXPECT_EQ(rig.peers.drives[5].model.state(), DriveState::kOperationEnabled);
}

TEST(CanbridgeNodeTest, ADriveFaultOfItsOwnReadBySdoWaitsForTheOperator) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.peers.drives[1].Fault(0x2310, nullptr);  // over-current, EMCY lost
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kFault; }, 0.2));
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_GE(rig.peers.drives[1].uploads, 1);  // read, and not reset
  EXPECT_EQ(rig.node.state(), BridgeState::kFault);
  EXPECT_EQ(rig.peers.drives[1].model.state(), DriveState::kFault);
}

TEST(CanbridgeNodeTest, AutomaticResetsWaitForAZeroCommandAndStopAfterTheLimit) {
  CanbridgeOptions options;
  options.max_auto_resets_per_minute = 2;
  Rig rig(options);
  ASSERT_TRUE(rig.Running());
  for (int k = 0; k < 3; ++k) {
    std::vector<can::CanFrame> out;
    rig.peers.drives[0].Fault(canopen::emcy_code::kHeartbeatError, &out);  // with its EMCY this time
    rig.peers.Send(out);
    ASSERT_TRUE(rig.CommandUntil(rig.Command(0.2, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kFault; }, 0.2));
    rig.CommandFor(rig.Command(0.2, 0.0, 0.0), 1.0);  // a command still moving: no reset
    EXPECT_EQ(rig.node.state(), BridgeState::kFault) << k;
    rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 3.0);
    if (k < 2) {
      EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << k << ": " << rig.node.stop_reason();
    } else {
      EXPECT_EQ(rig.node.state(), BridgeState::kFault) << "the third within a minute waits for the operator";
    }
  }
  CanbridgeOptions off;
  off.auto_reset_communication_faults = false;
  Rig manual(off);
  ASSERT_TRUE(manual.Running());
  std::vector<can::CanFrame> out;
  manual.peers.drives[0].Fault(canopen::emcy_code::kHeartbeatError, &out);
  manual.peers.Send(out);
  manual.CommandFor(manual.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(manual.node.state(), BridgeState::kFault);
}

TEST(CanbridgeNodeTest, LostDriveHeartbeatStopsAndRecovers) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.5);
  const int resets_before = rig.peers.drives[5].resets;
  const int starts_before = rig.peers.drives[5].starts;
  rig.peers.drives[5].silent = true;
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kStopped; }, 0.5));
  EXPECT_NE(rig.node.stop_reason().find("node 6"), std::string::npos) << rig.node.stop_reason();
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.1);
  EXPECT_EQ(rig.last_status.state, drive_status_t::STOPPED);
  EXPECT_EQ(rig.peers.base.mode(), base::BaseMode::kQuickStop);
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 1.0);
  EXPECT_NE(rig.node.state(), BridgeState::kRunning);
  rig.peers.drives[5].silent = false;
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 4.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
  // Re-configured from NMT reset (the recovery's start-up, begun while it was still silent and
  // retried until it answered) to NMT start.
  EXPECT_GT(rig.peers.drives[5].resets, resets_before);
  EXPECT_GT(rig.peers.drives[5].starts, starts_before);
}

TEST(CanbridgeNodeTest, LostBaseStopsEverything) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.peers.base.silent = true;
  ASSERT_TRUE(rig.TickUntil([&] { return rig.node.state() == BridgeState::kStopped; }, 0.5));
  EXPECT_NE(rig.node.stop_reason().find("base (node 16) lost"), std::string::npos) << rig.node.stop_reason();
  const std::size_t before = rig.peers.drives[0].controlwords.size();
  rig.TickFor(0.1);
  EXPECT_EQ(rig.peers.drives[0].controlwords.at(before - 1), 0x0002);  // the stop cycle: quick stop, then disabled
  EXPECT_EQ(rig.peers.drives[0].model.state(), DriveState::kSwitchOnDisabled);
  rig.peers.base.silent = false;
  rig.TickFor(2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
}

TEST(CanbridgeNodeTest, BusOffStopsAndRecoversAfterRestart) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.2);
  rig.bridge_bus.Inject(can::MakeCanErrorFrame(CAN_ERR_BUSOFF));
  rig.node.OnCommand(rig.Command(0.0, 0.0, 0.0), rig.t);
  rig.Tick();
  EXPECT_EQ(rig.node.state(), BridgeState::kStopped);
  EXPECT_NE(rig.node.stop_reason().find("bus-off"), std::string::npos) << rig.node.stop_reason();
  EXPECT_GT(rig.node.tx_refused(), 0);
  EXPECT_EQ(rig.last_status.bus_state, "bus-off");
  EXPECT_EQ(rig.last_status.bus_off_count, 1);
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.2);
  EXPECT_EQ(rig.node.state(), BridgeState::kStopped);
  rig.bridge_bus.Inject(can::MakeCanErrorFrame(CAN_ERR_RESTARTED));
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 4.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
  EXPECT_EQ(rig.last_status.bus_state, "error-active");
}

TEST(CanbridgeNodeTest, ADeviceLeavingItsRunningStateStopsAll) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  // The base's own watchdog (e.g. after a stall of the bridge) put it into quick stop.
  rig.bridge_bus.Inject(*base::EncodeStatus({base::BaseMode::kQuickStop, 0, 0, 48.0, 200}, 16, nullptr));
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.01);
  EXPECT_EQ(rig.node.state(), BridgeState::kStopped);
  EXPECT_NE(rig.node.stop_reason().find("left running: base in quick stop"), std::string::npos) << rig.node.stop_reason();
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
  // A drive disabled by itself (Switch on disabled in a TPDO1).
  rig.bridge_bus.Inject(*cia402::EncodeTpdo1({4, cia402::EncodeStatusword(DriveState::kSwitchOnDisabled), 0.1}, {}, nullptr));
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.01);
  EXPECT_EQ(rig.node.state(), BridgeState::kStopped);
  EXPECT_NE(rig.node.stop_reason().find("node 4"), std::string::npos) << rig.node.stop_reason();
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
}

TEST(CanbridgeNodeTest, BaseFaultStopsAndResets) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  std::vector<can::CanFrame> out;
  rig.peers.base.RaiseFault(base::BaseFault::kLeftMotorStall, rig.t, &out);
  rig.peers.Send(out);
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.1);
  EXPECT_EQ(rig.node.state(), BridgeState::kFault);
  EXPECT_NE(rig.node.stop_reason().find("left motor stall"), std::string::npos) << rig.node.stop_reason();
  EXPECT_EQ(rig.last_status.base_mode, 3);
  drive_command_t reset{};
  reset.command = drive_command_t::FAULT_RESET;
  EXPECT_EQ(rig.node.OnDriveCommand(reset, rig.t), "");
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 2.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning) << rig.node.stop_reason();
  EXPECT_EQ(rig.peers.base.mode(), base::BaseMode::kCanCommand);
}

TEST(CanbridgeNodeTest, StartupSdoAbortIsReportedAndRetried) {
  Rig rig;
  rig.peers.drives[1].abort_index = 0x6060;
  rig.TickFor(1.0);
  EXPECT_EQ(rig.node.state(), BridgeState::kStarting);
  EXPECT_NE(rig.node.stop_reason().find("0x6060"), std::string::npos) << rig.node.stop_reason();
  EXPECT_NE(rig.node.stop_reason().find("node 2"), std::string::npos) << rig.node.stop_reason();
  rig.peers.drives[1].abort_index.reset();
  EXPECT_TRUE(rig.Running()) << rig.node.stop_reason();
}

TEST(CanbridgeNodeTest, MalformedAndUnknownFramesAreCounted) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.peer_bus.Send(can::CanFrame::Standard(0x183, {0x27, 0x00, 0x00}));  // TPDO1 node 3, DLC 3
  rig.peer_bus.Send(can::CanFrame::Standard(0x183, {0x27, 0x00, 0x00}));
  can::CanFrame status = can::CanFrame::Standard(0x190, {1, 0, 0, 0, 0x10, 0x13, 5, 0});  // bad checksum
  rig.peer_bus.Send(status);
  rig.peer_bus.Send(can::CanFrame::Standard(0x123, {1, 2}));          // nobody's
  rig.peer_bus.Send(can::CanFrame::Extended(0x18FF0001, {1, 2, 3}));  // extended
  rig.peer_bus.Send(can::CanFrame::Remote(0x183, 6));
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.2);
  // Malformed: the two short TPDO1s and the remote frame on 0x183, the base status.
  EXPECT_EQ(rig.node.frame_counters().malformed(), 4);
  EXPECT_EQ(rig.node.frame_counters().unknown(), 2);
  EXPECT_EQ(rig.last_status.frames_malformed, 4);
  EXPECT_EQ(rig.last_status.frames_unknown, 2);
  EXPECT_EQ(rig.node.state(), BridgeState::kRunning);
  EXPECT_EQ(rig.node.frame_counters().by_kind().size(), 4u);
}

// Found by the canbridge fuzz target (tests/fuzz/regressions/canbridge/
// first_running_step_from_last_zero_sent): the first command after a stop counted its change
// from the time the stop began, not from the zero frame sent just before, so with cycles closer
// together than the period (here two at the same time) a near-zero command (within
// zero_command_tolerance) was a step of a whole cycle's acceleration at once.
TEST(CanbridgeNodeTest, FirstRunningCommandChangesFromTheLastZeroSent) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.peers.base.silent = true;
  ASSERT_TRUE(rig.TickUntil([&] { return rig.node.state() == BridgeState::kStopped; }, 0.5));
  rig.peers.base.silent = false;
  const control_command_t near_zero = rig.Command(0.0, 0.0, 0.9 * rig.options.zero_command_tolerance);
  // Every cycle twice at the same time: whichever of the two enters RUNNING, its frames follow a
  // frame sent at the same time, so nothing may change.
  double entered_at = -1.0;
  for (int i = 0; i < 800 && entered_at < 0.0; ++i) {
    for (int twice = 0; twice < 2 && entered_at < 0.0; ++twice) {
      rig.node.OnCommand(near_zero, rig.t);
      rig.node.Cycle(rig.t, static_cast<std::int64_t>(rig.t * 1e6));
      if (rig.node.state() == BridgeState::kRunning) entered_at = rig.t;
      rig.peers.Step(rig.t);
    }
    if (entered_at < 0.0) rig.t += rig.options.cycle_period_s;
  }
  ASSERT_GE(entered_at, 0.0) << rig.node.stop_reason();
  const std::uint32_t rpdo1 = 0x200u + static_cast<std::uint32_t>(rig.options.drives.node_ids[0]);
  std::optional<double> previous;
  for (const auto& [time, frame] : SentSince(rig, entered_at - 1.0)) {
    if (frame.id != rpdo1) continue;
    const auto pdo = cia402::DecodeRpdo1(frame, rig.options.drives.units, nullptr);
    ASSERT_TRUE(pdo);
    if (previous && time >= entered_at - 1e-9) {
      EXPECT_EQ(pdo->target_velocity_rad_per_s, *previous) << "at " << time << " s, no time after the last frame";
    }
    previous = pdo->target_velocity_rad_per_s;
  }
}

// Found by the canbridge fuzz target (tests/fuzz/regressions/canbridge/drive_reboot_recovers): a
// drive that restarted while operational kept "rebooted" as a stop cause until its start-up was
// re-run, which only a recovery does, and a recovery needs the cause gone: STOPPED for good.
TEST(CanbridgeNodeTest, DriveRebootWhileRunningStopsAndRecovers) {
  Rig rig;
  ASSERT_TRUE(rig.Running());
  rig.CommandFor(rig.Command(0.0, 0.0, 0.0), 0.2);
  const int resets_before = rig.peers.drives[3].resets;
  std::vector<can::CanFrame> out;
  rig.peers.drives[3].model = cia402::DriveModel{};
  rig.peers.drives[3].PowerOn(&out);  // a power dip: boot-up while operational
  rig.peers.Send(out);
  rig.Tick();
  EXPECT_EQ(rig.node.state(), BridgeState::kStopped);
  EXPECT_NE(rig.node.stop_reason().find("node 4) rebooted"), std::string::npos) << rig.node.stop_reason();
  ASSERT_TRUE(rig.CommandUntil(rig.Command(0.0, 0.0, 0.0), [&] { return rig.node.state() == BridgeState::kRunning; },
                               3.0))
      << rig.node.stop_reason();
  EXPECT_GT(rig.peers.drives[3].resets, resets_before);  // configured again from NMT reset
  EXPECT_EQ(rig.peers.drives[3].model.state(), DriveState::kOperationEnabled);
}

}  // namespace
}  // namespace topay::canbridge::test
