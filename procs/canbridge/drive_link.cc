#include "procs/canbridge/drive_link.h"

#include <cstdio>
#include <stdexcept>
#include <variant>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_host.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"

namespace topay::canbridge {

using canopen::CanopenFunction;
using canopen::NmtCommand;
using canopen::NmtState;
using cia402::DriveState;

namespace {
constexpr canopen::ObjectAddress kErrorCodeAddress{0x603F, 0x00};  // CiA 402 error code
}  // namespace

const char* ToString(DrivePhase phase) {
  switch (phase) {
    case DrivePhase::kIdle: return "idle";
    case DrivePhase::kWaitingBootUp: return "waiting for boot-up";
    case DrivePhase::kConfiguring: return "configuring";
    case DrivePhase::kOperational: return "operational";
    case DrivePhase::kFailed: return "start-up failed";
  }
  return "?";
}

DriveLink::DriveLink(int node_id, std::string joint_name, const DriveLinkOptions& options,
                     std::vector<cia402::SdoWrite> writes)
    : node_id_(node_id),
      joint_name_(std::move(joint_name)),
      options_(options),
      writes_(std::move(writes)),
      heartbeat_(options.heartbeat_timeout_s) {
  if (!canopen::CheckNodeId(node_id).empty()) throw std::invalid_argument(canopen::CheckNodeId(node_id));
}

std::string DriveLink::Label() const { return joint_name_ + " (node " + std::to_string(node_id_) + ")"; }

bool DriveLink::faulted() const {
  return state_ == DriveState::kFault || state_ == DriveState::kFaultReactionActive || emcy_active_;
}

FrameResult DriveLink::Handle(const can::CanFrame& frame, double now_s, std::string* error) {
  const std::optional<canopen::CobIdClass> cob = canopen::ClassifyCobId(frame.id, nullptr);
  if (!cob) return FrameResult::kNotMine;
  return Handle(frame, *cob, now_s, error);
}

FrameResult DriveLink::Handle(const can::CanFrame& frame, const canopen::CobIdClass& cob, double now_s,
                              std::string* error) {
  if (frame.error || frame.extended || cob.node_id != node_id_) return FrameResult::kNotMine;
  switch (cob.function) {
    case CanopenFunction::kTpdo1: {
      const auto pdo = cia402::DecodeTpdo1(frame, options_.units, error);
      if (!pdo) return FrameResult::kMalformed;
      statusword_ = pdo->statusword;
      state_ = cia402::DecodeStatusword(pdo->statusword, nullptr);
      position_rad_ = pdo->position_rad;
      last_tpdo1_s_ = now_s;
      new_feedback_ = true;
      if (state_ != DriveState::kFault && state_ != DriveState::kFaultReactionActive) fault_reset_armed_ = false;
      return FrameResult::kDecoded;
    }
    case CanopenFunction::kTpdo2: {
      const auto pdo = cia402::DecodeTpdo2(frame, options_.units, error);
      if (!pdo) return FrameResult::kMalformed;
      velocity_rad_per_s_ = pdo->velocity_rad_per_s;
      new_feedback_ = true;
      return FrameResult::kDecoded;
    }
    case CanopenFunction::kEmcy: {
      const auto emcy = canopen::DecodeEmcy(frame, error);
      if (!emcy) return FrameResult::kMalformed;
      last_emcy_code_ = emcy->error_code;
      emcy_active_ = emcy->error_code != canopen::emcy_code::kErrorResetOrNoError;
      return FrameResult::kDecoded;
    }
    case CanopenFunction::kHeartbeat: {
      const auto beat = canopen::DecodeHeartbeat(frame, error);
      if (!beat) return FrameResult::kMalformed;
      heartbeat_.OnHeartbeat(beat->state, now_s);
      last_heartbeat_s_ = now_s;
      if (beat->state == NmtState::kBootUp) {
        if (phase_ == DrivePhase::kWaitingBootUp) boot_seen_ = true;
        if (phase_ == DrivePhase::kOperational) rebooted_ = true;
      }
      return FrameResult::kDecoded;
    }
    case CanopenFunction::kSdoTx:
      return HandleSdoReply(frame, now_s, error);
    case CanopenFunction::kRpdo1:
    case CanopenFunction::kRpdo2:
    case CanopenFunction::kSdoRx:
      return FrameResult::kHostFrame;
    default:
      return FrameResult::kNotMine;
  }
}

FrameResult DriveLink::HandleSdoReply(const can::CanFrame& frame, double now_s, std::string* error) {
  const auto reply = canopen::DecodeSdoServerReply(frame, error);
  if (!reply) return FrameResult::kMalformed;
  HandleErrorCodeReply(*reply);
  if (phase_ != DrivePhase::kConfiguring || !write_pending_ || next_write_ >= writes_.size()) {
    return FrameResult::kDecoded;  // a late or unexpected reply: nothing waits for it
  }
  const cia402::SdoWrite& write = writes_[next_write_];
  if (const auto* abort = std::get_if<canopen::SdoAbort>(&*reply)) {
    if (abort->address == write.address) {
      char text[160];
      std::snprintf(text, sizeof(text), "SDO write 0x%04X:%02X (%.*s) aborted: %s", write.address.index,
                    write.address.subindex, static_cast<int>(write.what.size()), write.what.data(),
                    canopen::SdoAbortCodeName(abort->abort_code).c_str());
      Fail(text, now_s);
    }
    return FrameResult::kDecoded;
  }
  if (const auto* done = std::get_if<canopen::SdoDownloadResponse>(&*reply)) {
    if (done->address == write.address) {
      write_pending_ = false;
      ++next_write_;
      attempts_ = 0;
    }
  }
  return FrameResult::kDecoded;
}

void DriveLink::Fail(std::string why, double now_s) {
  phase_ = DrivePhase::kFailed;
  failure_ = Label() + ": " + std::move(why);
  phase_since_s_ = now_s;
  write_pending_ = false;
}

void DriveLink::BeginStartup(double now_s) {
  phase_ = DrivePhase::kIdle;
  phase_since_s_ = now_s;
  failure_.clear();
  rebooted_ = false;
}

void DriveLink::SendWrite(double now_s, std::vector<can::CanFrame>* out) {
  const cia402::SdoWrite& write = writes_[next_write_];
  if (auto frame = canopen::EncodeSdoDownloadRequest(cia402::ToDownloadRequest(node_id_, write), nullptr)) {
    out->push_back(*frame);
  }
  write_pending_ = true;
  write_sent_s_ = now_s;
  ++attempts_;
}

void DriveLink::RequestErrorCode() {
  if (error_code_read_.wanted || error_code_ || error_code_read_.gave_up) return;  // gave up: until a reset
  error_code_read_ = ErrorCodeRead{};
  error_code_read_.wanted = true;
}

std::optional<std::uint16_t> DriveLink::FaultCode() const {
  if (emcy_active_) return last_emcy_code_;
  return error_code_;
}

void DriveLink::ErrorCodeStep(double now_s, std::vector<can::CanFrame>* out) {
  ErrorCodeRead& r = error_code_read_;
  if (!r.wanted || (r.requests > 0 && now_s - r.sent_s < options_.sdo_timeout_s)) return;
  if (r.requests >= options_.sdo_attempts) {
    r.wanted = false;
    r.gave_up = true;
    return;
  }
  if (auto frame = canopen::EncodeSdoUploadRequest({node_id_, kErrorCodeAddress}, nullptr)) out->push_back(*frame);
  r.sent_s = now_s;
  ++r.requests;
}

void DriveLink::HandleErrorCodeReply(const canopen::SdoServerReply& reply) {
  if (!error_code_read_.wanted) return;
  if (const auto* up = std::get_if<canopen::SdoUploadResponse>(&reply); up && up->address == kErrorCodeAddress) {
    error_code_ = static_cast<std::uint16_t>(up->value & 0xFFFFu);
    error_code_read_.wanted = false;
  } else if (const auto* abort = std::get_if<canopen::SdoAbort>(&reply); abort && abort->address == kErrorCodeAddress) {
    error_code_read_.wanted = false;
    error_code_read_.gave_up = true;
  }
}

void DriveLink::StartupStep(double now_s, std::vector<can::CanFrame>* out) {
  switch (phase_) {
    case DrivePhase::kOperational:
      ErrorCodeStep(now_s, out);
      return;
    case DrivePhase::kFailed:
      if (now_s - phase_since_s_ < options_.retry_after_s) return;
      [[fallthrough]];
    case DrivePhase::kIdle:
      if (auto nmt = canopen::EncodeNmt({NmtCommand::kResetCommunication, node_id_}, nullptr)) out->push_back(*nmt);
      phase_ = DrivePhase::kWaitingBootUp;
      phase_since_s_ = now_s;
      boot_seen_ = false;
      return;
    case DrivePhase::kWaitingBootUp:
      if (!boot_seen_ && now_s - phase_since_s_ < options_.boot_timeout_s) return;
      // Pre-operational after a boot-up; say so explicitly when none came.
      if (auto nmt = canopen::EncodeNmt({NmtCommand::kEnterPreOperational, node_id_}, nullptr)) out->push_back(*nmt);
      phase_ = DrivePhase::kConfiguring;
      phase_since_s_ = now_s;
      next_write_ = 0;
      attempts_ = 0;
      write_pending_ = false;
      [[fallthrough]];
    case DrivePhase::kConfiguring:
      if (write_pending_ && now_s - write_sent_s_ < options_.sdo_timeout_s) return;
      if (write_pending_ && attempts_ >= options_.sdo_attempts) {
        const cia402::SdoWrite& write = writes_[next_write_];
        char text[160];
        std::snprintf(text, sizeof(text), "SDO write 0x%04X:%02X (%.*s) not confirmed after %d requests",
                      write.address.index, write.address.subindex, static_cast<int>(write.what.size()),
                      write.what.data(), attempts_);
        Fail(text, now_s);
        return;
      }
      if (next_write_ < writes_.size()) {
        SendWrite(now_s, out);
        return;
      }
      if (auto nmt = canopen::EncodeNmt({NmtCommand::kStartRemoteNode, node_id_}, nullptr)) out->push_back(*nmt);
      phase_ = DrivePhase::kOperational;
      operational_since_s_ = now_s;
      last_tpdo1_s_.reset();
      previous_controlword_ = 0;
      return;
  }
}

can::CanFrame DriveLink::Rpdo(DriveIntent intent, double qdot_radps) {
  std::uint16_t controlword = 0;
  const bool fault_state = state_ == DriveState::kFault || state_ == DriveState::kFaultReactionActive;
  if (!state_) {
    controlword = 0;  // no statusword yet: disable voltage, the safe word
  } else if (intent == DriveIntent::kQuickStop) {
    // Quick stop where the drive moves (Operation enabled) or is stopping (hold it); elsewhere
    // disable voltage, which every other state accepts (or holds) without motion.
    const bool moving = *state_ == DriveState::kOperationEnabled || *state_ == DriveState::kQuickStopActive;
    controlword = moving && !fault_state ? cia402::ControlwordOf(cia402::Command::kQuickStop) : 0x0000;
  } else if (fault_state && !fault_reset_armed_) {
    controlword = 0x0000;  // a fault waits for DRIVE_COMMAND FAULT_RESET
  } else {
    controlword = cia402::NextStepTowardsOperationEnabled(*state_, previous_controlword_).controlword;
  }
  previous_controlword_ = controlword;
  const bool moving = intent == DriveIntent::kEnable && enabled();
  cia402::Rpdo1 pdo{node_id_, controlword, moving ? qdot_radps : 0.0};
  std::optional<can::CanFrame> frame = cia402::EncodeRpdo1(pdo, options_.units, nullptr);
  if (!frame) {
    pdo.target_velocity_rad_per_s = 0.0;
    frame = cia402::EncodeRpdo1(pdo, options_.units, nullptr);
  }
  return *frame;
}

std::string DriveLink::LostReason(double now_s) const {
  if (phase_ != DrivePhase::kOperational) return "";
  const double since_beat = last_heartbeat_s_ && *last_heartbeat_s_ >= operational_since_s_
                                ? now_s - *last_heartbeat_s_
                                : now_s - operational_since_s_;
  char text[160];
  if (since_beat > options_.heartbeat_timeout_s) {
    std::snprintf(text, sizeof(text), "%s: no heartbeat for %.0f ms", Label().c_str(), since_beat * 1e3);
    return text;
  }
  if (options_.pdo_timeout_s > 0.0) {
    const double since_pdo = last_tpdo1_s_ ? now_s - *last_tpdo1_s_ : now_s - operational_since_s_;
    if (since_pdo > options_.pdo_timeout_s) {
      std::snprintf(text, sizeof(text), "%s: no TPDO1 for %.0f ms", Label().c_str(), since_pdo * 1e3);
      return text;
    }
  }
  return "";
}

bool DriveLink::TakeNewFeedback() {
  const bool fresh = new_feedback_;
  new_feedback_ = false;
  return fresh;
}

}  // namespace topay::canbridge
