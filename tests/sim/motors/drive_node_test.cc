// A simulated CiA 402 drive (sim/motors/drive_node.h) against the host side of drivers/arm: the
// start-up SDO writes answered (and bad writes aborted), NMT states, the enable sequence of
// cia402_host reaching Operation enabled, the target velocity followed only there, quick stop,
// fault + EMCY + fault reset, the heartbeat's timing, the host's heartbeat lost, RPDO1's deadline.

#include "sim/motors/drive_node.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_host.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/startup_sdo.h"
#include "drivers/arm/sync.h"

namespace topay::sim::motors {
namespace {

using canopen::NmtState;
using cia402::DriveState;
constexpr int kNode = 3;

can::CanFrame Nmt(canopen::NmtCommand command, int node = kNode) { return *canopen::EncodeNmt({command, node}, nullptr); }
can::CanFrame Sync() { return *canopen::EncodeSync({}, nullptr); }
can::CanFrame Rpdo1(std::uint16_t controlword, double velocity) {
  return *cia402::EncodeRpdo1({kNode, controlword, velocity}, {}, nullptr);
}

std::optional<canopen::CobIdClass> Classify(const can::CanFrame& f) { return canopen::ClassifyCobId(f.id, nullptr); }

std::vector<can::CanFrame> OfFunction(const std::vector<can::CanFrame>& frames, canopen::CanopenFunction function) {
  std::vector<can::CanFrame> out;
  for (const can::CanFrame& f : frames) {
    if (Classify(f) && Classify(f)->function == function) out.push_back(f);
  }
  return out;
}

// The drive with a clock, a SDO round trip and a SYNC cycle, as a host would use it.
struct Bench {
  DriveNode drive{[] {
                    DriveNodeOptions o;
                    o.node_id = kNode;
                    return o;
                  }(),
                  0.0};
  double t = 0.0;
  std::vector<can::CanFrame> out;

