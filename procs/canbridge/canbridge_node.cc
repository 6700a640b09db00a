#include "procs/canbridge/canbridge_node.h"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/sync.h"
#include "drivers/base/fault_codes.h"
#include "procs/runtime/process_loop.h"
#include "topay/heartbeat_t.hpp"
#include "topay_msgs/channels.h"

namespace topay::canbridge {
namespace {

using cia402::DriveState;

double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string Hex3(std::uint32_t id) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%03X", id);
  return text;
}

std::vector<DriveLink> MakeDrives(const CanbridgeOptions& options, const RobotModel& model) {
  if (static_cast<int>(options.drives.node_ids.size()) != model.num_joints()) {
    throw std::invalid_argument("drives.node_ids has " + std::to_string(options.drives.node_ids.size()) +
                                " entries, the robot has " + std::to_string(model.num_joints()) + " joints");
  }
  cia402::StartupOptions startup = options.drives.startup;
  startup.sync_period_ms = std::max(1, static_cast<int>(std::lround(options.cycle_period_s * 1e3)));
  std::vector<DriveLink> drives;
  for (int i = 0; i < model.num_joints(); ++i) {
    const int node = options.drives.node_ids[i];
    std::string error;
    auto writes = cia402::StartupSdoWrites(node, startup, &error);
    if (!writes) throw std::invalid_argument("start-up SDO writes of node " + std::to_string(node) + ": " + error);
    drives.emplace_back(node, model.joint_names[i], options.drives, std::move(*writes));
  }
  return drives;
}

}  // namespace

const char* ToString(BridgeState state) {
  switch (state) {
    case BridgeState::kStarting: return "starting";
    case BridgeState::kEnabling: return "enabling";
    case BridgeState::kRunning: return "running";
    case BridgeState::kStopped: return "stopped";
    case BridgeState::kFault: return "fault";
    case BridgeState::kRecovering: return "recovering";
    case BridgeState::kReplay: return "replay";
  }
  return "?";
}

CanbridgeNode::CanbridgeNode(const CanbridgeOptions& options, const RobotModel& model, can::CanBus* bus,
                             bool listen_only)
    : options_(options),
      bus_(bus),
      listen_only_(listen_only),
      base_(options.base),
      drives_(MakeDrives(options, model)),
      restart_(drives_.size(), false),
      limiter_(CommandLimitsOf(model), options.cycle_period_s),
      load_(options.bit_rate_bps) {
  options_.Check();
  if (bus_ == nullptr) throw std::invalid_argument("CanbridgeNode: no bus");
  latest_command_.qdot_radps.assign(drives_.size(), 0.0);
  if (listen_only_) {
    state_ = BridgeState::kReplay;
    stop_reason_ = "replaying a log: sending nothing";
  }
}

// ---------------------------------------------------------------------------------------------
// Inputs

void CanbridgeNode::OnCommand(const control_command_t& msg, double now_s) {
  const auto received = std::chrono::steady_clock::now();
  const std::string error = CheckControlCommand(msg, static_cast<int>(drives_.size()));
  if (!error.empty()) {
    ++commands_rejected_;
    if (error != last_command_error_) spdlog::warn("CONTROL_COMMAND rejected: {}", error);
    last_command_error_ = error;
    return;
  }
  latest_command_ = ToDeviceCommand(msg);
  last_command_s_ = now_s;
  ++commands_received_;
  if (state_ != BridgeState::kRunning || listen_only_) return;
  // Send on receipt; the cycle repeats the latest command until the next one.
  const DeviceCommand& command = limiter_.Step(latest_command_, now_s);
  SendFrame(base_.VelocityFrame(command.v_mps, command.omega_radps), now_s);
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    SendFrame(drives_[i].Rpdo(DriveIntent::kEnable, command.qdot_radps[i]), now_s);
  }
  latency_.Add(std::chrono::duration<double>(std::chrono::steady_clock::now() - received).count());
}

