#include "core/control/reference_horizon.h"

#include <algorithm>

namespace topay {

ReferenceHorizon ReferenceHorizon::Zero(int steps, int num_joints) {
  ReferenceHorizon horizon;
  horizon.pose.setZero(3, steps + 1);
  horizon.q_rad.setZero(num_joints, steps + 1);
  horizon.u_base.setZero(2, steps);
  horizon.qd_radps.setZero(num_joints, steps);
  return horizon;
}

void SampleReferenceHorizon(const TrajectorySampler& sampler, double duration_s, double t0_s,
                            double step_s, TrajectorySample* scratch, ReferenceHorizon* horizon) {
  const int steps = horizon->steps();
  for (int k = 0; k <= steps; ++k) {
    const double t_s = t0_s + k * step_s;
    const bool past_end = t_s > duration_s;
    sampler(std::clamp(t_s, 0.0, duration_s), scratch);
    horizon->pose.col(k) << scratch->state.x_m, scratch->state.y_m, scratch->state.yaw_rad;
    horizon->q_rad.col(k) = scratch->state.q_rad;
    if (k == steps) break;
    // Feed-forward: the trajectory's own rates, zero once it has ended (held at rest).
    horizon->u_base(0, k) = past_end ? 0.0 : scratch->v_mps;
    horizon->u_base(1, k) = past_end ? 0.0 : scratch->omega_radps;
    if (past_end) {
      horizon->qd_radps.col(k).setZero();
    } else {
      horizon->qd_radps.col(k) = scratch->qd_radps;
    }
  }
}

void HoldArmReference(const TrajectorySampler& sampler, double duration_s, double arm_t_s,
                      TrajectorySample* scratch, ReferenceHorizon* horizon) {
  sampler(std::clamp(arm_t_s, 0.0, duration_s), scratch);
  horizon->q_rad.colwise() = scratch->state.q_rad;
  horizon->qd_radps.setZero();
}

}  // namespace topay
