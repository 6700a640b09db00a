#pragma once
// Template body of RolloutJacobian (core/control/unicycle_rollout.h).

#include <cmath>

namespace topay {

template <typename Matrix>
void RolloutJacobian(const Eigen::Matrix3Xd& states, const Eigen::Ref<const Eigen::Matrix2Xd>& u,
                     double dt_s, Matrix* J) {
  const int steps = static_cast<int>(u.cols());
  J->setZero();
  for (int i = 0; i < steps; ++i) {
    const double theta = states(2, i) + 0.5 * u(1, i) * dt_s;  // mid-step yaw of step i
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    const double v = u(0, i);
    for (int j = i + 1; j <= steps; ++j) {
      const int row = 3 * (j - 1);
      (*J)(row + 0, 2 * i) = dt_s * c;                                        // dx_j/dv_i
      (*J)(row + 1, 2 * i) = dt_s * s;                                        // dy_j/dv_i
      (*J)(row + 0, 2 * i + 1) =
          -dt_s * (states(1, j) - states(1, i + 1)) - 0.5 * dt_s * dt_s * v * s;  // dx_j/domega_i
      (*J)(row + 1, 2 * i + 1) =
          dt_s * (states(0, j) - states(0, i + 1)) + 0.5 * dt_s * dt_s * v * c;   // dy_j/domega_i
      (*J)(row + 2, 2 * i + 1) = dt_s;                                        // dyaw_j/domega_i
    }
  }
}

}  // namespace topay
