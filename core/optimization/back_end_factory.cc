#include "core/optimization/back_end_factory.h"

namespace topay {

FlatnessOptimizerOptions FlatnessOptionsFrom(const TrajectoryOptimizerOptions& options) {
  FlatnessOptimizerOptions flatness;
  static_cast<BackEndOptions&>(flatness) = options;  // the shared part, as a whole
  flatness.objective.jerk_weights = options.objective.jerk_weights;
  flatness.objective.time_weight = options.objective.time_weight;
  flatness.objective.penalties = options.objective.penalties;
  flatness.check_period_s = options.feasibility.sample_period_s;
  return flatness;
}

std::unique_ptr<TrajectoryBackEnd> MakeTrajectoryBackEnd(const Kinematics& kinematics,
                                                         const SignedDistanceField2& base_field,
                                                         const SignedDistanceField3& arm_field,
                                                         const TrajectoryOptimizerOptions& options) {
  switch (options.parameterisation) {
    case TrajectoryParameterisation::kFlatness:
      CheckTrajectoryOptimizerOptions(options);  // what the planner's options promise
      return std::make_unique<FlatnessOptimizer>(kinematics, base_field, arm_field,
                                                 FlatnessOptionsFrom(options));
    case TrajectoryParameterisation::kArcLengthYaw:
      break;
  }
  return std::make_unique<TrajectoryOptimizer>(kinematics, base_field, arm_field, options);
}

}  // namespace topay
