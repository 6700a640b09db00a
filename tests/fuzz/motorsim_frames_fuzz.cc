// The motor simulator's device side (sim/motors/motor_sim.h: the wheel controller and the seven
// CiA 402 drives behind the fault injector, options from config/sim/motorsim.yaml) driven by a
// fuzzed sequence of received frames, time steps with a fuzzed plant, run-time faults and
// host-like frames. Checked after every step: every frame it sends is a valid CAN frame
// (can::CheckCanFrame), error frames aside a standard data frame from one of its own nodes that
// the host's decoder of that kind accepts (the base's status, wheel speeds, odometry, fault; a
// drive's TPDO1/2, EMCY, SDO reply, heartbeat); the actuator command is finite, each joint rate
// within its drive's velocity limit and the wheels within the motors' top speed; the number of
// frames sent stays proportional to the work given.
//
// Input: [fault seed] then ops until the input ends (at most kMaxOps, simulated time at most
// kMaxTimeS), each [op] + arguments, op % 6:
//   0 receive a frame record (can_fuzz.h). Addressed: flags bit 5 set: the base protocol's id of
//     kind (id % 6) for the base's node (seal: its checksum); clear: CANopen function (id % 14)
//     for node (id >> 8) % 8;
//   1 step after [dt, ms][plant?]; with plant (odd): [i16 v, mm/s][i16 omega, mrad/s]
//     [7 x i8 q, 0.05 rad][7 x i8 qdot, 0.05 rad/s]; else no plant state;
//   2 inject a fault [kind][joint, i8][u16 duration, ms][u16 value, 0.01][u16 code][raw?]; raw
//     (odd) then [double duration][double value] replace duration and value;
//   3 a frame a host would send, well formed: [which][node][u16 a][u16 b][c];
//   4 run [n] steps of the configured period with the plant following the command;
//   5 receive an error frame [u32 class bits][controller bits][tx errors][rx errors].
#include <linux/can/error.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/sync.h"
#include "drivers/base/diff_drive_kinematics.h"
#include "drivers/base/fault_frame.h"
#include "drivers/base/frame_bytes.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "drivers/can/can_error.h"
#include "sim/motors/motor_sim.h"
#include "sim/motors/motorsim_options.h"
#include "tests/fuzz/can_frame_kinds.h"
#include "tests/fuzz/can_fuzz.h"
#include "tests/fuzz/fuzz_check.h"

namespace topay::fuzz {
namespace {

using sim::motors::MotorSim;
using sim::motors::MotorSimOptions;

constexpr int kMaxOps = 2000;
constexpr double kMaxTimeS = 120.0;

// The objects the host writes at start-up and the process data ones (drivers/arm/startup_sdo.h,
// docs/cia402.md), for SDO requests that reach the dictionary's rules.
constexpr std::array<canopen::ObjectAddress, 12> kObjects = {{{0x1017, 0},
                                                              {0x1016, 1},
                                                              {0x6040, 0},
                                                              {0x6060, 0},
                                                              {0x60C2, 1},
                                                              {0x1400, 1},
                                                              {0x1600, 0},
                                                              {0x1600, 1},
                                                              {0x1800, 2},
                                                              {0x1A00, 1},
                                                              {0x6041, 0},
                                                              {0x1001, 0}}};

const MotorSimOptions& ConfigOptions() {
  static const MotorSimOptions options =
      sim::motors::LoadMotorSimOptions(std::string(TOPAY_SOURCE_DIR) + "/config/sim/motorsim.yaml");
  return options;
}

// The simulator, its clock and the plant it drives.
class Bench {
 public:
  explicit Bench(const MotorSimOptions& options) : options_(options), sim_(options, 0.0) {
    plant_.state.q_rad = Eigen::VectorXd::Zero(sim_.num_joints());
    plant_.qdot_radps = Eigen::VectorXd::Zero(sim_.num_joints());
  }

