#include "procs/planner/stop_planner.h"

namespace topay::planner {

StopPlanner::StopPlanner(const RobotModel& model, const BaseLimits& base_limits)
    : model_(model), base_limits_(base_limits) {}

std::optional<ArcYawTrajectory> StopPlanner::Make(const ArcYawTrajectory&, double, std::string* why) const {
  *why = "TEMPORARY: waiting for core's stopping trajectory";
  return std::nullopt;
}

}  // namespace topay::planner
