#pragma once
// The robot off its trajectory, checked against the map (finding 34, docs/reliability.md).
// The map check (CheckActiveAgainstMap) looks at the trajectory; the plan that made it was
// validated at the validator's margin (0), so a robot off it by more than the plan's clearance
// can touch what the trajectory passes: under overload the base ran 0.18-0.23 m off its
// reference and the arm grazed a table top, below the drift trigger (0.3 m). While the robot's
// drift exceeds small tolerances (the tracker's normal errors are ~2 cm), the planner also
// checks the drifted robot: the trajectory ahead with the robot's error carried along (as
// DriftedRobot). A collision of that is handled like a map collision: a replan from
// the drifted robot at once, and a safe stop if none comes in time.

#include <optional>

#include "core/collision/scene_clearance.h"
#include "core/validate/trajectory_collision_scan.h"
#include "procs/msgs/convert_robot_state.h"
#include "procs/planner/active_trajectory.h"

namespace topay::planner {

/// When and how far ahead the drifted robot is checked (ReplanTriggerOptions::drift_check;
/// config/planner/planner.yaml `triggers.drift_check_*`).
struct DriftCheckOptions {
  /// The drifted robot is checked while its drift exceeds any of these: base position (m),
  /// yaw (rad), any joint (rad). Below them the tracker's normal errors (1.5-2 cm RMS in the
  /// missions) would make every tight passage look like a collision. > 0.
  double position_m = 0.05;
  double yaw_rad = 0.05;
  double joint_rad = 0.05;
  /// How far ahead (s) of the state's time the drifted robot is checked: an error carried
  /// this long is taken as lasting (the tracker closes its normal errors within about a
  /// second). A collision found within it is nearer than a stopping trajectory lasts (3-4 s
  /// from speed), so the robot is stopped at once and replanned from the stop. > 0.
  double horizon_s = 2.0;
  /// On ROBOT_STATE (50 Hz), the check runs at most this often (s) while the drift exceeds
  /// the tolerances. > 0.
  double period_s = 0.1;
};

/// Whether `drift` exceeds any of the options' tolerances.
bool DriftWorthChecking(const Drift& drift, const DriftCheckOptions& options);

/// The first sample (every scan.sample_period_s from the state's time to horizon_s after it,
/// clamped to the trajectory) where the drifted robot's base or an arm sphere is within
/// scan.obstacle_margin_m of the checker's boxes; nullopt if none. t_s is along the trajectory.
/// Throws std::invalid_argument for bad options or a non-finite or non-positive horizon.
std::optional<PredictedCollision> FirstDriftedCollision(const DriftedRobot& robot, double horizon_s,
                                                        const SceneClearanceChecker& checker,
                                                        const TrajectoryCollisionScanOptions& scan);

}  // namespace topay::planner