  void Step(double dt = 0.005) {
    t += dt;
    drive.Step(t, false, &out);
  }
  std::optional<canopen::SdoServerReply> Sdo(const can::CanFrame& request) {
    out.clear();
    drive.OnFrame(request, t, &out);
    if (out.size() != 1) return std::nullopt;
    return canopen::DecodeSdoServerReply(out[0], nullptr);
  }
  std::uint32_t Write(canopen::ObjectAddress a, int size, std::uint32_t value) {
    const auto reply = Sdo(*canopen::EncodeSdoDownloadRequest({kNode, a, size, value}, nullptr));
    if (!reply) return 0xFFFFFFFF;
    if (const auto* abort = std::get_if<canopen::SdoAbort>(&*reply)) return abort->abort_code;
    return std::holds_alternative<canopen::SdoDownloadResponse>(*reply) ? 0 : 0xFFFFFFFE;
  }
  // One cycle: RPDO1 (if given), SYNC; returns the TPDO1 of the answer.
  std::optional<cia402::Tpdo1> Cycle(std::optional<std::uint16_t> controlword, double velocity = 0.0) {
    out.clear();
    if (controlword) drive.OnFrame(Rpdo1(*controlword, velocity), t, &out);
    drive.OnFrame(Sync(), t, &out);
    Step();
    const auto tpdo1 = OfFunction(out, canopen::CanopenFunction::kTpdo1);
    if (tpdo1.empty()) return std::nullopt;
    return cia402::DecodeTpdo1(tpdo1.back(), {}, nullptr);
  }
  // Runs cia402_host's enable sequence; true once the drive reports Operation enabled.
  bool Enable(int max_cycles = 10) {
    std::uint16_t previous = 0;
    std::optional<cia402::Tpdo1> feedback = Cycle(std::nullopt);
    for (int i = 0; i < max_cycles; ++i) {
      if (!feedback) return false;
      const auto state = cia402::DecodeStatusword(feedback->statusword, nullptr);
      if (state == DriveState::kOperationEnabled) return true;
      const cia402::HostStep step = cia402::NextStepTowardsOperationEnabled(*state, previous);
      previous = step.controlword;
      feedback = Cycle(step.controlword);
    }
    return false;
  }
  void Start() {
    Step();
    out.clear();
    drive.OnFrame(Nmt(canopen::NmtCommand::kStartRemoteNode), t, &out);
    drive.SetFeedback({0.1, 0.0});
  }
};

TEST(DriveNodeTest, BootsUpAndAnswersTheStartupWrites) {
  Bench b;
  b.Step();
  ASSERT_FALSE(b.out.empty());
  const auto boot = canopen::DecodeHeartbeat(b.out.front(), nullptr);
  ASSERT_TRUE(boot);
  EXPECT_EQ(boot->node_id, kNode);
  EXPECT_EQ(boot->state, NmtState::kBootUp);
  EXPECT_EQ(b.drive.nmt_state(), NmtState::kPreOperational);

  cia402::StartupOptions options;
  options.producer_heartbeat_ms = 50;
  const auto writes = cia402::StartupSdoWrites(kNode, options, nullptr);
  ASSERT_TRUE(writes);
  for (const cia402::SdoWrite& w : *writes) {
    EXPECT_EQ(b.Write(w.address, w.size_bytes, w.value), 0u) << w.what;
  }
  EXPECT_EQ(b.drive.counts().sdo_writes, static_cast<std::int64_t>(writes->size()));
  EXPECT_EQ(b.drive.dictionary().producer_heartbeat_ms(), 50);
  EXPECT_EQ(b.drive.dictionary().consumer_node_id(), 127);
  EXPECT_EQ(b.drive.dictionary().consumer_heartbeat_ms(), 300);
  EXPECT_EQ(b.drive.dictionary().rpdo1_deadline_ms(), 50);
  EXPECT_TRUE(b.drive.dictionary().PdoValid(Pdo::kRpdo1));
  EXPECT_TRUE(b.drive.dictionary().PdoValid(Pdo::kTpdo2));
  EXPECT_FALSE(b.drive.dictionary().PdoValid(Pdo::kRpdo2));
  // A read comes back with the written value and size.
  const auto reply = b.Sdo(*canopen::EncodeSdoUploadRequest({kNode, {0x1017, 0}}, nullptr));
  ASSERT_TRUE(reply);
  const auto* upload = std::get_if<canopen::SdoUploadResponse>(&*reply);
  ASSERT_NE(upload, nullptr);
  EXPECT_EQ(upload->value, 50u);
  EXPECT_EQ(upload->size_bytes, 2);
}

TEST(DriveNodeTest, AbortsBadWrites) {
  Bench b;
  b.Step();
  namespace abort = canopen::sdo_abort;
  EXPECT_EQ(b.Write({0x1017, 0}, 4, 100), abort::kLengthMismatch);
  EXPECT_EQ(b.Write({0x2000, 0}, 4, 1), abort::kObjectDoesNotExist);
  EXPECT_EQ(b.Write({0x6041, 0}, 2, 0x27), abort::kReadOnly);
  EXPECT_EQ(b.Write({0x6060, 0}, 1, 8), abort::kValueRangeExceeded) << "only the velocity modes are simulated";
  EXPECT_EQ(b.Write({0x1600, 1}, 4, 0x60400010), abort::kUnsupportedAccess) << "RPDO1 is valid: invalidate it first";
  EXPECT_EQ(b.Write({0x1400, 1}, 4, 0x80000000u | 0x200 | kNode), 0u);
  EXPECT_EQ(b.Write({0x1600, 0}, 1, 0), 0u);
  EXPECT_EQ(b.Write({0x1600, 1}, 4, 0x10000020), abort::kCannotBeMapped);
  EXPECT_EQ(b.Write({0x1600, 1}, 4, 0x60FF0020), 0u);  // mappable, but not this drive's RPDO1 layout
  EXPECT_EQ(b.Write({0x1600, 0}, 1, 1), 0u);
  EXPECT_EQ(b.Write({0x1400, 1}, 4, 0x200 | kNode), abort::kCannotBeMapped);
  EXPECT_EQ(b.Write({0x1400, 1}, 4, 0x80000000u | 0x200 | (kNode + 1)), abort::kValueRangeExceeded) << "another COB-ID";
  EXPECT_GE(b.drive.counts().sdo_aborts, 8);
  // A segmented download is refused with an abort naming the object.
  const auto reply = b.Sdo(can::CanFrame::Standard(0x600 + kNode, {0x21, 0x17, 0x10, 0x00, 4, 0, 0, 0}));
  ASSERT_TRUE(reply);
  const auto* abort_reply = std::get_if<canopen::SdoAbort>(&*reply);
  ASSERT_NE(abort_reply, nullptr);
  EXPECT_EQ(abort_reply->address.index, 0x1017);
  EXPECT_EQ(b.drive.counts().malformed, 1);
}

TEST(DriveNodeTest, NmtStatesGateSdoAndPdo) {
  Bench b;
  b.Step();
  b.drive.SetFeedback({0.2, 0.0});
  EXPECT_FALSE(b.Cycle(std::nullopt)) << "no TPDOs in pre-operational";
  b.drive.OnFrame(Nmt(canopen::NmtCommand::kStartRemoteNode, 0), b.t, &b.out);  // all nodes
  EXPECT_EQ(b.drive.nmt_state(), NmtState::kOperational);
  const auto tpdo = b.Cycle(std::nullopt);
  ASSERT_TRUE(tpdo);
  EXPECT_NEAR(tpdo->position_rad, 0.2, 1e-6);
  EXPECT_EQ(cia402::DecodeStatusword(tpdo->statusword, nullptr), DriveState::kSwitchOnDisabled);
  b.drive.OnFrame(Nmt(canopen::NmtCommand::kStopRemoteNode), b.t, &b.out);
  EXPECT_EQ(b.drive.nmt_state(), NmtState::kStopped);
  EXPECT_FALSE(b.Sdo(*canopen::EncodeSdoUploadRequest({kNode, {0x1017, 0}}, nullptr))) << "no SDO when stopped";
  b.drive.OnFrame(Nmt(canopen::NmtCommand::kResetNode, kNode + 1), b.t, &b.out);
  EXPECT_EQ(b.drive.nmt_state(), NmtState::kStopped) << "another node's reset";
  b.drive.OnFrame(Nmt(canopen::NmtCommand::kResetNode), b.t, &b.out);
  b.out.clear();
  b.Step();
  ASSERT_FALSE(b.out.empty());
  EXPECT_EQ(canopen::DecodeHeartbeat(b.out.front(), nullptr)->state, NmtState::kBootUp);
  EXPECT_EQ(b.drive.nmt_state(), NmtState::kPreOperational);
}

// TPDO2's transmission type from the start-up list (every 2nd SYNC): velocity on every other
// SYNC, statusword and position (TPDO1) on each; type 1 (the power-on value) on each SYNC.
TEST(DriveNodeTest, SynchronousTpdosGoOutOnEveryNthSync) {
  Bench b;
  b.Start();
  const auto tpdo2_per_sync = [&b] {
    std::vector<int> counts;
    for (int i = 0; i < 6; ++i) {
      b.Cycle(std::nullopt);
      counts.push_back(static_cast<int>(OfFunction(b.out, canopen::CanopenFunction::kTpdo2).size()) * 10 +
                       static_cast<int>(OfFunction(b.out, canopen::CanopenFunction::kTpdo1).size()));
    }
    return counts;
  };
  EXPECT_EQ(tpdo2_per_sync(), (std::vector<int>{11, 11, 11, 11, 11, 11}));  // type 1: both every SYNC
  EXPECT_EQ(b.Write({0x1801, 2}, 1, 2), 0u);
  const std::vector<int> counts = tpdo2_per_sync();
  EXPECT_EQ(std::count(counts.begin(), counts.end(), 11), 3) << "TPDO2 on every 2nd SYNC";
  EXPECT_EQ(std::count(counts.begin(), counts.end(), 1), 3) << "TPDO1 on every SYNC";
  EXPECT_EQ(b.Write({0x1801, 2}, 1, 254), 0u);  // event-driven (manufacturer): never on SYNC
  EXPECT_EQ(tpdo2_per_sync(), (std::vector<int>{1, 1, 1, 1, 1, 1}));
  cia402::StartupOptions options;
  const auto writes = cia402::StartupSdoWrites(kNode, options, nullptr);
  ASSERT_TRUE(writes);
  int tpdo2_type = -1;
  for (const cia402::SdoWrite& w : *writes) {
    if (w.address.index == 0x1801 && w.address.subindex == 2) tpdo2_type = static_cast<int>(w.value);
  }
  EXPECT_EQ(tpdo2_type, 2) << "the start-up list's default";
}

TEST(DriveNodeTest, FollowsTheTargetOnlyWhenOperationEnabled) {
  Bench b;
  b.Start();
  b.Cycle(cia402::ControlwordOf(cia402::Command::kShutdown), 1.0);  // Ready to switch on
  EXPECT_EQ(b.drive.state(), DriveState::kReadyToSwitchOn);
  EXPECT_EQ(b.drive.velocity_command_radps(), 0.0);
  b.Cycle(cia402::ControlwordOf(cia402::Command::kSwitchOn), 1.0);
  EXPECT_EQ(b.drive.state(), DriveState::kSwitchedOn);
  EXPECT_EQ(b.drive.velocity_command_radps(), 0.0) << "Switched on: no motion";
  ASSERT_TRUE(b.Enable());
  b.Cycle(0x000F, 1.25);
  EXPECT_NEAR(b.drive.velocity_command_radps(), 1.25, 1e-4);
  // The RPDO acts at SYNC, not before.
  b.out.clear();
  b.drive.OnFrame(Rpdo1(0x000F, -0.5), b.t, &b.out);
  b.Step();
  EXPECT_NEAR(b.drive.velocity_command_radps(), 1.25, 1e-4);
  b.drive.OnFrame(Sync(), b.t, &b.out);
  b.Step();
  EXPECT_NEAR(b.drive.velocity_command_radps(), -0.5, 1e-4);
  // Disable operation (transition 5): zero at once.
  b.Cycle(cia402::ControlwordOf(cia402::Command::kDisableOperation), -0.5);
  EXPECT_EQ(b.drive.state(), DriveState::kSwitchedOn);
  EXPECT_EQ(b.drive.velocity_command_radps(), 0.0);
}

TEST(DriveNodeTest, QuickStopRampsToZeroThenSwitchOnDisabled) {
  Bench b;
  b.Start();
  ASSERT_TRUE(b.Enable());
  b.Cycle(0x000F, 2.0);
  b.drive.SetFeedback({0.1, 2.0});
  b.Cycle(cia402::ControlwordOf(cia402::Command::kQuickStop), 2.0);
  EXPECT_EQ(b.drive.state(), DriveState::kQuickStopActive);
  EXPECT_LT(b.drive.velocity_command_radps(), 2.0);
  EXPECT_GT(b.drive.velocity_command_radps(), 1.9) << "a ramp at 6.28 rad/s^2, not a step";
  for (int i = 0; i < 100; ++i) b.Cycle(cia402::ControlwordOf(cia402::Command::kQuickStop), 2.0);
  EXPECT_EQ(b.drive.velocity_command_radps(), 0.0);
  EXPECT_EQ(b.drive.state(), DriveState::kQuickStopActive) << "the joint still moves (feedback 2 rad/s)";
  b.drive.SetFeedback({0.3, 0.0});
  b.Cycle(cia402::ControlwordOf(cia402::Command::kQuickStop), 2.0);
  EXPECT_EQ(b.drive.state(), DriveState::kSwitchOnDisabled);
}

TEST(DriveNodeTest, FaultSendsEmcyAndNeedsAFaultReset) {
  Bench b;
  b.Start();
  ASSERT_TRUE(b.Enable());
  b.Cycle(0x000F, 1.0);
  b.out.clear();
  b.drive.InjectFault(0x2310, b.t, &b.out);
  const auto emcy = OfFunction(b.out, canopen::CanopenFunction::kEmcy);
  ASSERT_EQ(emcy.size(), 1u);
  const auto decoded = canopen::DecodeEmcy(emcy[0], nullptr);
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->error_code, 0x2310);
  EXPECT_NE(decoded->error_register & canopen::error_register::kGeneric, 0);
  EXPECT_EQ(b.drive.state(), DriveState::kFaultReactionActive);
  for (int i = 0; i < 60; ++i) b.Cycle(0x000F, 1.0);
  EXPECT_EQ(b.drive.state(), DriveState::kFault);
  EXPECT_EQ(b.drive.velocity_command_radps(), 0.0);
  EXPECT_EQ(b.drive.counts().refused_controlwords > 0, true) << "enable operation is refused in Fault";
  // The host's helper resets it (0x0080 edge): EMCY "error reset", then back to enabled.
  b.out.clear();
  b.Cycle(0x0080, 0.0);
  EXPECT_EQ(b.drive.state(), DriveState::kSwitchOnDisabled);
  const auto reset = OfFunction(b.out, canopen::CanopenFunction::kEmcy);
  ASSERT_EQ(reset.size(), 1u);
  EXPECT_EQ(canopen::DecodeEmcy(reset[0], nullptr)->error_code, canopen::emcy_code::kErrorResetOrNoError);
  EXPECT_TRUE(b.Enable());
}

TEST(DriveNodeTest, HeartbeatAtTheProducerTime) {
  Bench b;
  b.Step();
  b.out.clear();
  std::vector<double> times;
  for (int i = 0; i < 200; ++i) {  // 1 s
    const std::size_t before = b.out.size();
    b.Step();
    for (std::size_t k = before; k < b.out.size(); ++k) {
      if (const auto hb = canopen::DecodeHeartbeat(b.out[k], nullptr)) {
        EXPECT_EQ(hb->state, NmtState::kPreOperational);
        times.push_back(b.t);
      }
    }
  }
  ASSERT_GE(times.size(), 9u);
  ASSERT_LE(times.size(), 11u);
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_NEAR(times[i] - times[i - 1], 0.1, 0.0051);
  // Suppressed (injected heartbeat loss): none.
  b.out.clear();
  for (int i = 0; i < 100; ++i) {
    b.t += 0.005;
    b.drive.Step(b.t, true, &b.out);
  }
  EXPECT_TRUE(OfFunction(b.out, canopen::CanopenFunction::kHeartbeat).empty());
}

TEST(DriveNodeTest, LostHostHeartbeatFaultsTheDrive) {
  Bench b;
  b.Start();
  ASSERT_EQ(b.Write({0x1016, 1}, 4, (127u << 16) | 300u), 0u);
  ASSERT_TRUE(b.Enable());
  const can::CanFrame host = *canopen::EncodeHeartbeat({127, NmtState::kOperational}, nullptr);
  for (int i = 0; i < 40; ++i) {  // 0.2 s with the host's heartbeat every 0.1 s
    if (i % 20 == 0) b.drive.OnFrame(host, b.t, &b.out);
    b.Cycle(0x000F, 0.5);
  }
  EXPECT_EQ(b.drive.state(), DriveState::kOperationEnabled);
  std::vector<can::CanFrame> sent;
  for (int i = 0; i < 80; ++i) {  // 0.4 s of silence
    b.Cycle(0x000F, 0.5);
    sent.insert(sent.end(), b.out.begin(), b.out.end());
  }
  EXPECT_EQ(b.drive.counts().host_heartbeat_lost, 1);
  EXPECT_TRUE(b.drive.state() == DriveState::kFault || b.drive.state() == DriveState::kFaultReactionActive);
  bool heartbeat_emcy = false;
  for (const can::CanFrame& f : OfFunction(sent, canopen::CanopenFunction::kEmcy)) {
    heartbeat_emcy = heartbeat_emcy || canopen::DecodeEmcy(f, nullptr)->error_code == canopen::emcy_code::kHeartbeatError;
  }
  EXPECT_TRUE(heartbeat_emcy);
}

bool SentEmcy(const std::vector<can::CanFrame>& frames, std::uint16_t code) {
  for (const can::CanFrame& f : OfFunction(frames, canopen::CanopenFunction::kEmcy)) {
    if (canopen::DecodeEmcy(f, nullptr)->error_code == code) return true;
  }
  return false;
}

TEST(DriveNodeTest, NoRpdoWithinTheDeadlineFaultsTheDriveAndRampsTheJointToZero) {
  Bench b;
  b.Start();
  ASSERT_EQ(b.Write({0x1400, 5}, 2, 50), 0u);  // RPDO1's event timer: a 50 ms deadline
  ASSERT_TRUE(b.Enable());
  for (int i = 0; i < 20; ++i) b.Cycle(0x000F, 1.0);
  ASSERT_DOUBLE_EQ(b.drive.velocity_command_radps(), 1.0);
  // SYNCs go on but the setpoints stop (the host died between the two): 45 ms is within the
  // deadline, the drive keeps its last setpoint; by 60 ms it has given up on the host.
  std::vector<can::CanFrame> sent;
  for (int i = 0; i < 8; ++i) b.Cycle(std::nullopt);
  EXPECT_EQ(b.drive.counts().rpdo_timeouts, 0);
  EXPECT_EQ(b.drive.state(), DriveState::kOperationEnabled);
  EXPECT_DOUBLE_EQ(b.drive.velocity_command_radps(), 1.0);
  for (int i = 0; i < 3; ++i) {
    b.Cycle(std::nullopt);
    sent.insert(sent.end(), b.out.begin(), b.out.end());
  }
  EXPECT_EQ(b.drive.counts().rpdo_timeouts, 1);
  EXPECT_TRUE(SentEmcy(sent, canopen::emcy_code::kRpdoTimeout));
  EXPECT_EQ(b.drive.dictionary().Get({0x603F, 0}), canopen::emcy_code::kRpdoTimeout);
  EXPECT_EQ(b.drive.state(), DriveState::kFaultReactionActive);
  EXPECT_LT(b.drive.velocity_command_radps(), 1.0);  // ramping down at the quick-stop deceleration
  // 1 rad/s at 6.28 rad/s^2: at zero within 0.16 s, then Fault; one timeout per silence.
  for (int i = 0; i < 40; ++i) b.Cycle(std::nullopt);
  EXPECT_EQ(b.drive.velocity_command_radps(), 0.0);
  EXPECT_EQ(b.drive.state(), DriveState::kFault);
  EXPECT_EQ(b.drive.counts().rpdo_timeouts, 1);
}

TEST(DriveNodeTest, TheDeadlineIsWatchedOnlyWhenSetAndOnlyWhileOperational) {
  Bench unset;  // power-on: event timer 0, no monitoring (the setpoint is simply kept)
  unset.Start();
  ASSERT_TRUE(unset.Enable());
  unset.Cycle(0x000F, 0.5);
  for (int i = 0; i < 100; ++i) unset.Cycle(std::nullopt);
  EXPECT_EQ(unset.drive.counts().rpdo_timeouts, 0);
  EXPECT_EQ(unset.drive.state(), DriveState::kOperationEnabled);

  Bench pre_op;  // set, but the host takes the drive out of operational: no PDOs are expected
  pre_op.Start();
  ASSERT_EQ(pre_op.Write({0x1400, 5}, 2, 50), 0u);
  ASSERT_TRUE(pre_op.Enable());
  pre_op.Cycle(0x000F, 0.5);
  pre_op.drive.OnFrame(Nmt(canopen::NmtCommand::kEnterPreOperational), pre_op.t, &pre_op.out);
  for (int i = 0; i < 40; ++i) pre_op.Step();
  EXPECT_EQ(pre_op.drive.counts().rpdo_timeouts, 0);
  // Operational again: the watch starts with the next RPDO1, not with the NMT start.
  pre_op.drive.OnFrame(Nmt(canopen::NmtCommand::kStartRemoteNode), pre_op.t, &pre_op.out);
  for (int i = 0; i < 40; ++i) pre_op.Cycle(std::nullopt);
  EXPECT_EQ(pre_op.drive.counts().rpdo_timeouts, 0);
  pre_op.Cycle(0x000F, 0.5);
  for (int i = 0; i < 12; ++i) pre_op.Cycle(std::nullopt);
  EXPECT_EQ(pre_op.drive.counts().rpdo_timeouts, 1);
}

// kill-canbridge: a drive faulted by its RPDO deadline while the bridge was dead; the restarted
// bridge resets its communication and reads 0x603F to see whether it may reset the fault itself.
// The code must survive the reset communication (it read 0 before: the operator was needed).
TEST(DriveNodeTest, ResetCommunicationKeepsAFaultAndItsCodeButResetsTheCommunicationObjects) {
  Bench b;
  b.Start();
  ASSERT_EQ(b.Write({0x1400, 5}, 2, 50), 0u);
  ASSERT_EQ(b.Write({0x1016, 1}, 4, (127u << 16) | 300u), 0u);
  ASSERT_TRUE(b.Enable());
  b.Cycle(0x000F, 0.5);
  for (int i = 0; i < 60; ++i) b.Cycle(std::nullopt);  // 0.3 s without setpoints: 0x8250
  ASSERT_EQ(b.drive.state(), DriveState::kFault);
  b.drive.OnFrame(Nmt(canopen::NmtCommand::kResetCommunication), b.t, &b.out);
  b.Step();
  EXPECT_EQ(b.drive.nmt_state(), NmtState::kPreOperational);
  EXPECT_EQ(b.drive.state(), DriveState::kFault);
  EXPECT_EQ(b.drive.dictionary().Get({0x603F, 0}), canopen::emcy_code::kRpdoTimeout);
  EXPECT_NE(b.drive.dictionary().Get({0x1001, 0}) & canopen::error_register::kCommunication, 0u);
  EXPECT_EQ(b.drive.dictionary().rpdo1_deadline_ms(), 0);  // communication objects: power-on
  EXPECT_EQ(b.drive.dictionary().consumer_heartbeat_ms(), 0);
  const auto reply = b.Sdo(*canopen::EncodeSdoUploadRequest({kNode, {0x603F, 0}}, nullptr));
  ASSERT_TRUE(reply);
  const auto* upload = std::get_if<canopen::SdoUploadResponse>(&*reply);
  ASSERT_NE(upload, nullptr);
  EXPECT_EQ(upload->value, canopen::emcy_code::kRpdoTimeout);
  // Reset node: the whole drive to power-on, the fault cleared.
  b.drive.OnFrame(Nmt(canopen::NmtCommand::kResetNode), b.t, &b.out);
  b.Step();
  EXPECT_NE(b.drive.state(), DriveState::kFault);
  EXPECT_EQ(b.drive.dictionary().Get({0x603F, 0}), 0u);
}

}  // namespace
}  // namespace topay::sim::motors
