#include "procs/canbridge/base_link.h"

#include <stdexcept>

#include "drivers/base/fault_frame.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"

namespace topay::canbridge {

using base::BaseFrameKind;
using base::BaseMode;
using base::ModeRequest;

BaseLink::BaseLink(const BaseLinkOptions& options) : options_(options) {
  if (!base::CheckNodeId(options.node_id).empty()) throw std::invalid_argument(base::CheckNodeId(options.node_id));
}

FrameResult BaseLink::Handle(const can::CanFrame& frame, double now_s, std::string* error) {
  const std::optional<BaseFrameKind> kind = base::IdentifyFrame(frame, options_.node_id, nullptr);
  if (!kind) return FrameResult::kNotMine;
  switch (*kind) {
    case BaseFrameKind::kModeRequest:
    case BaseFrameKind::kVelocityCommand:
      return FrameResult::kHostFrame;
    case BaseFrameKind::kStatus: {
      const auto status = base::DecodeStatus(frame, options_.node_id, error);
      if (!status) return FrameResult::kMalformed;
      mode_ = status->mode;
      fault_bits_ = status->fault_bits;
      battery_v_ = status->battery_voltage_v;
      last_status_s_ = now_s;
      if (mode_ != BaseMode::kFault) fault_reset_armed_ = false;
      return FrameResult::kDecoded;
    }
    case BaseFrameKind::kWheelSpeeds: {
      const auto speeds = base::DecodeWheelSpeeds(frame, options_.node_id, error);
      if (!speeds) return FrameResult::kMalformed;
      new_velocity_ = base::WheelSpeedsToUnicycle({speeds->left_rad_per_s, speeds->right_rad_per_s},
                                                 options_.geometry);
      return FrameResult::kDecoded;
    }
    case BaseFrameKind::kOdometry: {
      const auto odometry = base::DecodeOdometry(frame, options_.node_id, last_odometry_counter_, error);
      if (!odometry) return FrameResult::kMalformed;
      last_odometry_counter_ = odometry->counter;
      return FrameResult::kDecoded;
    }
    case BaseFrameKind::kFault: {
      const auto fault = base::DecodeFault(frame, options_.node_id, error);
      if (!fault) return FrameResult::kMalformed;
      mode_ = fault->mode;
      fault_bits_ = fault->fault_bits;
      return FrameResult::kDecoded;
    }
  }
  return FrameResult::kNotMine;
}

std::optional<ModeRequest> BaseLink::NextRequest() const {
  if (mode_ == target_) return std::nullopt;
  if (mode_ == BaseMode::kFault) {
    if (fault_reset_armed_) return ModeRequest::kFaultReset;
    return std::nullopt;  // only a fault reset leaves it; nothing else would be accepted
  }
  if (target_ == BaseMode::kQuickStop) return ModeRequest::kQuickStop;
  if (target_ == BaseMode::kCanCommand) {
    // quick stop is left through standby only (docs/base_protocol.md)
    return mode_ == BaseMode::kQuickStop ? ModeRequest::kStandby : ModeRequest::kCanCommand;
  }
  return ModeRequest::kStandby;
}

can::CanFrame BaseLink::VelocityFrame(double v_mps, double omega_radps) {
  base::VelocityCommand command{v_mps, omega_radps, counter_++};
  std::string error;
  std::optional<can::CanFrame> frame = base::EncodeVelocityCommand(command, options_.node_id, &error);
  if (!frame) {  // never with clamped commands; zero is always encodable
    command.v_m_per_s = 0.0;
    command.omega_rad_per_s = 0.0;
    frame = base::EncodeVelocityCommand(command, options_.node_id, &error);
  }
  ++velocity_frames_sent_;
  return *frame;
}

void BaseLink::CycleFrames(double now_s, double v_mps, double omega_radps, std::vector<can::CanFrame>* out) {
  std::vector<can::CanFrame>& frames = *out;
  const std::optional<ModeRequest> request = NextRequest();
  if (request && (request != last_request_ || now_s - last_request_s_ >= options_.mode_request_repeat_s - 1e-9)) {
    if (auto frame = base::EncodeModeRequest(*request, options_.node_id, nullptr)) frames.push_back(*frame);
    last_request_ = request;
    last_request_s_ = now_s;
  }
  if (!request) last_request_.reset();
  frames.push_back(VelocityFrame(v_mps, omega_radps));
}

std::optional<base::UnicycleVelocity> BaseLink::TakeNewVelocity() {
  std::optional<base::UnicycleVelocity> velocity = new_velocity_;
  new_velocity_.reset();
  return velocity;
}

}  // namespace topay::canbridge
