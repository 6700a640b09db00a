#include "core/optimization/pose_residual.h"

#include <cmath>
#include <numbers>

namespace topay {
namespace {

Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

Vector6d PoseResidual(const Eigen::Isometry3d& X_WE, const Eigen::Isometry3d& X_WG) {
  Vector6d r;
  // Eq. (7): position part.
  r.head<3>() = X_WE.translation() - X_WG.translation();
  // Eq. (7): orientation part, Log(R_WE R_WG^T) through a unit quaternion (atan2-based angle,
  // accurate for small and large angles).
  const Eigen::Quaterniond q_err(X_WE.linear() * X_WG.linear().transpose());
  const Eigen::AngleAxisd angle_axis(q_err.normalized());
  double angle = angle_axis.angle();
  Eigen::Vector3d axis = angle_axis.axis();
  if (angle > std::numbers::pi) {  // shortest rotation: angle in [0, pi]
    angle = 2.0 * std::numbers::pi - angle;
    axis = -axis;
  }
  r.tail<3>() = angle * axis;
  return r;
}

Eigen::Matrix3d InverseLeftJacobianSO3(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d phi_x = Skew(phi);
  // Barfoot eq. 7.77 with the series of the last coefficient near 0.
  const double coefficient =
      theta < 1e-4 ? 1.0 / 12.0 + theta * theta / 720.0
                   : 1.0 / (theta * theta) -
                         (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
  return Eigen::Matrix3d::Identity() - 0.5 * phi_x + coefficient * phi_x * phi_x;
}

void PoseResidualJacobian(const Vector6d& residual, const Eigen::Ref<const Eigen::MatrixXd>& J_WE,
                          Eigen::Ref<Eigen::MatrixXd> dr_dz) {
  dr_dz.topRows<3>() = J_WE.bottomRows<3>();
  dr_dz.bottomRows<3>().noalias() =
      InverseLeftJacobianSO3(residual.tail<3>()) * J_WE.topRows<3>();
}

}  // namespace topay
