#include "procs/planner/stop_planner.h"

#include "core/planner/stopping_trajectory.h"

namespace topay::planner {

StopPlanner::StopPlanner(const RobotModel& model, const BaseLimits& base_limits)
    : model_(model), base_limits_(base_limits) {}

std::optional<ArcYawTrajectory> StopPlanner::Make(const ArcYawTrajectory& current, double t0_s, std::string* why,
                                                  std::optional<double> duration_per_rate_ratio) const {
  StoppingTrajectoryOptions options;
  if (duration_per_rate_ratio) options.duration_per_rate_ratio = *duration_per_rate_ratio;
  StoppingTrajectory stop = MakeStoppingTrajectory(current, t0_s, base_limits_, model_.joint_limits, options);
  if (!stop.success()) {
    *why = stop.reason;
    return std::nullopt;
  }
  return std::move(stop.trajectory);
}

}  // namespace topay::planner
