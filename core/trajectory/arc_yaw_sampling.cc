#include "core/trajectory/arc_yaw_sampling.h"

#include <memory>
#include <stdexcept>

namespace topay {

SampledTrajectory SampleArcYaw(const ArcYawTrajectory& trajectory) {
  if (!trajectory.minco().solved()) {
    throw std::invalid_argument("SampleArcYaw: the trajectory has no Update yet");
  }
  SampledTrajectory sampled;
  sampled.duration_s = trajectory.duration_s();
  sampled.num_joints = trajectory.num_joints();
  sampled.make_sampler = [&trajectory]() -> TrajectorySampler {
    // Shared by the copies of this one sampler only (std::function copies its target).
    auto point = std::make_shared<TrajectorySample>(trajectory.MakePoint());
    return [&trajectory, point](double t_s, TrajectorySample* sample) {
      trajectory.Evaluate(t_s, point.get());
      // Every field but the jerk (the caller's sample need not be sized for it).
      sample->t_s = point->t_s;
      sample->state.x_m = point->state.x_m;
      sample->state.y_m = point->state.y_m;
      sample->state.yaw_rad = point->state.yaw_rad;
      sample->state.q_rad = point->state.q_rad;  // same size: no allocation
      sample->s_m = point->s_m;
      sample->v_mps = point->v_mps;
      sample->omega_radps = point->omega_radps;
      sample->a_mps2 = point->a_mps2;
      sample->beta_radps2 = point->beta_radps2;
      sample->qd_radps = point->qd_radps;
      sample->qdd_radps2 = point->qdd_radps2;
    };
  };
  return sampled;
}

}  // namespace topay
