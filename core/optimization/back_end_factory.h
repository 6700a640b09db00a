#pragma once

#include <memory>

#include "core/map/signed_distance_field2.h"
#include "core/map/signed_distance_field3.h"
#include "core/optimization/flatness_optimizer.h"
#include "core/optimization/trajectory_back_end.h"
#include "core/optimization/trajectory_optimizer.h"
#include "core/robot/kinematics.h"

namespace topay {

/// The flatness baseline's options from the planner's back-end options: the shared
/// BackEndOptions as they are, the jerk and time weights and penalty options of the
/// objective, and the feasibility check's sample period as its dense check's; its own
/// sampling (16 trapezoid panels per piece, dense at the stops) and minimum-speed defaults
/// stay.
FlatnessOptimizerOptions FlatnessOptionsFrom(const TrajectoryOptimizerOptions& options);

/// The back end options.parameterisation names: TrajectoryOptimizer (kArcLengthYaw) or
/// FlatnessOptimizer with FlatnessOptionsFrom(options) (kFlatness). The kinematics and the
/// fields must outlive it. Throws std::invalid_argument for options out of range.
std::unique_ptr<TrajectoryBackEnd> MakeTrajectoryBackEnd(const Kinematics& kinematics,
                                                         const SignedDistanceField2& base_field,
                                                         const SignedDistanceField3& arm_field,
                                                         const TrajectoryOptimizerOptions& options);

}  // namespace topay
