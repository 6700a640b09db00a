#pragma once
// The tracker's reference on an arc length-yaw trajectory: what the tracker process and the
// planner's prediction of the tracked robot (TrackedRobotPredictor) sample.

#include <cstdint>
#include <memory>

#include "core/control/nmpc_tracker.h"
#include "core/trajectory/arc_yaw_trajectory.h"

namespace topay {

/// A TrackerReference on `trajectory` (shared by the sampler, which keeps its own full-size
/// scratch point: ArcYawTrajectory::Evaluate needs MakePoint's sizes, the tracker's samples have
/// no jerk). t = 0 of the trajectory is start_time_s on the tracker's clock.
TrackerReference MakeArcYawReference(std::shared_ptr<const ArcYawTrajectory> trajectory, std::int64_t trajectory_id,
                                     double start_time_s);

/// Copies what the NMPC reads from a full sample (everything but the jerk) into `to`
/// (allocation-free for equal joint counts).
void CopySampleWithoutJerk(const TrajectorySample& from, TrajectorySample* to);

}  // namespace topay