std::string CanbridgeNode::OnDriveCommand(const drive_command_t& msg, double now_s) {
  std::string refused;
  if (msg.command != drive_command_t::FAULT_RESET) {
    refused = "unknown command " + std::to_string(msg.command);
  } else if (listen_only_) {
    refused = "replaying: nothing is commanded";
  } else if (state_ != BridgeState::kFault) {
    refused = std::string("no fault to reset (state ") + ToString(state_) + ")";
  } else if (!CommandAllowsRecovery(now_s)) {
    refused = "the CONTROL_COMMAND is not zero: stop the robot's commands first";
  }
  if (!refused.empty()) {
    spdlog::warn("DRIVE_COMMAND from '{}' refused: {}", msg.source, refused);
    return refused;
  }
  spdlog::info("DRIVE_COMMAND from '{}': fault reset ({})", msg.source, stop_reason_);
  ResetFaults(now_s);
  return "";
}

void CanbridgeNode::ResetFaults(double now_s) {
  for (DriveLink& drive : drives_) drive.ArmFaultReset();
  base_.ArmFaultReset();
  fault_reset_s_ = now_s;
  BeginRecovery(now_s);
}

void CanbridgeNode::MaybeResetCommunicationFault(double now_s) {
  if (!options_.auto_reset_communication_faults || base_.faulted()) return;
  std::string codes;
  for (DriveLink& drive : drives_) {
    if (!drive.faulted()) continue;
    const std::optional<std::uint16_t> code = drive.FaultCode();
    if (!code) {
      drive.RequestErrorCode();  // no EMCY came (lost with the bus): ask the drive; none -> operator
      return;
    }
    if (!canopen::IsCommunicationError(*code)) return;  // a fault of the drive itself: the operator's
    char text[48];
    std::snprintf(text, sizeof(text), "%s%s 0x%04X", codes.empty() ? "" : ", ", drive.Label().c_str(), *code);
    codes += text;
  }
  if (codes.empty() || !CommandAllowsRecovery(now_s)) return;
  constexpr double kWindow_s = 60.0;
  while (!auto_resets_s_.empty() && now_s - auto_resets_s_.front() > kWindow_s) auto_resets_s_.pop_front();
  if (static_cast<int>(auto_resets_s_.size()) >= options_.max_auto_resets_per_minute) {
    if (!auto_reset_limit_logged_) {
      spdlog::error("canbridge: {} automatic fault resets within {:.0f} s: waiting for the operator's FAULT_RESET",
                    auto_resets_s_.size(), kWindow_s);
    }
    auto_reset_limit_logged_ = true;
    return;
  }
  auto_reset_limit_logged_ = false;
  auto_resets_s_.push_back(now_s);
  spdlog::warn("canbridge: automatic fault reset: communication errors only ({}): {}", codes, stop_reason_);
  ResetFaults(now_s);
}

// ---------------------------------------------------------------------------------------------
// The cycle

const CanbridgeOutputs& CanbridgeNode::Cycle(double now_s, std::int64_t now_utime) {
  if (!started_) {
    started_ = true;
    state_since_s_ = now_s;
  }
  ++cycles_;
  outputs_ = CanbridgeOutputs{};
  ReadFrames(now_s);
  if (!listen_only_) {
    ServiceBus(now_s);
    MarkRestarts(now_s);
    UpdateState(now_s);
    SendCycleFrames(now_s);
  }
  FillOutputs(now_s, now_utime);
  return outputs_;
}

void CanbridgeNode::ReadFrames(double now_s) {
  can::ReceivedCanFrame received;
  for (int i = 0; i < 10000; ++i) {
    const can::CanResult result = bus_->Receive(0.0, &received);
    if (result.code == can::CanResult::Code::kTimeout) return;
    if (!result.ok()) {
      if (result.code == can::CanResult::Code::kInterfaceDown || result.code == can::CanResult::Code::kClosed) {
        if (!bus_down_) spdlog::error("CAN bus {}: {}", bus_->url(), result.message);
        bus_down_ = true;
      }
      return;
    }
    load_.Add(received.frame, now_s);
    Dispatch(received.frame, now_s);
  }
}

