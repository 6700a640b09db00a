#pragma once

#include <string>

#include <Eigen/Geometry>

#include "core/collision/scene_clearance.h"
#include "core/robot/whole_body_rates.h"
#include "core/trajectory/trajectory_sample.h"
#include "core/validate/trajectory_validator.h"
#include "core/validate/validation_report.h"

namespace topay {

/// One TrajectoryValidator::Validate call's state (internal to core/validate): its
/// workspace, the task, and the report it fills sample by sample. Per-sample checks are
/// allocation-free unless they fail (failure messages are formatted once, for the first
/// failure only).
class ValidationRun {
 public:
  /// start_rates: a moving start's rates, checked at the first sample (null: a rest start,
  /// whose rates are not checked there). Must outlive this object.
  ValidationRun(const TrajectoryValidator& validator, const WholeBodyState& start,
                const Eigen::Isometry3d& X_WE_goal, ValidationReport* report,
                const WholeBodyRates* start_rates = nullptr);

  /// Every check of one sample in ValidationCheck order: finite values, the start (first
  /// sample), obstacle and self clearances, limits, and at the last sample rest and the
  /// end-effector pose. Returns true if any check failed. `sample` must have the model's
  /// joint count.
  bool CheckSample(double t_s, const TrajectorySample& sample, bool is_first, bool is_last);

  /// Records a failure (kept only if it is the first) and marks the current sample failed.
  void Fail(ValidationCheck check, double t_s, int index, double value, double threshold,
            const std::string& message, Limit limit = Limit::kNone, int box = -1);

  /// Fills the readable part names of the report's clearance records.
  void NameRecords();

 private:
  bool CheckFinite(double t_s, const TrajectorySample& sample);
  void CheckStart(double t_s, const WholeBodyState& state);
  /// A moving start: v, omega, qd within start_velocity_tolerance and a, beta, qdd within
  /// start_acceleration_tolerance of start_rates_.
  void CheckStartRates(double t_s, const TrajectorySample& sample);
  void CheckObstacles(double t_s);
  void CheckSelf(double t_s);
  void CheckLimits(double t_s, const TrajectorySample& sample);
  void CheckEnd(double t_s, const TrajectorySample& sample);
  bool HasFirstFailure() const { return report_->first_failure.check != ValidationCheck::kNone; }

  std::string SphereName(int sphere) const;
  std::string PairName(int pair) const;
  std::string JointName(int joint) const;

  const TrajectoryValidator& validator_;
  const TrajectoryValidatorOptions& options_;
  const RobotModel& model_;
  const WholeBodyState& start_;
  const WholeBodyRates* start_rates_;
  const Eigen::Isometry3d& X_WE_goal_;
  ValidationReport* report_;
  SceneClearanceWorkspace workspace_;
  bool sample_failed_ = false;
};

}  // namespace topay
