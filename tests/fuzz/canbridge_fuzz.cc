// topay-canbridge's node (procs/canbridge/canbridge_node.h, options from
// config/canbridge/canbridge.yaml) on the in-memory bus with the base and drive peers
// (tests/procs/canbridge/canbridge_rig.h), driven by a fuzzed sequence of CONTROL_COMMANDs (decoded
// from fuzzed bytes, or built from fuzzed doubles: NaN, infinities, huge, wrong joint counts, at
// fuzzed times, backwards too), DRIVE_COMMANDs, fuzzed frames and error frames (bus-off and its
// restart) into the bridge's receive queue or onto the wire, the peers falling silent, faulting,
// power cycling or aborting start-up writes, the interface going down, and cycles at the regular
// period or at fuzzed times (backwards too). Checked on every frame the bridge sends, with the
// state it sent it in: the envelope of tests/procs/canbridge/sent_frame_limits.h (velocity limits,
// acceleration limits between consecutive frames, zero outside RUNNING and after the command
// timeout, only its own ids, decodable); after every call the limiter's command is finite. And
// liveness at the end: with the devices and the bus healed (peers answering, no start-up aborts,
// interface up, bus-off restarted, the clock past any time it was given) and zero commands with
// an operator's fault reset, the bridge is RUNNING again within kRecoveryLimitS.
//
// Input: [start] then ops until the input ends (at most kMaxOps and kMaxCycles cycles), each [op]
// + arguments. start bit 0: first cycle until RUNNING (at most 3 s). op % 8:
//   0 [n] n % 16 + 1 cycles at the configured period;
//   1 [i16 dt, 0.1 ms] one cycle, then the clock moves by dt (backwards when negative);
//   2 [selector][u16 length][bytes][i8 offset, ms] a control_command_t decoded from the bytes
//     (lcm_fuzz.h; selector bit 7 fixes the fingerprint) received at now + offset;
//   3 [v][omega][joints][qdot x n][i8 offset, 0.5 ms] a control_command_t built from values, each
//     value [tag] + (tag % 4: 0 a raw double, 1 an i16 in 1e-3, 2 one of kSpecial, 3 zero);
//     joints < 240: the robot's count, else a wrong count;
//   4 [command][source length] a drive_command_t;
//   5 a frame record (can_fuzz.h) put into the bridge's receive queue; addressed: flags bit 5 the
//     base protocol id of kind (id % 6) (seal: its checksum), else CANopen function (id % 14) of
//     node (id >> 8) % 8;
//   6 [u32 class bits][controller][tx errors][rx errors] an error frame into the bridge's queue;
//   7 [action][argument] a peer or link event (see PeerEvent).
#include <linux/can/error.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/io/robot_loader.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_drive_model.h"
#include "drivers/base/fault_codes.h"
#include "drivers/base/frame_bytes.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/can/can_error.h"
#include "procs/canbridge/canbridge_node.h"
#include "procs/canbridge/canbridge_options.h"
#include "tests/fuzz/can_frame_kinds.h"
#include "tests/fuzz/can_fuzz.h"
#include "tests/fuzz/fuzz_check.h"
#include "tests/fuzz/lcm_fuzz.h"
#include "tests/procs/canbridge/canbridge_rig.h"
#include "tests/procs/canbridge/memory_can_bus.h"
#include "tests/procs/canbridge/sent_frame_limits.h"
#include "topay/control_command_t.hpp"
#include "topay/drive_command_t.hpp"

namespace topay::fuzz {
namespace {

using canbridge::BridgeState;
using canbridge::CanbridgeOptions;
using canbridge::test::MemoryCanBus;
using canbridge::test::Rig;
using canbridge::test::SentFrameLimits;

constexpr int kMaxOps = 2000;
constexpr int kMaxCycles = 6000;  // 30 s of the 5 ms cycle
// Healed, the bridge recovers within this (hold 0.5 s, start-up retries 1 s, enable timeout 3 s).
constexpr double kRecoveryLimitS = 10.0;
constexpr double kSpecial[] = {std::numeric_limits<double>::quiet_NaN(),
                               std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity(),
                               1e300,
                               -1e300,
                               std::numeric_limits<double>::denorm_min(),
                               -0.0,
                               std::numeric_limits<double>::max(),
                               1e-9,
                               -4.0};
// Objects of the start-up writes a drive peer may be told to abort (docs/cia402.md).
constexpr std::uint16_t kStartupIndexes[] = {0x1400, 0x1600, 0x1800, 0x1A00, 0x1017, 0x1016, 0x60C2, 0x6060};

const CanbridgeOptions& ConfigOptions() {
  static const CanbridgeOptions options =
      canbridge::LoadCanbridgeOptions(std::string(TOPAY_SOURCE_DIR) + "/config/canbridge/canbridge.yaml");
  return options;
}

// The rig, a third node on its wire for rogue frames, and the envelope check of every frame the
// bridge sends.
class Bench {
 public:
  explicit Bench(const CanbridgeOptions& options)
      : rig_(options), rogue_(rig_.wire, "fuzz"), limits_(options, rig_.node.limiter().limits()) {}