void CanbridgeNode::Dispatch(const can::CanFrame& frame, double now_s) {
  if (frame.error) return;  // the bus status follows them
  std::string error;
  FrameResult result = base_.Handle(frame, now_s, &error);
  const DriveLink* owner = nullptr;  // the drive that took the frame; none: the base or nobody
  if (result == FrameResult::kNotMine && !frame.extended) {
    // Classified once; only the drive of its node id can take it (the others' Handle would say
    // kNotMine).
    if (const auto cob = canopen::ClassifyCobId(frame.id, nullptr); cob && cob->node_id != 0) {
      for (DriveLink& drive : drives_) {
        if (drive.node_id() != cob->node_id) continue;
        result = drive.Handle(frame, *cob, now_s, &error);
        owner = &drive;
        break;
      }
    }
  }
  if (result == FrameResult::kNotMine && !frame.extended && !frame.remote) {
    const std::uint32_t host_heartbeat = 0x700u + static_cast<std::uint32_t>(options_.drives.startup.host_node_id);
    if (frame.id == 0x000 || frame.id == 0x080 || frame.id == host_heartbeat) result = FrameResult::kHostFrame;
  }
  switch (result) {
    case FrameResult::kDecoded: return;
    case FrameResult::kHostFrame: counters_.CountHostFrame(); return;
    case FrameResult::kMalformed: {
      const std::string from = owner ? owner->Label() : "base (node " + std::to_string(base_.node_id()) + ")";
      counters_.CountMalformed(from + " id " + Hex3(frame.id), error);
      return;
    }
    case FrameResult::kNotMine:
      counters_.CountUnknown((frame.extended ? "extended id " : "id ") + Hex3(frame.id), can::ToString(frame));
      return;
  }
}

void CanbridgeNode::ServiceBus(double now_s) {
  if (!bus_down_ || now_s - last_reopen_s_ < options_.bus_reopen_period_s) return;
  last_reopen_s_ = now_s;
  const can::CanResult result = bus_->Reopen();
  if (result.ok()) {
    spdlog::info("CAN bus {} reopened", bus_->url());
    bus_down_ = false;
  }
}

void CanbridgeNode::MarkRestarts(double now_s) {
  if (state_ == BridgeState::kStarting) return;
  const bool bus_trouble = bus_down_ || bus_->status().state == can::CanBusState::kBusOff;
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    if (bus_trouble || drives_[i].rebooted() || !drives_[i].LostReason(now_s).empty() ||
        drives_[i].phase() == DrivePhase::kFailed) {
      restart_[i] = true;
    }
  }
}

std::string CanbridgeNode::FaultCause() const {
  for (const DriveLink& drive : drives_) {
    if (!drive.faulted()) continue;
    char text[200];
    std::snprintf(text, sizeof(text), "drive fault: %s in %s, last EMCY 0x%04X", drive.Label().c_str(),
                  drive.state() ? std::string(cia402::ToString(*drive.state())).c_str() : "unknown state",
                  drive.last_emcy_code());
    return text;
  }
  if (base_.faulted()) {
    return "base fault: " + base::DescribeFaultBits(base_.fault_bits()) + " (base node " +
           std::to_string(base_.node_id()) + ")";
  }
  return "";
}

bool CanbridgeNode::CommandStale(double now_s) const {
  // Stale two cycles early, so that the stop frames are on the bus within command_timeout_s even
  // when a cycle runs late: one cycle early, the fault suite measured 102 ms on the graph's bus
  // on the loaded two-core machine (kill -9 of the tracker; limit 100 ms).
  return last_command_s_ && now_s - *last_command_s_ > options_.command_timeout_s - 2.0 * options_.cycle_period_s;
}

bool CanbridgeNode::CommandAllowsRecovery(double now_s) const {
  if (!last_command_s_) return true;
  if (now_s - *last_command_s_ > options_.command_timeout_s) return false;  // stale: wait for fresh zeros
  return IsZeroCommand(latest_command_, options_.zero_command_tolerance);
}

std::string CanbridgeNode::TransientCause(double now_s) const {
  if (bus_down_) return "CAN interface down (" + bus_->url() + ")";
  if (bus_->status().state == can::CanBusState::kBusOff) return "CAN bus-off (" + bus_->url() + ")";
  if (base_.lost(now_s)) {
    char text[120];
    std::snprintf(text, sizeof(text), "base (node %d) lost: no status for %.0f ms", base_.node_id(),
                  base_.status_age_s(now_s) * 1e3);
    return text;
  }
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    const DriveLink& drive = drives_[i];
    if (drive.phase() == DrivePhase::kFailed) return "drive start-up failed: " + drive.failure();
    // Stopped, a drive marked for a restart (lost or rebooted) waits for the recovery's start-up,
    // the only thing that can bring it back (a rebooted drive stays unconfigured: no heartbeat
    // or PDOs until its start-up writes); a start-up that fails then is the cause.
    if (state_ == BridgeState::kStopped && restart_[i]) continue;
    if (drive.rebooted()) return drive.Label() + " rebooted (boot-up while operational)";
    if (std::string lost = drive.LostReason(now_s); !lost.empty()) return "drive lost: " + lost;
  }
  if (CommandStale(now_s)) {
    char text[120];
    std::snprintf(text, sizeof(text), "CONTROL_COMMAND stale: none for %.0f ms", (now_s - *last_command_s_) * 1e3);
    return text;
  }
  return "";
}

