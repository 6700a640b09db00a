#pragma once

#include "core/trajectory/arc_yaw_trajectory.h"
#include "core/validate/trajectory_sample.h"

namespace topay {

/// The arc length-yaw trajectory as a SampledTrajectory: each sampler owns an ArcYawPoint and
/// copies ArcYawTrajectory::Evaluate's pose, v, omega, a, beta, q' and q'' into the sample
/// (allocation-free per sample). `trajectory` is held by reference: it must outlive the
/// result and every sampler made from it, and must not be updated while they are in use.
/// Throws std::invalid_argument if the trajectory has not been updated (no MINCO solve yet).
SampledTrajectory SampleArcYaw(const ArcYawTrajectory& trajectory);

}  // namespace topay
