#include "procs/msgs/planner_status_text.h"

#include <algorithm>
#include <cstdio>

namespace topay::msgs {
namespace {

constexpr std::string_view kTrajectoryPrefix = "trajectory ";
constexpr std::string_view kEndedSuffix = " ended";
constexpr std::string_view kReachedAtRestPrefix = "goal reached at rest: ";

// "trajectory " + digits + " ended", nothing else (a plan trigger may name a trajectory too).
bool IsTrajectoryEnded(const std::string& detail) {
  if (!detail.starts_with(kTrajectoryPrefix) || !detail.ends_with(kEndedSuffix)) return false;
  const auto begin = detail.begin() + kTrajectoryPrefix.size();
  const auto end = detail.end() - kEndedSuffix.size();
  return begin < end && std::all_of(begin, end, [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

std::string TrajectoryEndedDetail(std::int64_t trajectory_id) {
  return std::string(kTrajectoryPrefix) + std::to_string(trajectory_id) + std::string(kEndedSuffix);
}

std::string ReachedAtRestDetail(double position_m, double angle_rad) {
  char text[96];
  std::snprintf(text, sizeof text, "end effector %.3f m / %.3f rad from the target", position_m, angle_rad);
  return std::string(kReachedAtRestPrefix) + text;
}

bool ReportsTrajectoryEnded(const planner_status_t& status) {
  return status.state == planner_status_t::SUCCEEDED && IsTrajectoryEnded(status.detail);
}

bool ReportsReachedAtRest(const planner_status_t& status) {
  return status.state == planner_status_t::SUCCEEDED && status.detail.starts_with(kReachedAtRestPrefix);
}

bool ReportsGoalReached(const planner_status_t& status) {
  return ReportsTrajectoryEnded(status) || ReportsReachedAtRest(status);
}

}  // namespace topay::msgs