bool CanbridgeNode::AllDrivesOperational() const {
  for (const DriveLink& drive : drives_) {
    if (drive.phase() != DrivePhase::kOperational) return false;
  }
  return true;
}

std::string CanbridgeNode::NotReadyText() const {
  if (!base_.status_seen()) return "waiting for the base's status (node " + std::to_string(base_.node_id()) + ")";
  if (!base_.at_target()) {
    return std::string("base in ") + (base_.mode() ? base::ModeName(*base_.mode()) : "unknown mode");
  }
  for (const DriveLink& drive : drives_) {
    if (drive.phase() == DrivePhase::kFailed) return drive.failure();
  }
  for (const DriveLink& drive : drives_) {
    if (drive.phase() != DrivePhase::kOperational) return drive.Label() + " " + ToString(drive.phase());
  }
  for (const DriveLink& drive : drives_) {
    if (!drive.enabled()) {
      return drive.Label() + " in " +
             (drive.state() ? std::string(cia402::ToString(*drive.state())) : std::string("unknown state"));
    }
  }
  return "";
}

void CanbridgeNode::Enter(BridgeState state, double now_s, std::string reason) {
  if (state != state_ || reason != stop_reason_) {
    if (state == BridgeState::kRunning) {
      spdlog::info("canbridge: {} -> running", ToString(state_));
    } else if (state == BridgeState::kFault || state == BridgeState::kStopped) {
      spdlog::warn("canbridge: {} -> {}: {}", ToString(state_), ToString(state), reason);
    } else {
      spdlog::info("canbridge: {} -> {}: {}", ToString(state_), ToString(state), reason);
    }
  }
  if (state != state_) state_since_s_ = now_s;
  state_ = state;
  stop_reason_ = std::move(reason);
  cause_clear_since_s_.reset();
  if (state != BridgeState::kRunning) limiter_.ResetToZero(now_s);
}

void CanbridgeNode::BeginRecovery(double now_s) {
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    if (restart_[i] || drives_[i].phase() != DrivePhase::kOperational) drives_[i].BeginStartup(now_s);
    restart_[i] = false;
  }
  Enter(BridgeState::kRecovering, now_s, "recovering: " + stop_reason_);
}

void CanbridgeNode::UpdateState(double now_s) {
  const std::string fault = FaultCause();
  const bool in_reset_grace = fault_reset_s_ && now_s - *fault_reset_s_ < options_.fault_reset_timeout_s;
  switch (state_) {
    case BridgeState::kStarting:
      if (!fault.empty()) return Enter(BridgeState::kFault, now_s, fault);
      if (AllDrivesOperational() && base_.status_seen()) return Enter(BridgeState::kEnabling, now_s, "enabling");
      stop_reason_ = "starting: " + NotReadyText();
      return;
    case BridgeState::kEnabling:
    case BridgeState::kRecovering: {
      if (!fault.empty() && !in_reset_grace) {
        return Enter(BridgeState::kFault, now_s, (fault_reset_s_ ? "fault reset failed: " : "") + fault);
      }
      const std::string cause = TransientCause(now_s);
      if (!cause.empty() && !(state_ == BridgeState::kRecovering && cause.rfind("drive start-up failed", 0) == 0)) {
        return Enter(BridgeState::kStopped, now_s, cause);
      }
      std::string not_ready = NotReadyText();
      // Never start moving in the middle of a command stream meant for a robot that was not
      // running: the first RUNNING needs a zero command (or none), as every recovery does.
      if (not_ready.empty() && !CommandAllowsRecovery(now_s)) not_ready = "waiting for a zero CONTROL_COMMAND";
      if (not_ready.empty()) {
        fault_reset_s_.reset();
        return Enter(BridgeState::kRunning, now_s, "");
      }
      if (now_s - state_since_s_ > options_.enable_timeout_s) {
        return Enter(BridgeState::kStopped, now_s, "enable timed out: " + not_ready);
      }
      stop_reason_ = std::string(ToString(state_)) + ": " + not_ready;
      return;
    }
    case BridgeState::kRunning: {
      if (!fault.empty()) return Enter(BridgeState::kFault, now_s, fault);
      if (std::string cause = TransientCause(now_s); !cause.empty()) return Enter(BridgeState::kStopped, now_s, cause);
      // A device that left its running state by itself (the base's watchdog, a drive's own
      // quick stop or disable) stops the others too; recovery brings it back.
      if (std::string left = NotReadyText(); !left.empty()) return Enter(BridgeState::kStopped, now_s, "left running: " + left);
      return;
    }
    case BridgeState::kStopped: {
      if (!fault.empty()) return Enter(BridgeState::kFault, now_s, fault);
      if (std::string cause = TransientCause(now_s); !cause.empty()) {
        stop_reason_ = cause;
        cause_clear_since_s_.reset();
        return;
      }
      if (!cause_clear_since_s_) cause_clear_since_s_ = now_s;
      if (now_s - *cause_clear_since_s_ >= options_.recovery_hold_s && CommandAllowsRecovery(now_s)) {
        BeginRecovery(now_s);
      }
      return;
    }
    case BridgeState::kFault:
      MaybeResetCommunicationFault(now_s);
      return;
    case BridgeState::kReplay:
      return;
  }
}