  double now() const { return now_s_; }
  MotorSim& sim() { return sim_; }
  sim::PlantState& plant() { return plant_; }
  void CountInjected() { ++injected_; }

  void Step(double dt_s, bool with_plant) {
    now_s_ += dt_s;
    std::vector<can::CanFrame> out;
    sim_.Step(now_s_, with_plant ? &plant_ : nullptr, &out);
    CheckSent(out);
    CheckCommand();
  }

  // The plant follows the actuator command for one step of `dt_s`.
  void Follow(double dt_s) {
    const sim::ActuatorCommand command = sim_.command();
    plant_.v_mps = command.v_mps;
    plant_.omega_radps = command.omega_radps;
    plant_.qdot_radps = command.qdot_radps;
    plant_.state.q_rad += command.qdot_radps * dt_s;
  }

 private:
  void CheckSent(const std::vector<can::CanFrame>& out) const {
    for (const can::CanFrame& frame : out) {
      FuzzCheck(can::CheckCanFrame(frame).empty(), "the simulator sends only valid frames");
      if (frame.error) {
        FuzzCheck(!can::DecodeCanErrorFrame(frame).description.empty(), "an error frame it sends says something");
        continue;
      }
      FuzzCheck(!frame.extended && !frame.remote, "the nodes send standard data frames");
      if (const auto kind = base::IdentifyFrame(frame, options_.base.node_id, nullptr)) {
        CheckBaseFrame(frame, *kind);
      } else {
        CheckDriveFrame(frame);
      }
    }
  }

  void CheckBaseFrame(const can::CanFrame& frame, base::BaseFrameKind kind) const {
    const int node = options_.base.node_id;
    std::string error;
    bool ok = false;
    switch (kind) {
      case base::BaseFrameKind::kStatus:
        ok = base::DecodeStatus(frame, node, &error).has_value();
        break;
      case base::BaseFrameKind::kWheelSpeeds:
        ok = base::DecodeWheelSpeeds(frame, node, &error).has_value();
        break;
      case base::BaseFrameKind::kOdometry:
        ok = base::DecodeOdometry(frame, node, std::nullopt, &error).has_value();
        break;
      case base::BaseFrameKind::kFault:
        ok = base::DecodeFault(frame, node, &error).has_value();
        break;
      case base::BaseFrameKind::kModeRequest:
      case base::BaseFrameKind::kVelocityCommand:
        FuzzCheck(false, "the wheel controller never sends the host's frames");
    }
    FuzzCheck(ok, "every base frame it sends decodes on the host");
  }

  void CheckDriveFrame(const can::CanFrame& frame) const {
    const auto cob = canopen::ClassifyCobId(frame.id, nullptr);
    FuzzCheck(cob.has_value(), "every CANopen frame it sends has a COB-ID of the predefined set");
    bool ours = false;
    for (const int id : options_.joint_node_ids) ours = ours || id == cob->node_id;
    FuzzCheck(ours, "every CANopen frame it sends is from one of its drives");
    const cia402::JointUnits& units = options_.drive.units;
    bool ok = false;
    switch (cob->function) {
      case canopen::CanopenFunction::kEmcy:
        ok = canopen::DecodeEmcy(frame, nullptr).has_value();
        break;
      case canopen::CanopenFunction::kTpdo1:
        ok = cia402::DecodeTpdo1(frame, units, nullptr).has_value();
        break;
      case canopen::CanopenFunction::kTpdo2:
        ok = cia402::DecodeTpdo2(frame, units, nullptr).has_value();
        break;
      case canopen::CanopenFunction::kSdoTx:
        ok = canopen::DecodeSdoServerReply(frame, nullptr).has_value();
        break;
      case canopen::CanopenFunction::kHeartbeat:
        ok = canopen::DecodeHeartbeat(frame, nullptr).has_value();
        break;
      default:
        FuzzCheck(false, "a drive sends only EMCY, TPDO1/2, SDO replies and heartbeats");
    }
    FuzzCheck(ok, "every drive frame it sends decodes on the host");
  }

