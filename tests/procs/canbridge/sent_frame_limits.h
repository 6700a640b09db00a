#pragma once
// The envelope every frame topay-canbridge sends must keep (docs/canbridge.md, "Clamping" and
// "Stops, reporting and recovery"), checked frame by frame, for the property test
// (command_limits_property_test.cc) and the canbridge fuzz target (tests/fuzz/canbridge_fuzz.cc).
// The limits are the bridge's own: the robot model's (CommandLimits, as its limiter has them) and
// the CanbridgeOptions' (node ids, PDO units, cycle, command timeout); no number is typed in.
//
// For each commanded value (the base velocity command's v and omega, each drive's RPDO1 target
// velocity), with `now_s` the time the bridge was given when it sent the frame:
//  - the frame decodes with the protocol's own decoder (the bridge's node ids and units);
//  - |value| <= its velocity limit + half an encoder unit (the encoders round to the nearest);
//  - the value is zero in every state but RUNNING, and in any frame sent command_timeout_s or
//    more after the last valid CONTROL_COMMAND (the stale-command stop);
//  - the change from the value's previous frame is at most the acceleration limit times the time
//    between the two (at most one cycle, as the limiter counts it) plus one encoder unit (the
//    tolerance of canbridge_node_test's NothingSentOutsideTheLimits). The stop itself is the one
//    exception: a zero sent in STOPPED or FAULT goes with the quick stop (base mode request,
//    controlword 0x0002 or 0x0000), and the devices ramp down at their own quick-stop rate; such
//    an RPDO1 never commands enable operation. A stop whose frames the bus refused (bus-off,
//    interface down) is a stop all the same: the devices stop on their own when their commands
//    and the host's heartbeat cease (the base's watchdog, the drives' heartbeat consumer), so the
//    values after it change from zero, from the time the bridge was seen stopped (OnState).
// Every frame is a valid standard data frame with one of the ids the bridge uses (base mode
// request and velocity command, RPDO1 and SDO requests of its drives, NMT, SYNC, its heartbeat)
// that the protocol's decoder accepts.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_state.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/sync.h"
#include "drivers/base/frame_bytes.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/protocol_ids.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/can/can_frame.h"
#include "procs/canbridge/bridge_state.h"
#include "procs/canbridge/canbridge_options.h"
#include "procs/canbridge/command_limiter.h"

namespace topay::canbridge::test {

class SentFrameLimits {
 public:
  SentFrameLimits(const CanbridgeOptions& options, const CommandLimits& limits)
      : options_(options), base_node_(options.base.node_id) {
    if (limits.qd_max_radps.size() != options.drives.node_ids.size() ||
        limits.qdd_max_radps2.size() != options.drives.node_ids.size()) {
      throw std::invalid_argument("SentFrameLimits: one joint limit per drive expected");
    }
    const auto [v_unit, omega_unit] = BaseUnits();
    AddChannel("base v [m/s]", limits.v_max_mps, limits.a_max_mps2, v_unit);
    AddChannel("base omega [rad/s]", limits.omega_max_radps, limits.beta_max_radps2, omega_unit);
    for (std::size_t i = 0; i < options.drives.node_ids.size(); ++i) {
      const int node = options.drives.node_ids[i];
      AddChannel("qdot of node " + std::to_string(node) + " [rad/s]", limits.qd_max_radps[i], limits.qdd_max_radps2[i],
                 options.drives.units.rad_per_s_per_velocity_unit);
      rpdo1_channel_[CobId(canopen::CanopenFunction::kRpdo1, node)] = channels_.size() - 1;
      sdo_request_ids_.push_back(CobId(canopen::CanopenFunction::kSdoRx, node));
    }
  }

  /// A CONTROL_COMMAND the bridge accepted at now_s (the command timeout runs from its time).
  void OnValidCommand(double now_s) { last_valid_command_s_ = now_s; }

