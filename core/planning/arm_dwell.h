#pragma once
// Time for the arm where the base barely moves (ours, finding 29). The arm's RRT* moves the
// joints only while the base goes from layer to layer (|dq_i| <= qd_max_i x the step's time),
// so a base sequence of a few centimetres or none at all (a robot stopped next to its goal,
// finishing with the arm alone) leaves the arm no time, or only the straight joint move. A
// sequence shorter than the arm needs ends with the base standing at its last pose for the
// rest: layers at the same pose, the arm moving between them. The optimizer's warm start
// times such a run by the joints' travel (MakeWarmStart: "moving only the arm").

#include <Eigen/Core>

#include "core/planning/discrete_se2.h"

namespace topay {

/// Options of AddArmDwell, Ceres style.
struct ArmDwellOptions {
  /// The sequence must last at least travel_time_factor x the arm's fastest travel time
  /// (max_i |q_goal,i - q_start,i| / qd_max_i) + min_time_s (s); room for the arm to go
  /// round an obstacle rather than straight. 0 and 0: never a dwell.
  double travel_time_factor = 1.5;
  double min_time_s = 1.0;
  /// The standing layers are at most this far apart in time (s).
  double step_s = 0.5;
};

/// Throws std::invalid_argument naming the first option out of range (factor and min_time_s
/// finite and >= 0, step_s finite and > 0).
void CheckArmDwellOptions(const ArmDwellOptions& options);

/// The time (s) the sequence must last for the arm (ArmDwellOptions): factor x
/// max_i |q_goal,i - q_start,i| / qd_max_i + min_time_s. Sizes must agree, qd_max > 0.
double ArmTimeNeeded(const Eigen::VectorXd& q_start_rad, const Eigen::VectorXd& q_goal_rad,
                     const Eigen::VectorXd& qd_max_radps, const ArmDwellOptions& options);

/// Appends to a non-empty `path` standing layers (its last layer's pose, turn_in_place, time
/// steps of at most step_s, equal) until it lasts ArmTimeNeeded. Returns the time added (s):
/// 0 when it lasts that long already.
double AddArmDwell(const Eigen::VectorXd& q_start_rad, const Eigen::VectorXd& q_goal_rad,
                   const Eigen::VectorXd& qd_max_radps, const ArmDwellOptions& options,
                   DiscreteSE2Path* path);

}  // namespace topay
