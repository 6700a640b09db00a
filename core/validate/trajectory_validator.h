#pragma once

#include <stop_token>

#include <Eigen/Geometry>

#include "core/collision/scene_clearance.h"
#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/self_collision.h"
#include "core/robot/moving_state.h"
#include "core/robot/whole_body_state.h"
#include "core/trajectory/trajectory_sample.h"
#include "core/validate/validation_report.h"

namespace topay {

/// Options of TrajectoryValidator: 10 ms samples, 1 % rate tolerance, 0.01 m / 0.02 rad at the end.
struct TrajectoryValidatorOptions {
  /// Samples at t = 0, period, 2 period, ... and always at the exact end time.
  double sample_period_s = 0.01;
  /// Rate limits (v, omega, coupled v-omega, a, beta, qd, qdd) pass while
  /// value / limit <= 1 + limit_tolerance (1 %).
  double limit_tolerance = 0.01;
  /// Joint positions are hard limits (URDF): q in [q_min - tol, q_max + tol], tol only
  /// absorbing round-off.
  double joint_position_tolerance_rad = 1e-9;
  /// End-effector pose at the end vs the goal: |p_end - p_goal| and angle(R_goal^T R_end).
  double ee_position_tolerance_m = 0.01;
  double ee_orientation_tolerance_rad = 0.02;
  /// Exact clearances must exceed these (SceneClearance::IsCollisionFree): obstacles (base
  /// cylinder, spheres vs boxes) and self (sphere pairs, arm above the chassis top).
  double obstacle_margin_m = 0.0;
  double self_margin_m = 0.0;
  /// The state at t = 0 must match the task's start: base position within 1 mm, yaw (modulo
  /// 2 pi) and every joint within 1 mrad.
  double start_position_tolerance_m = 1e-3;
  double start_angle_tolerance_rad = 1e-3;
  /// A moving start (Validate with a MovingState, issue 18): at t = 0 the trajectory's v,
  /// omega and every qd (m/s, rad/s) within start_velocity_tolerance of the start's rates,
  /// a, beta and every qdd (m/s^2, rad/s^2) within start_acceleration_tolerance. The arc
  /// length-yaw head imposes them exactly (round-off ~1e-9), so 1e-3 only absorbs sampling
  /// round-off. A rest start's rates are not checked (as before).
  double start_velocity_tolerance = 1e-3;
  double start_acceleration_tolerance = 1e-3;
  /// At the end the robot must be at rest (paper eqs. (18)-(20)): |v| (m/s), |omega| and every
  /// |qd| (rad/s) at most this.
  double end_rest_tolerance = 1e-3;
  /// Longer (or non-finite, or <= 0) durations fail as bad input: a guard against runaway
  /// sample counts (600 s = 60001 samples, a few seconds of checking).
  double max_duration_s = 600.0;
  /// Stop at the first failing sample (faster rejection). The report's minima and worst
  /// ratio then cover only the samples up to it. Default: scan the whole trajectory.
  bool stop_at_first_failure = false;
};

/// Throws std::invalid_argument naming the first option out of range and its value (the
/// TrajectoryValidator constructor calls it; the planner YAML loader too).
void CheckTrajectoryValidatorOptions(const TrajectoryValidatorOptions& options);

/// The independent validator used for every reported success: samples a trajectory every
/// sample_period_s and checks, against the exact scene geometry (boxes, no distance field),
/// the whole collision model (base cylinder over its height, every arm sphere), self
/// collision (sphere pairs and the arm above the chassis), the joint position limits, every
/// rate limit with a 1 % tolerance including the coupled v-omega one (eq. (9)), the start
/// state, rest at the end and the end-effector pose at the end. A trajectory that fails it
/// is a failure, whatever the optimizer said.
///
/// The base limits are the caller's (the benchmark uses omega_max 1.25, the robot 0.9); the
/// joint limits are the model's. The scene is copied; the Kinematics (and its model) must
/// outlive this object. Not copyable (the checker refers to the copy of the scene).
class TrajectoryValidator {
 public:
  /// Throws std::invalid_argument naming the field for a bad option, base limit or model
  /// joint limit.
  TrajectoryValidator(const Kinematics& kinematics, const Scene& scene,
                      const BaseLimits& base_limits,
                      const TrajectoryValidatorOptions& options = {});
  TrajectoryValidator(const TrajectoryValidator&) = delete;
  TrajectoryValidator& operator=(const TrajectoryValidator&) = delete;

  /// Validates `trajectory` for a task from `start` to the end-effector goal X_WE_goal.
  /// Never throws for bad input (wrong sizes, NaN, a throwing sampler): it is a failure in
  /// the report. Thread-safe: each call has its own workspace and sampler.
  /// `stop` (e.g. the plan's time limit) is polled before every sample; if it ends the check
  /// early, the report says so (stopped, and a kStopped failure unless an earlier sample
  /// failed) and is never ok: a trajectory checked in part is not validated. A sample costs
  /// the exact clearance queries (SceneClearanceChecker: the boxes near the robot), so the
  /// check ends within about one sample of the stop.
  ValidationReport Validate(const SampledTrajectory& trajectory, const WholeBodyState& start,
                            const Eigen::Isometry3d& X_WE_goal, std::stop_token stop = {}) const;

  /// Validates a trajectory from a moving start (issue 18): as above, and at t = 0 also the
  /// rates v, omega, a, beta, qd, qdd against start.rates (start_velocity_tolerance,
  /// start_acceleration_tolerance); a failure there is a kStart failure naming the rate.
  /// Rates whose joint vectors are neither empty nor N long, or not finite, are kInput.
  ValidationReport Validate(const SampledTrajectory& trajectory, const MovingState& start,
                            const Eigen::Isometry3d& X_WE_goal, std::stop_token stop = {}) const;

  const TrajectoryValidatorOptions& options() const { return options_; }
  const BaseLimits& base_limits() const { return base_limits_; }
  const Kinematics& kinematics() const { return kinematics_; }
  const Scene& scene() const { return scene_; }
  const SceneClearanceChecker& checker() const { return checker_; }
  const SelfCollision& self_collision() const { return self_collision_; }

 private:
  ValidationReport Run(const SampledTrajectory& trajectory, const WholeBodyState& start,
                       const WholeBodyRates* start_rates, const Eigen::Isometry3d& X_WE_goal,
                       std::stop_token stop) const;

  const Kinematics& kinematics_;
  Scene scene_;  // before checker_, which refers to it
  BaseLimits base_limits_;
  TrajectoryValidatorOptions options_;
  SceneClearanceChecker checker_;
  SelfCollision self_collision_;
};

}  // namespace topay
