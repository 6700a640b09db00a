#pragma once

#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/trajectory/trajectory_sample.h"

namespace topay {

/// The arc length-yaw trajectory as a SampledTrajectory: each sampler owns a sample sized by
/// ArcYawTrajectory::MakePoint and copies Evaluate's result but the jerk into the caller's
/// (sized by MakeTrajectorySample; allocation-free per sample). `trajectory` is held by reference: it must outlive the
/// result and every sampler made from it, and must not be updated while they are in use.
/// Throws std::invalid_argument if the trajectory has not been updated (no MINCO solve yet).
SampledTrajectory SampleArcYaw(const ArcYawTrajectory& trajectory);

}  // namespace topay
