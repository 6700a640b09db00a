#pragma once

#include <Eigen/Core>

#include "core/trajectory/minco_s3.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// What defines a flatness-baseline trajectory (FlatnessObjective): one MINCO s = 3 trajectory
/// in D = 2 + N dimensions (x, y, q_1..q_N), plus the headings at the two rest points.
struct FlatnessTrajectoryData {
  Eigen::MatrixXd head;       ///< D x 3: position, velocity (0), acceleration.
  Eigen::MatrixXd tail;       ///< D x 3.
  Eigen::MatrixXd waypoints;  ///< D x (M - 1).
  Eigen::VectorXd durations_s;  ///< M.
  double start_yaw_rad = 0.0;   ///< Heading at t = 0 (where v = 0).
  double end_yaw_rad = 0.0;     ///< Heading at the end (where v = 0).

  int num_pieces() const { return static_cast<int>(durations_s.size()); }
  int num_joints() const { return static_cast<int>(head.rows()) - 2; }
  double duration_s() const { return durations_s.sum(); }
};

/// The flatness trajectory evaluated at any time: x, y and q from MINCO, yaw and the base
/// rates from the flat outputs (flat_yaw.h). At a rest point (speed below 1e-9 m/s: the two
/// ends) yaw is the stored rest heading, v = omega = beta = 0 and a = +-|p''| (the heading
/// is defined there by continuity only, a documented weakness of the parameterisation).
/// Construction solves MINCO (allocates); Evaluate does not allocate.
class FlatnessTrajectory {
 public:
  /// Throws std::invalid_argument for inconsistent sizes, non-finite values or durations <= 0.
  explicit FlatnessTrajectory(const FlatnessTrajectoryData& data);

  double duration_s() const { return minco_.total_duration(); }
  int num_joints() const { return data_.num_joints(); }
  const MincoS3& minco() const { return minco_; }

  /// Writes every field of *sample (sized for N joints) at t_s (clamped to [0, duration]).
  void Evaluate(double t_s, TrajectorySample* sample);

 private:
  FlatnessTrajectoryData data_;
  MincoS3 minco_;
  Eigen::VectorXd values_[4];
};

/// The flatness trajectory as the validator sees it (core/validate/trajectory_validator.h):
/// holds the data by value; each sampler owns its own FlatnessTrajectory.
SampledTrajectory SampleFlatness(const FlatnessTrajectoryData& data);

}  // namespace topay