  void CheckCommand() const {
    const sim::ActuatorCommand command = sim_.command();
    FuzzCheck(sim::CheckActuatorCommand(command, sim_.num_joints()).empty(), "the actuator command is well formed");
    for (int k = 0; k < sim_.num_joints(); ++k) {
      FuzzCheck(std::abs(command.qdot_radps[k]) <= options_.drive.max_velocity_radps,
                "a joint rate is within its drive's velocity limit");
    }
    const base::WheelSpeeds wheels =
        base::UnicycleToWheelSpeeds({command.v_mps, command.omega_radps}, options_.base.geometry);
    const double top = options_.base.max_wheel_speed_radps * (1.0 + 1e-9);
    FuzzCheck(std::abs(wheels.left_rad_per_s) <= top && std::abs(wheels.right_rad_per_s) <= top,
              "the wheels are within the motors' top speed");
    const sim::motors::MotorSimCounts& counts = sim_.counts();
    FuzzCheck(counts.frames_sent <= 64 * (counts.steps + counts.frames_received + injected_ + 1),
              "the frames sent stay proportional to the steps, frames and faults given");
  }

  const MotorSimOptions& options_;
  MotorSim sim_;
  sim::PlantState plant_;
  double now_s_ = 0.0;
  std::int64_t injected_ = 0;
};

void ReceiveFrameRecord(FuzzReader& in, Bench& bench, const MotorSimOptions& options) {
  bench.sim().Receive(ReceivableFrame(in, options.base.node_id), bench.now());
}

void StepWithPlant(FuzzReader& in, Bench& bench) {
  const double dt_s = in.Byte() * 1e-3;
  const bool with_plant = in.Byte() % 2 == 1;
  if (with_plant) {
    sim::PlantState& plant = bench.plant();
    plant.v_mps = static_cast<std::int16_t>(in.U16()) * 1e-3;
    plant.omega_radps = static_cast<std::int16_t>(in.U16()) * 1e-3;
    for (Eigen::Index k = 0; k < plant.state.q_rad.size(); ++k) {
      plant.state.q_rad[k] = static_cast<std::int8_t>(in.Byte()) * 0.05;
    }
    for (Eigen::Index k = 0; k < plant.qdot_radps.size(); ++k) {
      plant.qdot_radps[k] = static_cast<std::int8_t>(in.Byte()) * 0.05;
    }
  }
  bench.Step(dt_s, with_plant);
}

void InjectFault(FuzzReader& in, Bench& bench) {
  sim::motors::FaultEvent event;
  event.kind = static_cast<sim::motors::FaultKind>(in.Byte() % 8);
  event.joint = static_cast<std::int8_t>(in.Byte());
  event.duration_s = in.U16() * 1e-3;
  event.value = in.U16() * 0.01;
  event.code = in.U16();
  if (in.Byte() % 2 == 1) {
    event.duration_s = in.RawDouble();
    event.value = in.RawDouble();
  }
  const std::string why = bench.sim().Inject(event, bench.now());
  FuzzCheck(why.empty() ==
                sim::motors::CheckFaultEvent({event.kind, 0.0, event.joint, event.duration_s, event.value, event.code},
                                             bench.sim().num_joints())
                    .empty(),
            "a run-time fault is refused exactly when it is malformed");
  bench.CountInjected();
}

// A well-formed frame of what a host sends (the protocols' own encoders), so that the nodes'
// state machines are reached without guessing checksums.
void ReceiveHostFrame(FuzzReader& in, Bench& bench, const MotorSimOptions& options) {
  const int which = in.Byte() % 8;
  const int node = options.joint_node_ids[in.Byte() % options.joint_node_ids.size()];
  const std::uint16_t a = in.U16();
  const std::uint16_t b = in.U16();
  const std::uint8_t c = in.Byte();
  std::optional<can::CanFrame> frame;
  switch (which) {
    case 0: {
      constexpr canopen::NmtCommand kCommands[] = {
          canopen::NmtCommand::kStartRemoteNode, canopen::NmtCommand::kStopRemoteNode,
          canopen::NmtCommand::kEnterPreOperational, canopen::NmtCommand::kResetNode,
          canopen::NmtCommand::kResetCommunication};
      frame = canopen::EncodeNmt({kCommands[c % 5], c >= 128 ? 0 : node}, nullptr);
      break;
    }
    case 1:
      frame = canopen::EncodeSync({}, nullptr);
      break;
    case 2: {
      const double target = static_cast<std::int16_t>(b) * 1e-4;  // +-3.3 rad/s: beyond the bound too
      frame = cia402::EncodeRpdo1({node, a, target}, options.drive.units, nullptr);
      if (!frame) frame = cia402::EncodeRpdo1({node, a, 0.0}, options.drive.units, nullptr);
      break;
    }
    case 3: {
      const canopen::ObjectAddress address = kObjects[c % kObjects.size()];
      const int size = 1 + (c >> 6);
      const std::uint32_t value =
          (std::uint32_t{a} | (std::uint32_t{b} << 16)) & (size == 4 ? 0xFFFFFFFFu : (1u << (8 * size)) - 1);
      frame = canopen::EncodeSdoDownloadRequest({node, address, size, value}, nullptr);
      break;
    }
    case 4:
      frame = canopen::EncodeSdoUploadRequest({node, kObjects[c % kObjects.size()]}, nullptr);
      break;
    case 5:
      frame = base::EncodeModeRequest(static_cast<base::ModeRequest>(c % 4), options.base.node_id, nullptr);
      break;
    case 6: {
      const base::VelocityCommand command{static_cast<std::int16_t>(a) % 3000 * 1e-3,
                                          static_cast<std::int16_t>(b) % 10000 * 1e-3, c};
      frame = base::EncodeVelocityCommand(command, options.base.node_id, nullptr);
      break;
    }
    default:
      frame = canopen::EncodeHeartbeat({127, c % 2 == 0 ? canopen::NmtState::kOperational : canopen::NmtState::kBootUp},
                                       nullptr);
      break;
  }
  FuzzCheck(frame.has_value(), "the host frames of this target encode");
  bench.sim().Receive(*frame, bench.now());
}

void RunClosedLoop(FuzzReader& in, Bench& bench, const MotorSimOptions& options) {
  const int steps = in.Byte() % 64;
  for (int i = 0; i < steps && bench.now() < kMaxTimeS; ++i) {
    bench.Follow(options.step_period_s);
    bench.Step(options.step_period_s, true);
  }
}

void ReceiveErrorFrame(FuzzReader& in, Bench& bench) {
  const std::uint32_t class_bits = in.U32();
  const std::uint8_t controller = in.Byte();
  const int tx = in.Byte();
  const int rx = in.Byte();
  bench.sim().Receive(can::MakeCanErrorFrame(class_bits, controller, tx, rx), bench.now());
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  MotorSimOptions options = ConfigOptions();
  options.faults.seed = in.Byte();
  Bench bench(options);
  for (int op = 0; op < kMaxOps && !in.empty() && bench.now() < kMaxTimeS; ++op) {
    switch (in.Byte() % 6) {
      case 0:
        ReceiveFrameRecord(in, bench, options);
        break;
      case 1:
        StepWithPlant(in, bench);
        break;
      case 2:
        InjectFault(in, bench);
        break;
      case 3:
        ReceiveHostFrame(in, bench, options);
        break;
      case 4:
        RunClosedLoop(in, bench, options);
        break;
      default:
        ReceiveErrorFrame(in, bench);
        break;
    }
  }
  bench.Step(options.step_period_s, false);
  return 0;
}
