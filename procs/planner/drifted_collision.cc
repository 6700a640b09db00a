#include "procs/planner/drifted_collision.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace topay::planner {

bool DriftWorthChecking(const Drift& drift, const DriftCheckOptions& options) {
  return drift.position_m > options.position_m || drift.yaw_rad > options.yaw_rad ||
         drift.joint_rad > options.joint_rad;
}

std::optional<PredictedCollision> FirstDriftedCollision(const DriftedRobot& robot, double horizon_s,
                                                        const SceneClearanceChecker& checker,
                                                        const TrajectoryCollisionScanOptions& scan) {
  if (!std::isfinite(horizon_s) || horizon_s <= 0.0) {
    throw std::invalid_argument("FirstDriftedCollision: horizon_s must be finite and > 0");
  }
  const ArcYawTrajectory& trajectory = *robot.active().trajectory;
  const double t_begin = std::clamp(robot.state_time_s(), 0.0, trajectory.duration_s());
  const double t_end = std::clamp(robot.state_time_s() + horizon_s, t_begin, trajectory.duration_s());
  const TrajectorySampler drifted = [&robot](double t_s, TrajectorySample* sample) { robot.Evaluate(t_s, sample); };
  return FirstPredictedCollisionOf(drifted, trajectory.MakePoint(), t_begin, t_end, checker, scan);
}

}  // namespace topay::planner
