#include "sim/motors/drive_node.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/sync.h"
#include "sim/motors/node_output.h"

namespace topay::sim::motors {
namespace {

using canopen::CanopenFunction;
using canopen::NmtState;
using cia402::DriveState;


std::uint32_t ToRaw(double value, double unit) {
  return static_cast<std::uint32_t>(static_cast<std::int32_t>(std::llround(value / unit)));
}

}  // namespace

std::string CheckDriveNodeOptions(const DriveNodeOptions& o) {
  if (std::string bad = canopen::CheckNodeId(o.node_id); !bad.empty()) return "node_id: " + bad;
  if (o.producer_heartbeat_ms < 0 || o.producer_heartbeat_ms > 0xFFFF) return "producer_heartbeat_ms must be in 0..65535";
  if (!PositiveFinite(o.max_velocity_radps) || o.max_velocity_radps > o.units.max_target_velocity_rad_per_s) {
    return "max_velocity_radps must be > 0 and at most the PDO bound " +
           std::to_string(o.units.max_target_velocity_rad_per_s) + " rad/s";
  }
  if (!PositiveFinite(o.quick_stop_decel_radps2)) return "quick_stop_decel_radps2 must be finite and > 0";
  if (!PositiveFinite(o.standstill_radps)) return "standstill_radps must be finite and > 0";
  if (!PositiveFinite(o.fault_reaction_timeout_s)) return "fault_reaction_timeout_s must be finite and > 0";
  return "";
}

DriveNode::DriveNode(const DriveNodeOptions& options, double start_time_s)
    : options_(options),
      dictionary_(options.node_id, options.producer_heartbeat_ms),
      model_(options.model),
      producer_(0.0),
      last_step_s_(start_time_s) {
  if (std::string bad = CheckDriveNodeOptions(options); !bad.empty()) {
    throw std::invalid_argument("DriveNodeOptions: " + bad);
  }
  PowerOn(true);
}

void DriveNode::PowerOn(bool reset_application) {
  // Reset communication keeps the drive's own objects: a fault still present is still named by
  // 0x603F (a host that restarted reads it to decide whether it may reset the fault itself).
  if (reset_application) {
    dictionary_ = DriveObjectDictionary(options_.node_id, options_.producer_heartbeat_ms);
    model_ = cia402::DriveModel(options_.model);
    model_.CompleteInitialization();  // transition 1: the simulated drive initialises at once
  } else {
    dictionary_.ResetCommunicationArea();
  }
  nmt_ = NmtState::kBootUp;
  boot_up_due_ = true;
  producer_ms_ = consumer_ms_ = -1;
  host_lost_ = false;
  pending_rpdo_.reset();
  last_rpdo_s_.reset();
  target_radps_ = 0.0;
  UpdateStatusObjects();
}

bool DriveNode::OnFrame(const can::CanFrame& frame, double time_s, std::vector<can::CanFrame>* out) {
  if (frame.error || frame.extended || frame.remote) return false;
  const std::optional<canopen::CobIdClass> cob = canopen::ClassifyCobId(frame.id, nullptr);
  if (!cob) return false;
  if (nmt_ == NmtState::kBootUp && cob->function != CanopenFunction::kNmt) return false;
  switch (cob->function) {
    case CanopenFunction::kNmt:
      OnNmt(frame);
      return true;
    case CanopenFunction::kSync:
      if (nmt_ == NmtState::kOperational) OnSync(out);
      return nmt_ == NmtState::kOperational;
    case CanopenFunction::kHeartbeat:
      if (cob->node_id != dictionary_.consumer_node_id() || cob->node_id == options_.node_id) return false;
      OnHostHeartbeat(frame, time_s);
      return true;
    default:
      break;
  }
  if (cob->node_id != options_.node_id) return false;
  if (cob->function == CanopenFunction::kRpdo1) {
    if (nmt_ == NmtState::kOperational && dictionary_.PdoValid(Pdo::kRpdo1)) OnRpdo1(frame, time_s, out);
    return true;
  }
  if (cob->function == CanopenFunction::kSdoRx) {
    if (nmt_ != NmtState::kStopped) OnSdo(frame, out);
    return true;
  }
  return false;
}

void DriveNode::OnNmt(const can::CanFrame& frame) {
  std::string error;
  const std::optional<canopen::NmtMessage> nmt = canopen::DecodeNmt(frame, &error);
  if (!nmt) {
    ++counts_.malformed;
    last_error_ = error;
    return;
  }
  if (nmt->node_id != canopen::kNmtAllNodes && nmt->node_id != options_.node_id) return;
  ++counts_.nmt_commands;
  switch (nmt->command) {
    case canopen::NmtCommand::kStartRemoteNode:
      if (nmt_ != NmtState::kBootUp) nmt_ = NmtState::kOperational;
      return;
    case canopen::NmtCommand::kStopRemoteNode:
      if (nmt_ != NmtState::kBootUp) nmt_ = NmtState::kStopped;
      return;
    case canopen::NmtCommand::kEnterPreOperational:
      if (nmt_ != NmtState::kBootUp) nmt_ = NmtState::kPreOperational;
      return;
    case canopen::NmtCommand::kResetNode:
      PowerOn(true);
      return;
    case canopen::NmtCommand::kResetCommunication:
      PowerOn(false);
      return;
  }
}

// A synchronous TPDO of transmission type n (1..240, CiA 301 §7.5.2.37) goes out on every n-th
// SYNC the drive acted on; the other types are not synchronous: never on SYNC.
bool DriveNode::DueOnThisSync(std::uint16_t tpdo_comm_index) const {
  const std::uint32_t type = dictionary_.Get({tpdo_comm_index, 2});
  return type >= 1 && type <= 240 && counts_.syncs % type == 0;
}

void DriveNode::OnSync(std::vector<can::CanFrame>* out) {
  ++counts_.syncs;
  if (pending_rpdo_) {
    ApplyControlword(pending_rpdo_->controlword, out);
    target_radps_ = std::clamp(pending_rpdo_->target_velocity_rad_per_s, -options_.max_velocity_radps,
                               options_.max_velocity_radps);
    dictionary_.Set({0x60FF, 0}, ToRaw(pending_rpdo_->target_velocity_rad_per_s,
                                       options_.units.rad_per_s_per_velocity_unit));
    pending_rpdo_.reset();
  }
  if (!feedback_) return;
  const cia402::JointUnits& u = options_.units;
  const double position = std::clamp(feedback_->position_rad, -u.max_position_rad, u.max_position_rad);
  const double velocity = std::clamp(feedback_->velocity_radps, -u.max_actual_velocity_rad_per_s,
                                     u.max_actual_velocity_rad_per_s);
  std::string error;
  if (dictionary_.PdoValid(Pdo::kTpdo1) && DueOnThisSync(0x1800)) {
    const cia402::Tpdo1 tpdo1{options_.node_id, model_.statusword(), position};
    Emit(cia402::EncodeTpdo1(tpdo1, u, &error), error, out);
  }
  if (dictionary_.PdoValid(Pdo::kTpdo2) && DueOnThisSync(0x1801)) {
    Emit(cia402::EncodeTpdo2(cia402::Tpdo2{options_.node_id, velocity}, u, &error), error, out);
  }
}

void DriveNode::OnRpdo1(const can::CanFrame& frame, double time_s, std::vector<can::CanFrame>* out) {
  std::string error;
  const std::optional<cia402::Rpdo1> rpdo = cia402::DecodeRpdo1(frame, options_.units, &error);
  if (!rpdo) {
    ++counts_.malformed;
    last_error_ = error;
    if (frame.dlc != 6) SendEmcy(canopen::emcy_code::kPdoLengthError, canopen::error_register::kCommunication, out);
    return;
  }
  ++counts_.rpdos;
  pending_rpdo_ = *rpdo;
  last_rpdo_s_ = time_s;
}

// RPDO deadline monitoring (CiA 301 §7.5.2.35, the RPDO's event timer): it starts with the first
// RPDO1 received in NMT operational; no RPDO1 for the event time -> EMCY 0x8250 and, as on a
// lost heartbeat, the fault reaction (the abort connection option "fault"), once per silence.
// Leaving operational ends the monitoring until the next RPDO1.
void DriveNode::CheckRpdoDeadline(double time_s, std::vector<can::CanFrame>* out) {
  if (nmt_ != NmtState::kOperational) last_rpdo_s_.reset();
  const int deadline_ms = dictionary_.rpdo1_deadline_ms();
  if (!last_rpdo_s_ || deadline_ms <= 0 || time_s - *last_rpdo_s_ < deadline_ms * 1e-3) return;
  last_rpdo_s_.reset();
  ++counts_.rpdo_timeouts;
  EnterFault(canopen::emcy_code::kRpdoTimeout, canopen::error_register::kCommunication, time_s, out);
}

void DriveNode::OnSdo(const can::CanFrame& frame, std::vector<can::CanFrame>* out) {
  std::string error;
  const std::optional<canopen::SdoClientRequest> request = canopen::DecodeSdoClientRequest(frame, &error);
  canopen::ObjectAddress address{static_cast<std::uint16_t>(frame.data[1] | (frame.data[2] << 8)), frame.data[3]};
  std::uint32_t abort_code = 0;
  if (!request) {
    ++counts_.malformed;
    last_error_ = error;
    abort_code = canopen::sdo_abort::kInvalidCommandSpecifier;
  } else if (const auto* write = std::get_if<canopen::SdoDownloadRequest>(&*request)) {
    address = write->address;
    abort_code = dictionary_.Write(write->address, write->size_bytes, write->value);
    if (abort_code == 0) {
      ++counts_.sdo_writes;
      Emit(canopen::EncodeSdoDownloadResponse({options_.node_id, address}, &error), error, out);
      if (address == cia402::object::kControlword) ApplyControlword(static_cast<std::uint16_t>(write->value), out);
      return;
    }
  } else if (const auto* read = std::get_if<canopen::SdoUploadRequest>(&*request)) {
    address = read->address;
    UpdateStatusObjects();
    ObjectEntry entry;
    abort_code = dictionary_.Read(read->address, &entry);
    if (abort_code == 0) {
      ++counts_.sdo_reads;
      Emit(canopen::EncodeSdoUploadResponse({options_.node_id, address, entry.size_bytes, entry.value}, &error),
           error, out);
      return;
    }
  } else {
    return;  // the client aborted its transfer: nothing to answer
  }
  ++counts_.sdo_aborts;
  const canopen::SdoAbort reply{options_.node_id, address, abort_code};
  Emit(canopen::EncodeSdoAbort(reply, canopen::SdoChannel::kServerToClient, &error), error, out);
}

void DriveNode::OnHostHeartbeat(const can::CanFrame& frame, double time_s) {
  std::string error;
  const std::optional<canopen::Heartbeat> heartbeat = canopen::DecodeHeartbeat(frame, &error);
  if (!heartbeat) {
    ++counts_.malformed;
    last_error_ = error;
    return;
  }
  consumer_.OnHeartbeat(heartbeat->state, time_s);
  host_lost_ = false;
}

void DriveNode::ApplyControlword(std::uint16_t controlword, std::vector<can::CanFrame>* out) {
  dictionary_.Set(cia402::object::kControlword, controlword);
  const cia402::TransitionResult result = model_.ApplyControlword(controlword);
  if (!result.accepted) {
    ++counts_.refused_controlwords;
    last_error_ = result.reason;
  } else if (result.transition == 15) {  // fault reset: the errors are cleared
    dictionary_.Set({0x1001, 0}, 0);
    dictionary_.Set({0x603F, 0}, 0);
    SendEmcy(canopen::emcy_code::kErrorResetOrNoError, 0, out);
  }
  UpdateStatusObjects();
}

void DriveNode::InjectFault(std::uint16_t emcy_code, double time_s, std::vector<can::CanFrame>* out) {
  EnterFault(emcy_code != 0 ? emcy_code : options_.fault_emcy_code, canopen::error_register::kGeneric, time_s, out);
}

void DriveNode::EnterFault(std::uint16_t emcy_code, std::uint8_t error_register, double time_s,
                           std::vector<can::CanFrame>* out) {
  fault_reaction_since_s_ = time_s;
  ++counts_.faults;
  const auto reg = static_cast<std::uint8_t>(dictionary_.Get({0x1001, 0}) | error_register | canopen::error_register::kGeneric);
  dictionary_.Set({0x1001, 0}, reg);
  dictionary_.Set({0x603F, 0}, emcy_code);
  model_.OnFault();  // transition 13 (none when already in a fault state)
  SendEmcy(emcy_code, reg, out);
  UpdateStatusObjects();
}

void DriveNode::SendEmcy(std::uint16_t code, std::uint8_t error_register, std::vector<can::CanFrame>* out) {
  if (nmt_ == NmtState::kStopped || nmt_ == NmtState::kBootUp) return;  // EMCY: pre-operational and operational only
  std::string error;
  canopen::Emcy emcy;
  emcy.node_id = options_.node_id;
  emcy.error_code = code;
  emcy.error_register = error_register;
  Emit(canopen::EncodeEmcy(emcy, &error), error, out);
  ++counts_.emcy;
}

void DriveNode::Step(double time_s, bool heartbeat_suppressed, std::vector<can::CanFrame>* out) {
  const double dt_s = std::max(0.0, time_s - last_step_s_);
  last_step_s_ = std::max(last_step_s_, time_s);
  std::string error;
  if (boot_up_due_) {
    boot_up_due_ = false;
    Emit(canopen::EncodeHeartbeat({options_.node_id, NmtState::kBootUp}, &error), error, out);
    ++counts_.heartbeats;
    nmt_ = NmtState::kPreOperational;
  }
  if (dictionary_.producer_heartbeat_ms() != producer_ms_) {
    producer_ms_ = dictionary_.producer_heartbeat_ms();
    producer_ = canopen::HeartbeatProducer(producer_ms_ * 1e-3);
    producer_.OnSent(time_s);  // the next one a period from now
  }
  if (!heartbeat_suppressed && producer_.IsDue(time_s)) {
    Emit(canopen::EncodeHeartbeat({options_.node_id, nmt_}, &error), error, out);
    producer_.OnSent(time_s);
    ++counts_.heartbeats;
  }
  if (dictionary_.consumer_heartbeat_ms() != consumer_ms_) {
    consumer_ms_ = dictionary_.consumer_heartbeat_ms();
    consumer_ = canopen::HeartbeatConsumer(consumer_ms_ * 1e-3);
  }
  if (!host_lost_ && consumer_.IsLost(time_s)) {  // CiA 301 heartbeat event
    host_lost_ = true;
    ++counts_.host_heartbeat_lost;
    EnterFault(canopen::emcy_code::kHeartbeatError, canopen::error_register::kCommunication, time_s, out);
  }
  CheckRpdoDeadline(time_s, out);
  UpdateOutput(dt_s);
  const double speed = feedback_ ? std::abs(feedback_->velocity_radps) : 0.0;
  const bool stopped = output_radps_ == 0.0 && speed < options_.standstill_radps;
  if (model_.state() == DriveState::kFaultReactionActive &&
      (stopped || time_s - fault_reaction_since_s_ >= options_.fault_reaction_timeout_s)) {
    model_.CompleteFaultReaction();
  }
  if (model_.state() == DriveState::kQuickStopActive && stopped) model_.CompleteQuickStop();
  UpdateStatusObjects();
}

void DriveNode::UpdateOutput(double dt_s) {
  const DriveState state = model_.state();
  const bool halted = (dictionary_.Get(cia402::object::kControlword) & cia402::controlword::kHalt) != 0;
  if (state == DriveState::kOperationEnabled && nmt_ == NmtState::kOperational && !halted) {
    output_radps_ = target_radps_;
  } else if (state == DriveState::kOperationEnabled || state == DriveState::kQuickStopActive ||
             state == DriveState::kFaultReactionActive) {
    output_radps_ = RampTowardsZero(output_radps_, options_.quick_stop_decel_radps2 * dt_s);
  } else {
    output_radps_ = 0.0;  // not enabled: no torque, the joint's brake holds
  }
}

void DriveNode::UpdateStatusObjects() {
  dictionary_.Set(cia402::object::kStatusword, model_.statusword());
  if (!feedback_) return;
  dictionary_.Set(cia402::object::kPositionActual, ToRaw(feedback_->position_rad, options_.units.rad_per_position_unit));
  dictionary_.Set(cia402::object::kVelocityActual,
                  ToRaw(feedback_->velocity_radps, options_.units.rad_per_s_per_velocity_unit));
}

void DriveNode::Emit(const std::optional<can::CanFrame>& frame, const std::string& error,
                     std::vector<can::CanFrame>* out) {
  if (AppendFrame(frame, error, out, &last_error_)) ++counts_.frames_sent;
}

}  // namespace topay::sim::motors
