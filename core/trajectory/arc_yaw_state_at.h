#pragma once

#include "core/robot/moving_state.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

/// The whole-body state and rates of a solved trajectory at t_s (clamped to [0, duration]):
/// where a replanned trajectory must start to join it C2-continuously (issue 18). x, y, yaw,
/// q and v = s', omega = yaw', a = s'', beta = yaw'', qd, qdd (paper Sec. III-B, dims
/// [s, yaw, q]; x, y integrated by eqs. (1)-(2)). Throws std::invalid_argument for a NaN time
/// or a trajectory not yet updated (ArcYawTrajectory::Evaluate). Allocates.
MovingState ArcYawStateAt(const ArcYawTrajectory& trajectory, double t_s);

/// The state and rates of a trajectory sample (its jerk and arc length dropped).
MovingState MovingStateOf(const TrajectorySample& sample);

}  // namespace topay
