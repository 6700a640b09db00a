#include "tools/report/robot_track.h"

#include <algorithm>
#include <cstdlib>

namespace topay::report {

std::vector<Eigen::Vector2d> DrivenPath(const std::vector<msgs::RobotStateEstimate>& states) {
  std::vector<Eigen::Vector2d> path;
  path.reserve(states.size());
  for (const msgs::RobotStateEstimate& s : states) path.emplace_back(s.state.x_m, s.state.y_m);
  return path;
}

std::optional<Eigen::Vector2d> BasePositionAt(const std::vector<msgs::RobotStateEstimate>& states,
                                              std::int64_t utime) {
  if (states.empty()) return std::nullopt;
  const auto after = std::lower_bound(states.begin(), states.end(), utime,
                                      [](const msgs::RobotStateEstimate& s, std::int64_t t) { return s.utime < t; });
  auto best = after == states.end() ? std::prev(after) : after;
  if (after != states.begin() && std::llabs(std::prev(after)->utime - utime) < std::llabs(best->utime - utime)) {
    best = std::prev(after);
  }
  return Eigen::Vector2d(best->state.x_m, best->state.y_m);
}

}  // namespace topay::report
