#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay {

using Vector6d = Eigen::Matrix<double, 6, 1>;

/// The 6-D residual of the end-effector constraint FK(s_f) = p_e (TopAY paper eq. (7)) for a
/// pose X_WE against the goal X_WG:
///   r = [p_WE - p_WG;  phi],  phi = Log(R_WE R_WG^T),
/// position error (m) first, then the orientation error as a rotation vector (rad) expressed
/// in W (|phi| is the angle between the two frames).
Vector6d PoseResidual(const Eigen::Isometry3d& X_WE, const Eigen::Isometry3d& X_WG);

/// The inverse of SO(3)'s left Jacobian at phi (Barfoot, "State Estimation for Robotics",
/// eq. 7.77):
///   J_l^{-1}(phi) = I - [phi]x / 2 + c(theta) [phi]x^2,
///   c(theta) = 1 / theta^2 - (1 + cos theta) / (2 theta sin theta),
/// theta = |phi|; c's series 1/12 + theta^2 / 720 below theta = 1e-4.
/// Singular at theta = pi (the log map's cut), where the coefficient grows without bound.
Eigen::Matrix3d InverseLeftJacobianSO3(const Eigen::Vector3d& phi);

/// dr/dz (6 x (3 + N)) from the end effector's spatial Jacobian J_WE (Kinematics::
/// EndEffectorJacobian: rows 0-2 angular velocity w_WE in W, rows 3-5 velocity of E's origin
/// in W) at the residual r: rows 0-2 = J_WE rows 3-5; rows 3-5 = J_l^{-1}(phi) J_WE rows 0-2,
/// since a rotation of E by w dt in W turns R_WE R_WG^T into Exp(w dt) R_WE R_WG^T, whose log
/// moves by J_l^{-1}(phi) w dt. Allocation-free; dr_dz must be 6 x J_WE.cols().
void PoseResidualJacobian(const Vector6d& residual, const Eigen::Ref<const Eigen::MatrixXd>& J_WE,
                          Eigen::Ref<Eigen::MatrixXd> dr_dz);

}  // namespace topay
