#include "tools/report/active_trajectory.h"

#include <algorithm>

namespace topay::report {

std::int64_t ActivationUtime(const LoggedTrajectory& trajectory) {
  return std::max(trajectory.poly.start_utime, trajectory.poly.utime);
}

std::optional<std::size_t> ActiveTrajectoryAt(const std::vector<LoggedTrajectory>& trajectories,
                                              std::int64_t utime) {
  for (std::size_t k = trajectories.size(); k-- > 0;) {
    if (ActivationUtime(trajectories[k]) <= utime) return k;
  }
  return std::nullopt;
}

std::vector<std::int64_t> TrajectorySwitchUtimes(const std::vector<LoggedTrajectory>& trajectories) {
  std::vector<std::int64_t> switches;
  for (std::size_t k = 0; k < trajectories.size(); ++k) {
    const std::int64_t at = ActivationUtime(trajectories[k]);
    if (ActiveTrajectoryAt(trajectories, at) == k) switches.push_back(at);
  }
  std::sort(switches.begin(), switches.end());
  return switches;
}

}  // namespace topay::report
