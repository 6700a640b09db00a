#include "core/robot/robot_state_history.h"

#include <algorithm>
#include <cmath>

#include "core/common/angles.h"

namespace topay {
namespace {

constexpr double kUsPerS = 1e6;

// (1 - a) from + a to, with the yaw along the shorter arc.
WholeBodyState Interpolate(const WholeBodyState& from, const WholeBodyState& to, double a) {
  WholeBodyState s;
  s.x_m = from.x_m + a * (to.x_m - from.x_m);
  s.y_m = from.y_m + a * (to.y_m - from.y_m);
  s.yaw_rad = WrapAngle(from.yaw_rad + a * WrapAngle(to.yaw_rad - from.yaw_rad));
  s.q_rad = from.q_rad + a * (to.q_rad - from.q_rad);
  return s;
}

}  // namespace

RobotStateHistory::RobotStateHistory(const RobotStateHistoryOptions& options)
    : options_(options) {}

bool RobotStateHistory::Add(std::int64_t utime, const WholeBodyState& state) {
  const bool joints_match = states_.empty() || states_.front().state.num_joints() == state.num_joints();
  if (!state.IsFinite() || !joints_match) {
    ++rejected_;
    return false;
  }
  const auto later = std::upper_bound(states_.begin(), states_.end(), utime,
                                      [](std::int64_t t, const Stamped& s) { return t < s.utime; });
  states_.insert(later, Stamped{utime, state});
  const auto horizon_us = static_cast<std::int64_t>(options_.horizon_s * kUsPerS);
  while (states_.size() > 1 && states_.back().utime - states_.front().utime > horizon_us) {
    states_.pop_front();
  }
  return true;
}

std::optional<WholeBodyState> RobotStateHistory::At(std::int64_t utime) const {
  if (states_.empty()) return std::nullopt;
  const auto max_gap_us = static_cast<std::int64_t>(options_.max_gap_s * kUsPerS);
  const auto after = std::lower_bound(states_.begin(), states_.end(), utime,
                                      [](const Stamped& s, std::int64_t t) { return s.utime < t; });
  if (after == states_.begin()) {
    if (after->utime - utime > max_gap_us) return std::nullopt;
    return after->state;
  }
  const auto before = std::prev(after);
  if (after == states_.end()) {
    if (utime - before->utime > max_gap_us) return std::nullopt;
    return before->state;
  }
  if (after->utime - before->utime > 2 * max_gap_us) {  // a hole in the stream: nearest only
    const auto& nearest = (utime - before->utime <= after->utime - utime) ? *before : *after;
    if (std::abs(nearest.utime - utime) > max_gap_us) return std::nullopt;
    return nearest.state;
  }
  const double a = static_cast<double>(utime - before->utime) /
                   static_cast<double>(std::max<std::int64_t>(after->utime - before->utime, 1));
  return Interpolate(before->state, after->state, a);
}

}  // namespace topay