  /// The bridge's state after a call at now_s (whether or not a frame went out): a stop hands
  /// every value over to the devices' own stop, the next frames change from zero.
  void OnState(BridgeState state, double now_s) {
    if (!IsStop(state)) return;
    for (Channel& c : channels_) {
      if (c.last != 0.0) ++stops_seen_;
      c.last = 0.0;
      c.last_s = now_s;
    }
  }

  /// "" when `frame`, sent at now_s in `state`, keeps the envelope; else what it breaks.
  std::string Check(const can::CanFrame& frame, double now_s, BridgeState state) {
    ++frames_by_state_[state];
    const std::string problem = Problem(frame, now_s, state);
    if (problem.empty()) return "";  // the frame's description only for a failure: this runs on every frame
    return can::ToString(frame) + " at " + std::to_string(now_s) + " s in " + ToString(state) + ": " + problem;
  }

  /// Frames checked in `state`.
  std::int64_t frames_in(BridgeState state) const {
    const auto it = frames_by_state_.find(state);
    return it == frames_by_state_.end() ? 0 : it->second;
  }
  /// Commanded values checked at or after the command timeout (which had to be zero).
  std::int64_t stale_values_checked() const { return stale_values_checked_; }
  /// Stops seen: a non-zero value followed by the stop's zero.
  std::int64_t stops_seen() const { return stops_seen_; }

 private:
  // "" when the frame keeps the envelope; else what it breaks.
  std::string Problem(const can::CanFrame& frame, double now_s, BridgeState state) {
    if (!can::CheckCanFrame(frame).empty() || frame.error || frame.remote || frame.extended) {
      return "not a valid standard data frame";
    }
    const bool stale = last_valid_command_s_ && now_s - *last_valid_command_s_ >= options_.command_timeout_s - 1e-9;
    if (frame.id == base::FrameId(base::BaseFrameKind::kVelocityCommand, base_node_)) {
      return CheckBaseVelocity(frame, now_s, state, stale);
    }
    if (const auto it = rpdo1_channel_.find(frame.id); it != rpdo1_channel_.end()) {
      return CheckRpdo1(frame, &channels_[it->second], now_s, state, stale);
    }
    if (frame.id == base::FrameId(base::BaseFrameKind::kModeRequest, base_node_)) {
      return base::DecodeModeRequest(frame, base_node_, nullptr) ? "" : "a malformed mode request";
    }
    if (std::find(sdo_request_ids_.begin(), sdo_request_ids_.end(), frame.id) != sdo_request_ids_.end()) {
      return canopen::DecodeSdoClientRequest(frame, nullptr) ? "" : "a malformed SDO request";
    }
    if (frame.id == CobId(canopen::CanopenFunction::kNmt, 0)) {
      return canopen::DecodeNmt(frame, nullptr) ? "" : "a malformed NMT command";
    }
    if (frame.id == CobId(canopen::CanopenFunction::kSync, 0)) {
      return canopen::DecodeSync(frame, nullptr) ? "" : "a malformed SYNC";
    }
    if (frame.id == CobId(canopen::CanopenFunction::kHeartbeat, options_.drives.startup.host_node_id)) {
      return canopen::DecodeHeartbeat(frame, nullptr) ? "" : "a malformed heartbeat";
    }
    return "an id the bridge has no business sending";
  }

  struct Channel {
    std::string name;
    double max_abs = 0.0;
    double max_rate = 0.0;
    double unit = 0.0;
    double last = 0.0;
    std::optional<double> last_s;
  };

  void AddChannel(std::string name, double max_abs, double max_rate, double unit) {
    Channel channel;
    channel.name = std::move(name);
    channel.max_abs = max_abs;
    channel.max_rate = max_rate;
    channel.unit = unit;
    channels_.push_back(std::move(channel));
  }

  static std::uint32_t CobId(canopen::CanopenFunction function, int node) {
    const auto id = canopen::CobIdOf(function, node, nullptr);
    if (!id) throw std::invalid_argument("SentFrameLimits: node id " + std::to_string(node));
    return *id;
  }

