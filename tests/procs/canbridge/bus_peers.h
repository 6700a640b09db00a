#pragma once
// The devices on the bus for the bridge's tests, speaking drivers/base and drivers/arm exactly:
// the base controller (ModeStateMachine, status 20 Hz, wheel speeds and odometry 100 Hz, fault
// frames) and CiA 402 drives (NMT, boot-up, SDO server for the start-up writes, heartbeat
// producer from 0x1017, RPDO1 -> DriveModel, TPDO1/TPDO2 on SYNC, EMCY on a fault). Ideal
// motion: the wheels and joints follow their commands at once.

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <variant>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_drive_model.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/base/diff_drive_kinematics.h"
#include "drivers/base/fault_frame.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/mode_state_machine.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "drivers/can/can_bus.h"

namespace topay::canbridge::test {

class BasePeer {
 public:
  explicit BasePeer(int node_id) : node_(node_id) {}

  void Handle(const can::CanFrame& frame, double now_s, std::vector<can::CanFrame>* out) {
    const auto kind = base::IdentifyFrame(frame, node_, nullptr);
    if (!kind) return;
    machine_.Step(now_s);
    if (*kind == base::BaseFrameKind::kModeRequest) {
      const auto request = base::DecodeModeRequest(frame, node_, nullptr);
      if (!request) return;
      requests.push_back(*request);
      const base::BaseMode before = machine_.mode();
      machine_.Request(*request, now_s);
      if (machine_.mode() != before) SendStatus(out);
    } else if (*kind == base::BaseFrameKind::kVelocityCommand) {
      const auto command = base::DecodeVelocityCommand(frame, node_, last_counter_, nullptr);
      if (!command) {
        ++bad_commands;
        return;
      }
      last_counter_ = command->counter;
      commands.push_back(*command);
      if (machine_.AcceptVelocityCommand(now_s).empty()) {
        v_ = command->v_m_per_s;
        omega_ = command->omega_rad_per_s;
      }
    }
  }

  void Step(double now_s, std::vector<can::CanFrame>* out) {
    if (machine_.Step(now_s)) SendStatus(out);
    if (machine_.mode() != base::BaseMode::kCanCommand) v_ = omega_ = 0.0;
    if (silent) return;
    if (now_s - last_status_s_ >= 0.05 - 1e-9) {
      last_status_s_ = now_s;
      SendStatus(out);
    }
    if (now_s - last_speeds_s_ >= 0.01 - 1e-9) {
      last_speeds_s_ = now_s;
      const base::WheelSpeeds w = base::UnicycleToWheelSpeeds({v_, omega_}, geometry);
      if (auto f = base::EncodeWheelSpeeds({w.left_rad_per_s, w.right_rad_per_s, speeds_counter_++}, node_, nullptr)) {
        out->push_back(*f);
      }
      if (auto f = base::EncodeOdometry({0, 0, odometry_counter_++}, node_, nullptr)) out->push_back(*f);
    }
  }

  void RaiseFault(base::BaseFault fault, double now_s, std::vector<can::CanFrame>* out) {
    machine_.RaiseFault(fault, now_s);
    if (auto f = base::EncodeFault({fault, machine_.mode(), machine_.fault_bits(), fault_counter_++}, node_, nullptr)) {
      out->push_back(*f);
    }
    SendStatus(out);
  }

  base::BaseMode mode() const { return machine_.mode(); }
  double v() const { return v_; }

  bool silent = false;
  base::DriveGeometry geometry;
  std::vector<base::VelocityCommand> commands;
  std::vector<base::ModeRequest> requests;
  int bad_commands = 0;

 private:
  void SendStatus(std::vector<can::CanFrame>* out) {
    if (silent) return;
    base::BaseStatus status{machine_.mode(), machine_.error_code(), machine_.fault_bits(), 48.0, status_counter_++};
    if (auto f = base::EncodeStatus(status, node_, nullptr)) out->push_back(*f);
  }

  int node_;
  base::ModeStateMachine machine_;
  std::optional<std::uint8_t> last_counter_;
  double v_ = 0.0, omega_ = 0.0;
  double last_status_s_ = -1.0, last_speeds_s_ = -1.0;
  std::uint8_t status_counter_ = 0, speeds_counter_ = 0, odometry_counter_ = 0, fault_counter_ = 0;
};

class DrivePeer {
 public:
  explicit DrivePeer(int node_id) : node_(node_id) {}

