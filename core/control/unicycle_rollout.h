#pragma once

#include <Eigen/Core>

namespace topay {

/// The NMPC's base model: a unicycle (x, y, yaw) driven by (v, omega) held over each step dt,
/// integrated with the mid-step yaw (second order, exact for a straight step):
///   yaw_k+1 = yaw_k + omega_k dt
///   theta_k = yaw_k + omega_k dt / 2
///   x_k+1   = x_k + v_k dt cos(theta_k),   y_k+1 = y_k + v_k dt sin(theta_k)
/// states: 3 x (N + 1), column 0 = x0; u: 2 x N. Allocation-free into a sized *states.
void RolloutUnicycle(const Eigen::Vector3d& x0, const Eigen::Ref<const Eigen::Matrix2Xd>& u,
                     double dt_s, Eigen::Matrix3Xd* states);

/// d(states 1..N) / d(u): J is 3N x 2N, row 3 (j - 1) + r = component r of state j, column
/// 2 i + c = input c of step i (row-major or column-major: any Eigen dense matrix). With
/// theta_i as above and sums of the increments collapsing to state differences:
///   d yaw_j / d omega_i = dt                                         (i < j)
///   d x_j / d v_i = dt cos(theta_i),  d y_j / d v_i = dt sin(theta_i)  (i < j)
///   d x_j / d omega_i = -dt (y_j - y_i+1) - dt^2 / 2 v_i sin(theta_i)
///   d y_j / d omega_i =  dt (x_j - x_i+1) + dt^2 / 2 v_i cos(theta_i)
/// Zero for i >= j. J must be sized 3N x 2N; every entry is written.
template <typename Matrix>
void RolloutJacobian(const Eigen::Matrix3Xd& states, const Eigen::Ref<const Eigen::Matrix2Xd>& u,
                     double dt_s, Matrix* J);

}  // namespace topay

#include "core/control/unicycle_rollout_impl.h"