  Rig& rig() { return rig_; }
  MemoryCanBus& rogue() { return rogue_; }
  int cycles() const { return cycles_; }
  double now() const { return rig_.t; }
  /// The latest time the bridge or a peer was given (the healed clock starts after it: a base
  /// told a later time refuses requests stamped before it, "time went back").
  double latest() const { return latest_s_; }
  void NoteTime(double t_s) { latest_s_ = std::max(latest_s_, t_s); }

  // One bridge cycle at the rig's time, the peers' step, then the clock moves by dt_s.
  void Cycle(double dt_s) {
    const double now_s = rig_.t;
    NoteTime(now_s);
    rig_.node.Cycle(now_s, static_cast<std::int64_t>(now_s * 1e6));
    CheckSent(now_s);
    rig_.peers.Step(now_s);
    can::ReceivedCanFrame ignored;
    while (rogue_.Receive(0.0, &ignored).ok()) {
    }
    rig_.t += dt_s;
    ++cycles_;
  }

  void Command(const control_command_t& msg, double now_s) {
    const std::int64_t before = rig_.node.commands_received();
    NoteTime(now_s);
    rig_.node.OnCommand(msg, now_s);
    if (rig_.node.commands_received() != before) limits_.OnValidCommand(now_s);
    CheckSent(now_s);
  }

  void DriveCommand(const drive_command_t& msg) {
    NoteTime(rig_.t);
    rig_.node.OnDriveCommand(msg, rig_.t);
    CheckSent(rig_.t);
  }

 private:
  void CheckSent(double now_s) {
    for (const auto& [stamp_ns, frame] : rig_.bridge_bus.sent) {
      const std::string problem = limits_.Check(frame, now_s, rig_.node.state());
      if (!problem.empty()) {
        std::fprintf(stderr, "canbridge sent %s\n", problem.c_str());
        FuzzCheck(false, "every frame the bridge sends keeps the envelope (sent_frame_limits.h)");
      }
    }
    rig_.bridge_bus.sent.clear();
    limits_.OnState(rig_.node.state(), now_s);
    const canbridge::DeviceCommand& last = rig_.node.limiter().last();
    bool finite = std::isfinite(last.v_mps) && std::isfinite(last.omega_radps);
    for (const double q : last.qdot_radps) finite = finite && std::isfinite(q);
    FuzzCheck(finite, "the limiter's command is finite");
  }