  /// Power on: initialised, boot-up, pre-operational.
  void PowerOn(std::vector<can::CanFrame>* out) {
    model.CompleteInitialization();
    BootUp(out);
  }

  void Handle(const can::CanFrame& frame, double now_s, std::vector<can::CanFrame>* out) {
    if (frame.error || frame.extended || frame.remote) return;
    const auto cob = canopen::ClassifyCobId(frame.id, nullptr);
    if (!cob) return;
    switch (cob->function) {
      case canopen::CanopenFunction::kNmt: return HandleNmt(frame, out);
      case canopen::CanopenFunction::kSync: return HandleSync(out);
      case canopen::CanopenFunction::kSdoRx: if (cob->node_id == node_) HandleSdo(frame, out); return;
      case canopen::CanopenFunction::kRpdo1: if (cob->node_id == node_) HandleRpdo(frame); return;
      default: return;
    }
    (void)now_s;
  }

  void Step(double now_s, std::vector<can::CanFrame>* out) {
    if (silent || heartbeat_ms_ <= 0) return;
    if (now_s - last_heartbeat_s_ >= heartbeat_ms_ * 1e-3 - 1e-9) {
      last_heartbeat_s_ = now_s;
      if (auto f = canopen::EncodeHeartbeat({node_, nmt}, nullptr)) out->push_back(*f);
    }
  }

  /// A fault with `code` (kept in 0x603F); its EMCY goes to *out (nullptr: lost, e.g. sent
  /// while the bus was off).
  void Fault(std::uint16_t code, std::vector<can::CanFrame>* out) {
    model.OnFault();
    model.CompleteFaultReaction();
    velocity_ = 0.0;
    error_code = code;
    if (out == nullptr) return;
    canopen::Emcy emcy;
    emcy.node_id = node_;
    emcy.error_code = code;
    emcy.error_register = canopen::error_register::kGeneric;
    if (auto f = canopen::EncodeEmcy(emcy, nullptr)) out->push_back(*f);
  }

  std::uint32_t Object(std::uint16_t index, std::uint8_t sub) const {
    const auto it = od.find(Key(index, sub));
    return it == od.end() ? 0xFFFFFFFFu : it->second;
  }

  cia402::DriveModel model;
  canopen::NmtState nmt = canopen::NmtState::kBootUp;
  std::map<std::uint32_t, std::uint32_t> od;  ///< Objects written by SDO.
  std::vector<std::uint16_t> controlwords;
  bool silent = false;           ///< No heartbeat, no TPDOs, no SDO answers.
  std::optional<std::uint16_t> abort_index;  ///< Abort every write to this index.
  int resets = 0, starts = 0;
  int uploads = 0;               ///< SDO upload (read) requests answered
  std::uint16_t error_code = 0;  ///< 0x603F
  double target_velocity = 0.0;

 private:
  static std::uint32_t Key(std::uint16_t index, std::uint8_t sub) { return (std::uint32_t{index} << 8) | sub; }

  void BootUp(std::vector<can::CanFrame>* out) {
    nmt = canopen::NmtState::kPreOperational;
    heartbeat_ms_ = 0;
    if (auto f = canopen::EncodeHeartbeat({node_, canopen::NmtState::kBootUp}, nullptr)) out->push_back(*f);
  }

  void HandleNmt(const can::CanFrame& frame, std::vector<can::CanFrame>* out) {
    const auto msg = canopen::DecodeNmt(frame, nullptr);
    if (!msg || (msg->node_id != 0 && msg->node_id != node_)) return;
    switch (msg->command) {
      case canopen::NmtCommand::kStartRemoteNode: nmt = canopen::NmtState::kOperational; ++starts; return;
      case canopen::NmtCommand::kStopRemoteNode: nmt = canopen::NmtState::kStopped; return;
      case canopen::NmtCommand::kEnterPreOperational: nmt = canopen::NmtState::kPreOperational; return;
      case canopen::NmtCommand::kResetNode:
      case canopen::NmtCommand::kResetCommunication: ++resets; if (!silent) BootUp(out); return;
    }
  }

