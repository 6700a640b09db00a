#pragma once
// poly_trajectory_t <-> the MINCO arc length-yaw trajectory (core/trajectory).

#include <cstdint>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "core/trajectory/arc_yaw_trajectory.h"
#include "topay/poly_trajectory_t.hpp"

namespace topay::msgs {

/// The polynomial form of an arc length-yaw trajectory as it travels: MINCO's coefficients
/// (6M x D, row 6j + k = coefficient of t^k of piece j, columns [s, yaw, q1..qN]) and piece
/// durations, with the start position p0_W = (x0, y0) from which x, y are integrated.
struct PolyTrajectory {
  std::int64_t utime = 0;          ///< publication time, us since the Unix epoch
  std::int64_t trajectory_id = 0;
  std::int64_t goal_id = 0;
  std::int64_t start_utime = 0;    ///< when piece 0 starts, us since the Unix epoch
  Eigen::Vector2d p0_W_m = Eigen::Vector2d::Zero();  ///< base position at the start, m
  double yaw0_rad = 0.0;           ///< yaw at the start (check value), rad
  Eigen::VectorXd durations_s;     ///< M piece durations, s
  Eigen::MatrixXd coefficients;    ///< 6M x (2 + N), MincoS3 layout

  int num_pieces() const { return static_cast<int>(durations_s.size()); }
  int num_joints() const { return static_cast<int>(coefficients.cols()) - 2; }
  /// The value of every dimension [s, yaw, q] at global time t_s (clamped to the duration).
  Eigen::VectorXd Evaluate(double t_s) const;
};

/// The polynomial form of a solved ArcYawTrajectory; its start point is p0_W_m and the yaw of
/// its first piece at t = 0.
PolyTrajectory FromArcYaw(const ArcYawTrajectory& trajectory, const Eigen::Vector2d& p0_W_m);

poly_trajectory_t ToMessage(const PolyTrajectory& trajectory);

/// nullopt with *error naming the field if counts disagree (num_coeffs, durations), a
/// duration is not finite and positive, or a coefficient is not finite.
std::optional<PolyTrajectory> FromMessage(const poly_trajectory_t& msg, std::string* error);

}  // namespace topay::msgs
