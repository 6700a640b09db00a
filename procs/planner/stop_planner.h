#pragma once
// The safe stop's trajectory: from the state the current trajectory has at t0, along the same
// path, decelerating to rest within the robot's limits (core/trajectory/stopping_trajectory.h).

#include <optional>
#include <string>

#include "core/robot/robot_model.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay::planner {

class StopPlanner {
 public:
  /// `model` outlives this object; `base_limits` are the core planner's.
  StopPlanner(const RobotModel& model, const BaseLimits& base_limits);

  /// The stopping trajectory starting at t0_s of `current` (its time), C2-continuous with it
  /// there; nullopt with *why if none could be made. `duration_per_rate_ratio` replaces
  /// StoppingTrajectoryOptions' (3.0) when given: a smaller one stops sooner and shorter
  /// (1.6: about 94 % of the acceleration limits, lengthened if beyond them).
  std::optional<ArcYawTrajectory> Make(const ArcYawTrajectory& current, double t0_s, std::string* why,
                                       std::optional<double> duration_per_rate_ratio = std::nullopt) const;

 private:
  const RobotModel& model_;
  BaseLimits base_limits_;
};

}  // namespace topay::planner