bool CanbridgeNode::SendFrame(const can::CanFrame& frame, double now_s) {
  const can::CanResult result = bus_->Send(frame);
  if (result.ok()) {
    load_.Add(frame, now_s);
    return true;
  }
  ++tx_refused_;
  if (result.code == can::CanResult::Code::kInterfaceDown || result.code == can::CanResult::Code::kClosed) {
    if (!bus_down_) spdlog::error("CAN bus {}: {}", bus_->url(), result.message);
    bus_down_ = true;
  }
  return false;
}

void CanbridgeNode::SendCycleFrames(double now_s) {
  const bool moving_state = state_ == BridgeState::kEnabling || state_ == BridgeState::kRecovering ||
                            state_ == BridgeState::kRunning;
  base_.SetTargetMode(state_ == BridgeState::kStarting ? base::BaseMode::kStandby
                      : moving_state                    ? base::BaseMode::kCanCommand
                                                        : base::BaseMode::kQuickStop);
  DeviceCommand command;
  command.qdot_radps.assign(drives_.size(), 0.0);
  // Running: the latest command again (zero before the first), clamped; else zero, which is then
  // the previous value sent: the first step of the next RUNNING changes from it, over the time
  // since this frame (not since the stop began).
  if (state_ == BridgeState::kRunning) {
    command = limiter_.Step(latest_command_, now_s);
  } else {
    limiter_.ResetToZero(now_s);
  }

  std::vector<can::CanFrame>& frames = cycle_frames_;
  frames.clear();  // its capacity kept: no allocation per cycle
  base_.CycleFrames(now_s, command.v_mps, command.omega_radps, &frames);
  const DriveIntent intent = moving_state ? DriveIntent::kEnable : DriveIntent::kQuickStop;
  bool any_operational = false;
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    DriveLink& drive = drives_[i];
    if (drive.phase() != DrivePhase::kOperational) {
      drive.StartupStep(now_s, &frames);
      continue;
    }
    any_operational = true;
    frames.push_back(drive.Rpdo(intent, command.qdot_radps[i]));
    drive.StartupStep(now_s, &frames);  // operational: only an error-code read, when asked
  }
  if (any_operational) {
    if (auto sync = canopen::EncodeSync({}, nullptr)) frames.push_back(*sync);
  }
  if (now_s - last_host_heartbeat_s_ >= options_.drives.host_heartbeat_period_s - 1e-9) {
    last_host_heartbeat_s_ = now_s;
    if (auto beat = canopen::EncodeHeartbeat({options_.drives.startup.host_node_id, canopen::NmtState::kOperational}, nullptr)) {
      frames.push_back(*beat);
    }
  }
  for (const can::CanFrame& frame : frames) SendFrame(frame, now_s);
}

// ---------------------------------------------------------------------------------------------
// Outputs

