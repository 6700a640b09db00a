#pragma once
// POINT_CLOUD -> the protective field's obstacle points (core/control/protective_field.h,
// docs/tracker.md): the message checked (msgs::CheckCloud: sizes, a finite proper pose, at most
// max_points), its points moved to W with the message's sensor pose X_WS, non-finite ones
// dropped, and the robot's own body removed at the robot's state at the scan's capture time
// (RobotStateHistory of the ROBOT_STATEs the tracker takes; RobotBodyFilter inflated by the
// field's self_margin_m). The LiDAR sees the arm and the chassis top: without this the robot
// would stop for itself.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/robot/kinematics.h"
#include "core/robot/robot_body_filter.h"
#include "core/robot/robot_model.h"
#include "core/robot/robot_state_history.h"
#include "core/robot/whole_body_state.h"
#include "procs/msgs/cloud_input.h"
#include "topay/point_cloud_t.hpp"

namespace topay::tracker {

class FieldScanIntake {
 public:
  /// Throws std::invalid_argument for a negative or non-finite self_margin_m.
  FieldScanIntake(const RobotModel& model, double self_margin_m);
  FieldScanIntake(const FieldScanIntake&) = delete;
  FieldScanIntake& operator=(const FieldScanIntake&) = delete;

  /// A robot state the tracker took (its time, us): the history the self filter looks up.
  void AddState(std::int64_t utime, const WholeBodyState& state);

  /// The obstacle points of `msg` in W into *p_WP (cleared first; capacity reused), or why the
  /// scan cannot be used: a malformed message (the field and what is wrong), a joint count
  /// other than the model's, or no robot state within the history's gap of its capture time.
  std::optional<std::string> Take(const point_cloud_t& msg, std::vector<Eigen::Vector3f>* p_WP);

  /// Points the last Take dropped as the robot's own.
  int last_self_points() const { return last_self_points_; }

 private:
  RobotModel model_;  // before kinematics_, which keeps a reference to it
  Kinematics kinematics_;
  KinematicsCache cache_;
  RobotBodyFilter body_;
  RobotStateHistory history_;
  msgs::CloudInputOptions input_options_;
  msgs::CheckedCloud cloud_;
  int last_self_points_ = 0;
};

}  // namespace topay::tracker
