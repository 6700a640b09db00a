#include "core/estimation/state_continuity_gate.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/common/angles.h"
#include "core/common/stamp_difference.h"

namespace topay {
namespace {

constexpr double kSPerUs = 1e-6;

void Require(bool ok, const char* field, const char* rule) {
  if (!ok) throw std::invalid_argument(std::string("StateContinuityGateOptions.") + field + " must be " + rule);
}

std::string Fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

}  // namespace

void StateContinuityGateOptions::Check() const {
  Require(max_speed_mps > 0.0, "max_speed_mps", "> 0");
  Require(max_yaw_rate_radps > 0.0, "max_yaw_rate_radps", "> 0");
  Require(max_joint_rate_radps > 0.0, "max_joint_rate_radps", "> 0");
  Require(slack_position_m >= 0.0, "slack_position_m", ">= 0");
  Require(slack_yaw_rad >= 0.0, "slack_yaw_rad", ">= 0");
  Require(slack_joint_rad >= 0.0, "slack_joint_rad", ">= 0");
  Require(max_gap_s > 0.0, "max_gap_s", "> 0");
  Require(reanchor_after >= 1, "reanchor_after", ">= 1");
  // NaN fails every comparison above, so it is refused too.
}

const char* ContinuityVerdictName(ContinuityVerdict verdict) {
  switch (verdict) {
    case ContinuityVerdict::kTaken: return "taken";
    case ContinuityVerdict::kReanchored: return "re-anchored";
    case ContinuityVerdict::kRefusedStale: return "stamped at or before the last state";
    case ContinuityVerdict::kRefusedGap: return "stamped too far after the last state";
    case ContinuityVerdict::kRefusedJump: return "a jump beyond the robot's limits";
    case ContinuityVerdict::kRefusedJoints: return "a different joint count";
    case ContinuityVerdict::kRefusedNotFinite: return "not finite";
  }
  return "?";
}

std::int64_t StateContinuityGateSummary::refused() const {
  return refused_stale + refused_gap + refused_jump + refused_joints + refused_not_finite;
}

std::string FormatStateContinuitySummary(const StateContinuityGateSummary& s) {
  return std::to_string(s.taken) + " taken, " + std::to_string(s.reanchored) + " re-anchored; refused: " +
         std::to_string(s.refused_stale) + " stale, " + std::to_string(s.refused_gap) + " gap, " +
         std::to_string(s.refused_jump) + " jump, " + std::to_string(s.refused_joints) + " joints, " +
         std::to_string(s.refused_not_finite) + " not finite";
}

StateContinuityGate::StateContinuityGate(const StateContinuityGateOptions& options) : options_(options) {
  options_.Check();
}

std::optional<ContinuityVerdict> StateContinuityGate::Discontinuity(const Stamped& from, const Stamped& next,
                                                                    std::string* reason) const {
  if (next.t_us <= from.t_us) {
    *reason = "stamped " + Fixed(static_cast<double>(StampDifferenceUs(from.t_us, next.t_us)) * 1e-3, 1) +
              " ms before the last state";
    return ContinuityVerdict::kRefusedStale;
  }
  const double dt_s = static_cast<double>(StampDifferenceUs(next.t_us, from.t_us)) * kSPerUs;
  if (dt_s > options_.max_gap_s) {
    *reason = "stamped " + Fixed(dt_s, 3) + " s after the last state, at most " + Fixed(options_.max_gap_s, 3);
    return ContinuityVerdict::kRefusedGap;
  }
  if (next.state.num_joints() != from.state.num_joints()) {
    *reason = std::to_string(next.state.num_joints()) + " joints after " + std::to_string(from.state.num_joints());
    return ContinuityVerdict::kRefusedJoints;
  }
  // Reachable in dt: |dp| <= v_max dt + slack, |dyaw| <= omega_max dt + slack, per joint
  // |dq| <= qdot_max dt + slack.
  const double moved_m = std::hypot(next.state.x_m - from.state.x_m, next.state.y_m - from.state.y_m);
  const double reach_m = options_.max_speed_mps * dt_s + options_.slack_position_m;
  const double turned_rad = std::abs(WrapAngle(next.state.yaw_rad - from.state.yaw_rad));
  const double reach_yaw_rad = options_.max_yaw_rate_radps * dt_s + options_.slack_yaw_rad;
  const double joint_rad =
      from.state.num_joints() == 0 ? 0.0 : (next.state.q_rad - from.state.q_rad).cwiseAbs().maxCoeff();
  const double reach_joint_rad = options_.max_joint_rate_radps * dt_s + options_.slack_joint_rad;
  if (moved_m <= reach_m && turned_rad <= reach_yaw_rad && joint_rad <= reach_joint_rad) return std::nullopt;
  *reason = "in " + Fixed(dt_s, 3) + " s moved " + Fixed(moved_m, 3) + " m (at most " + Fixed(reach_m, 3) +
            "), turned " + Fixed(turned_rad, 3) + " rad (at most " + Fixed(reach_yaw_rad, 3) + "), a joint " +
            Fixed(joint_rad, 3) + " rad (at most " + Fixed(reach_joint_rad, 3) + ")";
  return ContinuityVerdict::kRefusedJump;
}

ContinuityVerdict StateContinuityGate::Check(std::int64_t t_us, const WholeBodyState& state) {
  ++messages_;
  Stamped next{t_us, state};
  if (!state.IsFinite()) {
    last_reason_ = "a pose or joint value is not finite";
    Count(ContinuityVerdict::kRefusedNotFinite);
    return ContinuityVerdict::kRefusedNotFinite;
  }
  if (anchor_) {
    if (const std::optional<ContinuityVerdict> refused = Discontinuity(*anchor_, next, &last_reason_)) {
      return Refuse(*refused, next);
    }
  }
  anchor_ = std::move(next);
  candidates_.fill(Candidate{});
  last_reason_.clear();
  Count(ContinuityVerdict::kTaken);
  return ContinuityVerdict::kTaken;
}

StateContinuityGate::Candidate* StateContinuityGate::Extended(const Stamped& next) {
  std::string ignored;
  Candidate* oldest = &candidates_[0];
  for (Candidate& c : candidates_) {
    if (c.length > 0 && !Discontinuity(c.newest, next, &ignored)) {
      ++c.length;
      c.newest = next;
      c.last_extended = messages_;
      return &c;
    }
    if (c.length == 0 || (oldest->length > 0 && c.last_extended < oldest->last_extended)) oldest = &c;
  }
  *oldest = Candidate{next, 1, messages_};
  return oldest;
}

ContinuityVerdict StateContinuityGate::Refuse(ContinuityVerdict verdict, const Stamped& next) {
  const Candidate* stream = Extended(next);
  if (stream->length < options_.reanchor_after) {
    Count(verdict);
    return verdict;
  }
  // A consistent new stream: the state really jumped (re-initialised, restarted, replayed).
  last_reason_ = "re-anchored after " + std::to_string(stream->length) + " states that continue each other (" +
                 last_reason_ + ")";
  anchor_ = next;
  candidates_.fill(Candidate{});
  Count(ContinuityVerdict::kReanchored);
  return ContinuityVerdict::kReanchored;
}

void StateContinuityGate::Count(ContinuityVerdict verdict) {
  switch (verdict) {
    case ContinuityVerdict::kTaken: ++summary_.taken; break;
    case ContinuityVerdict::kReanchored: ++summary_.reanchored; break;
    case ContinuityVerdict::kRefusedStale: ++summary_.refused_stale; break;
    case ContinuityVerdict::kRefusedGap: ++summary_.refused_gap; break;
    case ContinuityVerdict::kRefusedJump: ++summary_.refused_jump; break;
    case ContinuityVerdict::kRefusedJoints: ++summary_.refused_joints; break;
    case ContinuityVerdict::kRefusedNotFinite: ++summary_.refused_not_finite; break;
  }
}

}  // namespace topay
