#include "core/trajectory/arc_yaw_state_at.h"

namespace topay {

MovingState ArcYawStateAt(const ArcYawTrajectory& trajectory, double t_s) {
  TrajectorySample sample = trajectory.MakePoint();
  trajectory.Evaluate(t_s, &sample);
  return MovingStateOf(sample);
}

MovingState MovingStateOf(const TrajectorySample& sample) {
  MovingState out;
  out.state = sample.state;
  out.rates.v_mps = sample.v_mps;
  out.rates.omega_radps = sample.omega_radps;
  out.rates.a_mps2 = sample.a_mps2;
  out.rates.beta_radps2 = sample.beta_radps2;
  out.rates.qd_radps = sample.qd_radps;
  out.rates.qdd_radps2 = sample.qdd_radps2;
  return out;
}

}  // namespace topay
