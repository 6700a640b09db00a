#pragma once
// The check the planner process runs after every map update: does the rest of the trajectory
// the robot is on still clear the (new) obstacles? Exact geometry (SceneClearanceChecker on
// the map's voxel boxes), sampled densely in time; obstacles only (self collision and limits
// were validated when the trajectory was planned and do not change with the map).

#include <optional>

#include "core/collision/scene_clearance.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

/// Options of FirstPredictedCollision.
struct TrajectoryCollisionScanOptions {
  /// Sample spacing (s). 0.02 s: 2 cm at 1 m/s, under half the map's 5 cm voxel, and about
  /// 0.03 rad of arm motion at the joints' 1.5 rad/s. Must be finite and > 0.
  double sample_period_s = 0.02;
  /// A sample collides when its base or an arm sphere is nearer than this (m) to a box; 0:
  /// only contact (the validator's default margin). Must be finite and >= 0.
  double obstacle_margin_m = 0.0;
};

/// The first sampled collision.
struct PredictedCollision {
  double t_s = 0.0;          ///< Time along the trajectory (from its start), s.
  SceneClearance clearance;  ///< Obstacle parts at that sample (base_m, spheres_m).
};

/// Samples `trajectory` at t_from_s, t_from_s + period, ... and at t_to_s (both clamped to
/// [0, duration]) and returns the first sample whose obstacle clearance is at most the margin,
/// or nullopt if none. Cost: one kinematics update and the boxes near the robot per sample.
/// Throws std::invalid_argument for bad options or non-finite times.
std::optional<PredictedCollision> FirstPredictedCollision(
    const ArcYawTrajectory& trajectory, double t_from_s, double t_to_s,
    const SceneClearanceChecker& checker, const TrajectoryCollisionScanOptions& options = {});

/// The same scan over any motion of the robot (e.g. the robot carried along a trajectory with
/// its tracking error): `motion` sampled at t_begin_s, + period, ... and at t_end_s (no
/// clamping: the caller's times), each sample written into `point` (made by the trajectory's
/// MakePoint). Throws std::invalid_argument for bad options or non-finite times.
std::optional<PredictedCollision> FirstPredictedCollisionOf(const TrajectorySampler& motion, TrajectorySample point,
                                                            double t_begin_s, double t_end_s,
                                                            const SceneClearanceChecker& checker,
                                                            const TrajectoryCollisionScanOptions& options = {});

}  // namespace topay
