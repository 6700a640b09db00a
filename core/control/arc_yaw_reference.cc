#include "core/control/arc_yaw_reference.h"

#include <utility>

namespace topay {

void CopySampleWithoutJerk(const TrajectorySample& from, TrajectorySample* to) {
  to->t_s = from.t_s;
  to->state.x_m = from.state.x_m;
  to->state.y_m = from.state.y_m;
  to->state.yaw_rad = from.state.yaw_rad;
  to->state.q_rad = from.state.q_rad;
  to->s_m = from.s_m;
  to->v_mps = from.v_mps;
  to->omega_radps = from.omega_radps;
  to->a_mps2 = from.a_mps2;
  to->beta_radps2 = from.beta_radps2;
  to->qd_radps = from.qd_radps;
  to->qdd_radps2 = from.qdd_radps2;
}

TrackerReference MakeArcYawReference(std::shared_ptr<const ArcYawTrajectory> trajectory, std::int64_t trajectory_id,
                                     double start_time_s) {
  TrackerReference reference;
  reference.trajectory_id = trajectory_id;
  reference.start_time_s = start_time_s;
  reference.duration_s = trajectory->duration_s();
  auto point = std::make_shared<TrajectorySample>(trajectory->MakePoint());
  reference.sampler = [trajectory = std::move(trajectory), point](double t_s, TrajectorySample* out) {
    trajectory->Evaluate(t_s, point.get());
    CopySampleWithoutJerk(*point, out);
  };
  return reference;
}

}  // namespace topay