void CanbridgeNode::FillOutputs(double now_s, std::int64_t now_utime) {
  if (const auto velocity = base_.TakeNewVelocity()) {
    base_velocity_t msg;
    msg.utime = now_utime;
    msg.v_mps = velocity->v_m_per_s;
    msg.omega_radps = velocity->omega_rad_per_s;
    outputs_.base_velocity = msg;
  }
  bool fresh = false;
  for (DriveLink& drive : drives_) fresh = drive.TakeNewFeedback() || fresh;
  if (fresh) {
    joint_state_t msg;
    msg.utime = now_utime;
    msg.num_joints = static_cast<int>(drives_.size());
    msg.names.reserve(drives_.size());
    msg.position_rad.reserve(drives_.size());
    msg.velocity_radps.reserve(drives_.size());
    msg.effort_Nm.reserve(drives_.size());
    for (const DriveLink& drive : drives_) {
      msg.names.push_back(drive.joint_name());
      msg.position_rad.push_back(drive.position_rad());
      msg.velocity_radps.push_back(drive.velocity_rad_per_s());
      msg.effort_Nm.push_back(std::numeric_limits<double>::quiet_NaN());
    }
    outputs_.joint_state = msg;
  }
  FillStatusKey(&status_key_);
  if (status_key_ != last_status_key_ || now_s - last_status_s_ >= options_.status_period_s - 1e-9) {
    std::swap(last_status_key_, status_key_);
    last_status_s_ = now_s;
    outputs_.status = StatusMessage(now_s, now_utime);
  }
}

void CanbridgeNode::FillStatusKey(StatusKey* key) const {
  key->state = state_;
  key->stop_reason = stop_reason_;  // assigned in place: no allocation while it fits
  key->bus_state = bus_->status().state;
  key->base_mode = base_.mode() ? static_cast<int>(*base_.mode()) : -1;
  key->base_fault_bits = base_.fault_bits();
  key->drives.resize(drives_.size());
  for (std::size_t i = 0; i < drives_.size(); ++i) {
    const DriveLink& drive = drives_[i];
    key->drives[i] = DriveStatusKey{drive.state() ? static_cast<int>(*drive.state()) : -1, drive.last_emcy_code(),
                                    static_cast<int>(drive.phase())};
  }
}

drive_status_t CanbridgeNode::StatusMessage(double now_s, std::int64_t now_utime) {
  const can::CanBusStatus& bus = bus_->status();
  drive_status_t msg;
  msg.utime = now_utime;
  msg.state = static_cast<std::int8_t>(state_);
  msg.stop_reason = stop_reason_;
  msg.can_url = bus_->url();
  msg.bus_state = can::ToString(bus.state);
  msg.frames_sent = static_cast<std::int64_t>(bus.frames_sent);
  msg.frames_received = static_cast<std::int64_t>(bus.frames_received);
  msg.error_frames = static_cast<std::int64_t>(bus.error_frames);
  msg.bus_off_count = static_cast<std::int64_t>(bus.bus_off_count);
  msg.tx_refused = tx_refused_;
  msg.frames_malformed = counters_.malformed();
  msg.frames_unknown = counters_.unknown();
  msg.bus_load_percent = load_.LoadPercent(now_s);
  msg.command_age_s = last_command_s_ ? now_s - *last_command_s_ : -1.0;
  msg.commands_received = commands_received_;
  msg.commands_rejected = commands_rejected_;
  msg.clamp_count = limiter_.clamp_count();
  msg.command_latency_p99_ms = latency_.Summary().p99_ms;
  msg.cycle_jitter_p99_ms = jitter_.Summary().p99_ms;
  msg.base_mode = static_cast<std::int8_t>(base_.mode() ? static_cast<int>(*base_.mode()) : -1);
  msg.base_fault_bits = base_.fault_bits();
  msg.base_faults = base::DescribeFaultBits(base_.fault_bits());
  msg.base_status_age_s = base_.status_age_s(now_s);
  msg.base_battery_v = base_.battery_v();
  msg.num_drives = static_cast<std::int32_t>(drives_.size());
  for (const DriveLink& drive : drives_) {
    msg.node_id.push_back(drive.node_id());
    msg.joint_name.push_back(drive.joint_name());
    msg.drive_state.push_back(drive.state() ? std::string(cia402::ToString(*drive.state())) : "unknown");
    msg.nmt_state.push_back(drive.nmt_state() ? std::string(canopen::ToString(*drive.nmt_state())) : "unknown");
    msg.statusword.push_back(drive.statusword() ? *drive.statusword() : -1);
    msg.last_emcy_code.push_back(drive.last_emcy_code());
    msg.heartbeat_age_s.push_back(drive.heartbeat_age_s(now_s));
  }
  return msg;
}

