#include "core/control/unicycle_rollout.h"

#include <cmath>

namespace topay {

void RolloutUnicycle(const Eigen::Vector3d& x0, const Eigen::Ref<const Eigen::Matrix2Xd>& u,
                     double dt_s, Eigen::Matrix3Xd* states) {
  states->col(0) = x0;
  for (int k = 0; k < u.cols(); ++k) {
    const double theta = (*states)(2, k) + 0.5 * u(1, k) * dt_s;               // mid-step yaw
    (*states)(0, k + 1) = (*states)(0, k) + u(0, k) * dt_s * std::cos(theta);  // x_k+1
    (*states)(1, k + 1) = (*states)(1, k) + u(0, k) * dt_s * std::sin(theta);  // y_k+1
    (*states)(2, k + 1) = (*states)(2, k) + u(1, k) * dt_s;                    // yaw_k+1
  }
}

}  // namespace topay