  Rig rig_;
  MemoryCanBus rogue_;
  SentFrameLimits limits_;
  int cycles_ = 0;
  double latest_s_ = 0.0;
};

double NextValue(FuzzReader& in) {
  switch (in.Byte() % 4) {
    case 0:
      return in.RawDouble();
    case 1:
      return static_cast<std::int16_t>(in.U16()) * 1e-3;
    case 2:
      return kSpecial[in.Byte() % std::size(kSpecial)];
    default:
      return 0.0;
  }
}

control_command_t BuiltCommand(FuzzReader& in, Bench& bench) {
  control_command_t msg{};
  msg.utime = static_cast<std::int64_t>(in.U32());
  msg.v_mps = NextValue(in);
  msg.omega_radps = NextValue(in);
  const int robot_joints = bench.rig().model.num_joints();
  const std::uint8_t joints = in.Byte();
  constexpr int kWrongCounts[] = {0, -1, 1, 6, 8, 1000};
  msg.num_joints = joints < 240 ? robot_joints : kWrongCounts[joints % std::size(kWrongCounts)];
  // Joints 255: the count right, the array one short (a message the decoder would not give).
  const int entries = joints == 255 ? robot_joints - 1 : std::clamp(msg.num_joints, 0, 16);
  for (int i = 0; i < entries; ++i) msg.qdot_radps.push_back(NextValue(in));
  if (joints == 255) msg.num_joints = robot_joints;
  return msg;
}

can::CanFrame AddressedFrame(FuzzReader& in, const CanbridgeOptions& options) {
  return ReceivableFrame(in, options.base.node_id);
}

// A peer or link event: action % 8: 0 the base falls silent or speaks again; 1 drive (argument)
// likewise; 2 the drive faults (EMCY code from the next two bytes); 3 the base raises fault
// (argument % 10 + 1); 4 the drive power-cycles (boot-up); 5 the drive aborts the start-up
// write of an object (or no longer); 6 the bridge's interface goes down or comes back; 7 a rogue
// node puts a frame record on the wire (everyone receives it).
void PeerEvent(FuzzReader& in, Bench& bench, const CanbridgeOptions& options) {
  Rig& rig = bench.rig();
  bench.NoteTime(rig.t);  // a fault raised in the base is stamped with it
  const std::uint8_t action = in.Byte();
  const std::uint8_t argument = in.Byte();
  auto& drive = rig.peers.drives[argument % rig.peers.drives.size()];
  std::vector<can::CanFrame> out;
  switch (action % 8) {
    case 0:
      rig.peers.base.silent = !rig.peers.base.silent;
      break;
    case 1:
      drive.silent = !drive.silent;
      break;
    case 2:
      drive.Fault(in.U16(), &out);
      break;
    case 3:
      rig.peers.base.RaiseFault(static_cast<base::BaseFault>(argument % base::kMaxFaultCode + 1), rig.t, &out);
      break;
    case 4:
      drive.model = cia402::DriveModel{};
      drive.PowerOn(&out);
      break;
    case 5:
      if (argument & 0x80) {
        drive.abort_index.reset();
      } else {
        drive.abort_index = kStartupIndexes[argument % std::size(kStartupIndexes)];
      }
      break;
    case 6:
      rig.bridge_bus.down = !rig.bridge_bus.down;
      break;
    default:
      bench.rogue().Send(AddressedFrame(in, options));
      break;
  }
  rig.peers.Send(out);
}

// Heals the devices and the bus, then gives zero commands (and a fault reset when in FAULT) until
// the bridge runs again: it must, within kRecoveryLimitS.
void CheckRecovers(Bench& bench) {
  Rig& rig = bench.rig();
  rig.peers.base.silent = false;
  for (auto& drive : rig.peers.drives) {
    drive.silent = false;
    drive.abort_index.reset();
  }
  rig.bridge_bus.down = false;
  rig.bridge_bus.Inject(can::MakeCanErrorFrame(CAN_ERR_RESTARTED));
  rig.peer_bus.Inject(can::MakeCanErrorFrame(CAN_ERR_RESTARTED));  // rogue error frames reach the peers too
  rig.t = bench.latest() + 1.0;
  const double until_s = rig.t + kRecoveryLimitS;
  control_command_t zero{};
  zero.num_joints = rig.model.num_joints();
  zero.qdot_radps.assign(static_cast<std::size_t>(zero.num_joints), 0.0);
  drive_command_t reset{};
  reset.command = drive_command_t::FAULT_RESET;
  reset.source = "fuzz";
  for (int i = 0; rig.t < until_s && rig.node.state() != BridgeState::kRunning; ++i) {
    if (i % 4 == 0) bench.Command(zero, rig.t);
    if (i % 100 == 0 && rig.node.state() == BridgeState::kFault) bench.DriveCommand(reset);
    bench.Cycle(rig.options.cycle_period_s);
  }
  if (rig.node.state() != BridgeState::kRunning) {
    std::fprintf(stderr, "canbridge healed but not running after %.1f s: %s\n", kRecoveryLimitS,
                 rig.node.StatusLine(rig.t).c_str());
    FuzzCheck(false, "a healed bridge with zero commands (and a fault reset) runs again");
  }
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  spdlog::set_level(spdlog::level::off);  // the bridge logs every state change
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  using namespace topay;
  const CanbridgeOptions& options = ConfigOptions();
  FuzzReader in(data, size);
  Bench bench(options);
  if (in.Byte() & 1) {
    for (int i = 0; i < 600 && bench.rig().node.state() != BridgeState::kRunning; ++i) {
      bench.Cycle(options.cycle_period_s);
    }
  }
  for (int op = 0; op < kMaxOps && !in.empty() && bench.cycles() < kMaxCycles; ++op) {
    switch (in.Byte() % 8) {
      case 0: {
        const int n = in.Byte() % 16 + 1;
        for (int i = 0; i < n; ++i) bench.Cycle(options.cycle_period_s);
        break;
      }
      case 1:
        bench.Cycle(static_cast<std::int16_t>(in.U16()) * 1e-4);
        break;
      case 2: {
        const LcmRecord record = NextLcmRecord(in);
        const double offset_s = static_cast<std::int8_t>(in.Byte()) * 1e-3;
        if (const auto msg = DecodeFuzzed<control_command_t>(record.bytes, record.fix_fingerprint)) {
          bench.Command(*msg, bench.now() + offset_s);
        }
        break;
      }
      case 3: {
        const control_command_t msg = BuiltCommand(in, bench);
        bench.Command(msg, bench.now() + static_cast<std::int8_t>(in.Byte()) * 5e-4);
        break;
      }
      case 4: {
        drive_command_t msg{};
        msg.utime = static_cast<std::int64_t>(bench.now() * 1e6);
        msg.command = static_cast<std::int8_t>(in.Byte());
        msg.source = std::string(in.Byte() % 16, 'f');
        bench.DriveCommand(msg);
        break;
      }
      case 5:
        bench.rig().bridge_bus.Inject(AddressedFrame(in, options));
        break;
      case 6: {
        const std::uint32_t class_bits = in.U32();
        const std::uint8_t controller = in.Byte();
        const int tx = in.Byte();
        const int rx = in.Byte();
        bench.rig().bridge_bus.Inject(can::MakeCanErrorFrame(class_bits, controller, tx, rx));
        break;
      }
      default:
        PeerEvent(in, bench, options);
        break;
    }
  }
  CheckRecovers(bench);
  return 0;
}
