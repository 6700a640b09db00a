#pragma once
// The base path of a TRAJECTORY message: its base positions every dt seconds, for the
// director's placements (route_box.h).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "topay/poly_trajectory_t.hpp"

namespace topay::director {

struct BasePath {
  std::int64_t trajectory_id = 0;
  std::int64_t start_utime = 0;        ///< The trajectory's time 0 (us).
  double dt_s = 0.0;                   ///< Sample i is at time i * dt_s (the last at the end).
  std::vector<Eigen::Vector2d> p_W_m;  ///< Base positions, in time order.

  /// The sample the robot is at `utime` by time (clamped to the path; nullopt before the
  /// trajectory's start).
  std::optional<std::size_t> IndexAt(std::int64_t utime) const;
};

/// Samples the message's trajectory (msgs::FromMessage, msgs::ToArcYaw with the planner's
/// rebuild settings) every dt_s; nullopt with *error if the message is not a valid trajectory.
std::optional<BasePath> SampleBasePath(const poly_trajectory_t& msg, double dt_s, std::string* error);

}  // namespace topay::director
