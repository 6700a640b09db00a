#pragma once
// topay-estimator's options (config/estimator/estimator.yaml): the filter's (EstimatorOptions,
// section `filter`) and the process's own: publish rate, input timeouts, clock skew, joints.

#include <string>

#include "core/estimation/estimator_options.h"

namespace topay::estimator {

struct EstimatorProcessOptions {
  std::string source;       ///< The file these came from ("" = defaults).
  EstimatorOptions filter;  ///< The EKF (core/estimation/estimator_options.h).
  /// ROBOT_STATE rate, Hz (the pose predicted to each publish time). > 0.
  double publish_rate_hz = 100.0;
  /// No ROBOT_STATE while the newest BASE_VELOCITY is older than this (s): the tracker then
  /// stops the robot on its own stale-state rule (0.1 s). > 0.
  double odometry_timeout_s = 0.1;
  /// No ROBOT_STATE while the newest JOINT_STATE is older than this (s). > 0.
  double joints_timeout_s = 0.1;
  /// No ROBOT_STATE while the newest BASE_POSE taken is older than this (s): the longest dead
  /// reckoning allowed (docs/estimator.md, drift bound). > 0.
  double pose_timeout_s = 5.0;
  /// The gripper is unknown (NaN in ROBOT_STATE) while the newest GRIPPER_STATE is older than
  /// this (s) or none came. > 0.
  double gripper_timeout_s = 0.5;
  /// Inputs stamped more than this (s) after the process's clock are rejected (counted). >= 0.
  double max_future_s = 0.05;
  /// Joints JOINT_STATE must carry (the robot's arm: 7); 0 accepts any count. >= 0.
  int num_joints = 7;
  /// The fastest odometry believed: a BASE_VELOCITY with |v| (m/s) or |omega| (rad/s) above
  /// these is rejected (counted), not integrated (twice the robot's v_max 1.0 m/s and 4 x its
  /// omega_max 0.9 rad/s, as the consumers' continuity gate). > 0.
  double max_speed_mps = 2.0;
  double max_yaw_rate_radps = 4.0;
};

/// Loads options from YAML (every key optional). Throws ConfigError naming the file and the
/// dotted field for an unreadable file, an unknown (e.g. misspelt) key or a value out of range
/// (EstimatorOptions::Check's message for the `filter` section).
EstimatorProcessOptions LoadEstimatorProcessOptions(const std::string& path);

/// Throws std::invalid_argument naming the first process field out of range (not `filter`).
void CheckProcessOptions(const EstimatorProcessOptions& options);

}  // namespace topay::estimator