std::int8_t CanbridgeNode::Health() const {
  if (state_ == BridgeState::kRunning || state_ == BridgeState::kReplay) return heartbeat_t::OK;
  if (state_ == BridgeState::kFault) return heartbeat_t::ERROR;
  return heartbeat_t::WARN;
}

std::string CanbridgeNode::StatusLine(double now_s) {
  char text[400];
  std::snprintf(text, sizeof(text), "%s%s%s | bus %s %.1f%% | commands %lld (rejected %lld, clamped %ld) | malformed %lld unknown %lld",
                ToString(state_), stop_reason_.empty() ? "" : ": ", stop_reason_.c_str(),
                can::ToString(bus_->status().state), load_.LoadPercent(now_s),
                static_cast<long long>(commands_received_), static_cast<long long>(commands_rejected_),
                limiter_.clamp_count(), static_cast<long long>(counters_.malformed()),
                static_cast<long long>(counters_.unknown()));
  return text;
}

std::string CanbridgeNode::Report(double now_s) {
  const can::CanBusStatus& bus = bus_->status();
  std::string report = "topay-canbridge report\n";
  report += "  state: " + StatusLine(now_s) + "\n";
  char text[400];
  std::snprintf(text, sizeof(text),
                "  cycles %lld; frames sent %llu, received %llu (host frames %lld), error frames %llu, bus-off %llu, "
                "tx refused %lld\n",
                static_cast<long long>(cycles_), static_cast<unsigned long long>(bus.frames_sent),
                static_cast<unsigned long long>(bus.frames_received), static_cast<long long>(counters_.host_frames()),
                static_cast<unsigned long long>(bus.error_frames), static_cast<unsigned long long>(bus.bus_off_count),
                static_cast<long long>(tx_refused_));
  report += text;
  report += "  command -> CAN frame latency: " + latency_.Text() + "\n";
  report += "  cycle jitter: " + jitter_.Text() + "\n";
  for (const auto& [kind, count] : counters_.by_kind()) {
    report += "  " + kind + ": " + std::to_string(count) + "\n";
  }
  return report;
}

// ---------------------------------------------------------------------------------------------
// Wiring

void ConnectCanbridgeNode(procs::ProcessLoop* loop, CanbridgeNode* node, double period_s,
                          std::function<bool()> finished) {
  loop->Subscribe<control_command_t>(std::string(channels::CONTROL_COMMAND),
                                     [node](const control_command_t& msg) { node->OnCommand(msg, SteadySeconds()); });
  loop->Subscribe<drive_command_t>(std::string(channels::DRIVE_COMMAND),
                                   [node](const drive_command_t& msg) { node->OnDriveCommand(msg, SteadySeconds()); });
  using Clock = procs::ProcessLoop::Clock;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_s));
  auto due = std::make_shared<std::optional<Clock::time_point>>();
  loop->AddScheduledTimer([loop, node, period, due, finished]() {
    const Clock::time_point now = Clock::now();
    if (!*due) *due = now;
    node->RecordCycleLateness(std::chrono::duration<double>(now - **due).count());
    const double now_s = std::chrono::duration<double>(now.time_since_epoch()).count();
    const CanbridgeOutputs& out = node->Cycle(now_s, procs::NowUtime());
    lcm::LCM& lcm = loop->lcm();
    if (out.base_velocity) lcm.publish(std::string(channels::BASE_VELOCITY), &*out.base_velocity);
    if (out.joint_state) lcm.publish(std::string(channels::JOINT_STATE), &*out.joint_state);
    if (out.status) {
      lcm.publish(std::string(channels::DRIVE_STATUS), &*out.status);
      loop->SetHealth(node->Health(), node->StatusLine(now_s));
    }
    if (finished && finished()) loop->Stop();
    **due += period;
    if (**due < now) *due = now + period;  // far behind (a stall): skip, no burst
    return **due;
  });
}

}  // namespace topay::canbridge