  // The value of one raw unit of v and omega, from the protocol's decoder.
  std::pair<double, double> BaseUnits() const {
    can::CanFrame frame = base::MakeEmptyFrame(base::BaseFrameKind::kVelocityCommand, base_node_);
    base::PutInt16Le(frame, 0, 1);
    base::PutInt16Le(frame, 2, 1);
    base::SealFrame(frame, 0);
    const auto unit = base::DecodeVelocityCommand(frame, base_node_, std::nullopt, nullptr);
    if (!unit) throw std::invalid_argument("SentFrameLimits: the base's unit frame does not decode");
    return {unit->v_m_per_s, unit->omega_rad_per_s};
  }

  std::string CheckBaseVelocity(const can::CanFrame& frame, double now_s, BridgeState state, bool stale) {
    std::string error;
    const auto command = base::DecodeVelocityCommand(frame, base_node_, std::nullopt, &error);
    if (!command) return "the velocity command does not decode: " + error;
    std::string problem = CheckValue(&channels_[0], command->v_m_per_s, now_s, state, stale);
    if (problem.empty()) problem = CheckValue(&channels_[1], command->omega_rad_per_s, now_s, state, stale);
    return problem;
  }

  std::string CheckRpdo1(const can::CanFrame& frame, Channel* channel, double now_s, BridgeState state, bool stale) {
    std::string error;
    const auto pdo = cia402::DecodeRpdo1(frame, options_.drives.units, &error);
    if (!pdo) return "the RPDO1 does not decode: " + error;
    if (IsStop(state) && cia402::DecodeControlwordCommand(pdo->controlword) == cia402::Command::kEnableOperation) {
      return "a stop's RPDO1 commands enable operation";
    }
    return CheckValue(channel, pdo->target_velocity_rad_per_s, now_s, state, stale);
  }

  static bool IsStop(BridgeState state) { return state == BridgeState::kStopped || state == BridgeState::kFault; }

  std::string CheckValue(Channel* c, double value, double now_s, BridgeState state, bool stale) {
    char text[240];
    if (!std::isfinite(value) || std::abs(value) > c->max_abs + c->unit / 2 + 1e-9) {
      std::snprintf(text, sizeof(text), "%s = %.9g is beyond its limit %.9g", c->name.c_str(), value, c->max_abs);
      return text;
    }
    if (stale) ++stale_values_checked_;
    if ((state != BridgeState::kRunning || stale) && value != 0.0) {
      std::snprintf(text, sizeof(text), "%s = %.9g is not zero %s", c->name.c_str(), value,
                    stale ? "after the command timeout" : "outside RUNNING");
      return text;
    }
    if (IsStop(state)) {
      if (c->last != 0.0) ++stops_seen_;
    } else {
      const double dt_s =
          c->last_s ? std::clamp(now_s - *c->last_s, 0.0, options_.cycle_period_s) : options_.cycle_period_s;
      const double allowed = c->max_rate * dt_s + c->unit + 1e-9;
      if (std::abs(value - c->last) > allowed) {
        std::snprintf(text, sizeof(text), "%s changed by %.9g from %.9g in %.6f s, more than %.9g", c->name.c_str(),
                      value - c->last, c->last, dt_s, allowed);
        return text;
      }
    }
    c->last = value;
    c->last_s = now_s;
    return "";
  }

  CanbridgeOptions options_;
  int base_node_;
  std::vector<Channel> channels_;  // v, omega, then the joints in q order
  std::map<std::uint32_t, std::size_t> rpdo1_channel_;
  std::vector<std::uint32_t> sdo_request_ids_;
  std::optional<double> last_valid_command_s_;
  std::map<BridgeState, std::int64_t> frames_by_state_;
  std::int64_t stale_values_checked_ = 0;
  std::int64_t stops_seen_ = 0;
};

}  // namespace topay::canbridge::test