  void HandleSdo(const can::CanFrame& frame, std::vector<can::CanFrame>* out) {
    if (silent) return;
    const auto request = canopen::DecodeSdoClientRequest(frame, nullptr);
    if (!request) return;
    if (const auto* read = std::get_if<canopen::SdoUploadRequest>(&*request)) {
      ++uploads;
      const std::uint32_t value = read->address.index == 0x603F ? error_code : Object(read->address.index, read->address.subindex);
      if (auto f = canopen::EncodeSdoUploadResponse({node_, read->address, 4, value}, nullptr)) out->push_back(*f);
      return;
    }
    const auto* write = std::get_if<canopen::SdoDownloadRequest>(&*request);
    if (write == nullptr) return;
    if (abort_index && write->address.index == *abort_index) {
      if (auto f = canopen::EncodeSdoAbort({node_, write->address, canopen::sdo_abort::kValueRangeExceeded},
                                           canopen::SdoChannel::kServerToClient, nullptr)) {
        out->push_back(*f);
      }
      return;
    }
    od[Key(write->address.index, write->address.subindex)] = write->value;
    if (write->address.index == 0x1017) heartbeat_ms_ = static_cast<int>(write->value);
    if (auto f = canopen::EncodeSdoDownloadResponse({node_, write->address}, nullptr)) out->push_back(*f);
  }

  void HandleRpdo(const can::CanFrame& frame) {
    if (nmt != canopen::NmtState::kOperational) return;
    const auto pdo = cia402::DecodeRpdo1(frame, units_, nullptr);
    if (!pdo) return;
    controlwords.push_back(pdo->controlword);
    model.ApplyControlword(pdo->controlword);
    if (model.state() == cia402::DriveState::kQuickStopActive) model.CompleteQuickStop();
    target_velocity = pdo->target_velocity_rad_per_s;
  }

  void HandleSync(std::vector<can::CanFrame>* out) {
    if (nmt != canopen::NmtState::kOperational || silent) return;
    velocity_ = model.state() == cia402::DriveState::kOperationEnabled ? target_velocity : 0.0;
    position_ = std::remainder(position_ + velocity_ * 0.005, 2.0 * M_PI);  // a turning joint, within the PDO's bound
    if (auto f = cia402::EncodeTpdo1({node_, model.statusword(), position_}, units_, nullptr)) out->push_back(*f);
    if (auto f = cia402::EncodeTpdo2({node_, velocity_}, units_, nullptr)) out->push_back(*f);
  }

  int node_;
  cia402::JointUnits units_;
  int heartbeat_ms_ = 0;
  double last_heartbeat_s_ = -1.0;
  double position_ = 0.1;
  double velocity_ = 0.0;
};

/// The base and the drives on one bus: each Step reads every pending frame, answers, and sends
/// what is due.
class Peers {
 public:
  Peers(can::CanBus* bus, int base_node, const std::vector<int>& drive_nodes) : bus_(bus), base(base_node) {
    for (const int node : drive_nodes) drives.emplace_back(node);
  }
  void PowerOn() {
    std::vector<can::CanFrame> out;
    for (DrivePeer& drive : drives) drive.PowerOn(&out);
    Send(out);
  }
  void Step(double now_s) {
    std::vector<can::CanFrame>& out = step_frames_;
    out.clear();  // its capacity kept across steps
    can::ReceivedCanFrame received;
    while (bus_->Receive(0.0, &received).ok()) {
      received_frames.push_back(received.frame);
      base.Handle(received.frame, now_s, &out);
      for (DrivePeer& drive : drives) drive.Handle(received.frame, now_s, &out);
    }
    base.Step(now_s, &out);
    for (DrivePeer& drive : drives) drive.Step(now_s, &out);
    Send(out);
  }
  void Send(const std::vector<can::CanFrame>& frames) {
    for (const can::CanFrame& frame : frames) bus_->Send(frame);
  }

  can::CanBus* bus_;
  BasePeer base;
  std::vector<DrivePeer> drives;
  std::vector<can::CanFrame> received_frames;

 private:
  std::vector<can::CanFrame> step_frames_;
};

}  // namespace topay::canbridge::test
