#include "core/estimation/se2_motion.h"

#include <cmath>

#include "core/common/angles.h"

namespace topay {
namespace {

constexpr double kSeriesBelow = 1e-2;  // |dpsi| below which s1, c1 and their slopes are series

// s1(a) = sin(a) / a and c1(a) = (1 - cos a) / a: the arc's displacement in B per metre.
double S1(double a) {
  const double a2 = a * a;
  return std::abs(a) < kSeriesBelow ? 1.0 - a2 / 6.0 + a2 * a2 / 120.0 : std::sin(a) / a;
}
double C1(double a) {
  const double a2 = a * a;
  return std::abs(a) < kSeriesBelow ? a / 2.0 - a * a2 / 24.0 + a * a2 * a2 / 720.0 : (1.0 - std::cos(a)) / a;
}
// Their derivatives: s1'(a) = (a cos a - sin a) / a^2, c1'(a) = (a sin a - 1 + cos a) / a^2.
double S1Slope(double a) {
  const double a2 = a * a;
  return std::abs(a) < kSeriesBelow ? -a / 3.0 + a * a2 / 30.0 : (a * std::cos(a) - std::sin(a)) / a2;
}
double C1Slope(double a) {
  const double a2 = a * a;
  return std::abs(a) < kSeriesBelow ? 0.5 - a2 / 8.0 + a2 * a2 / 144.0 : (a * std::sin(a) - 1.0 + std::cos(a)) / a2;
}

// R(yaw) v: a vector of B expressed in W.
Eigen::Vector2d Rotate(double yaw_rad, const Eigen::Vector2d& v_B) {
  const double c = std::cos(yaw_rad), s = std::sin(yaw_rad);
  return {c * v_B.x() - s * v_B.y(), s * v_B.x() + c * v_B.y()};
}

}  // namespace

Eigen::Vector3d MoveAlongArc(const Eigen::Vector3d& X_WB, const OdometryIncrement& u) {
  const double d_m = u.v_mps * u.dt_s;          // distance along the arc
  const double dpsi_rad = u.omega_radps * u.dt_s;  // turn
  // p_B = d (s1, c1): the end of the arc in the frame B at its start.
  const Eigen::Vector2d p_W = Rotate(X_WB.z(), Eigen::Vector2d(d_m * S1(dpsi_rad), d_m * C1(dpsi_rad)));
  return {X_WB.x() + p_W.x(), X_WB.y() + p_W.y(), WrapAngle(X_WB.z() + dpsi_rad)};
}

Eigen::Matrix3d MotionJacobianState(const Eigen::Vector3d& X_WB, const OdometryIncrement& u) {
  const double d_m = u.v_mps * u.dt_s;
  const double dpsi_rad = u.omega_radps * u.dt_s;
  const Eigen::Vector2d p_W = Rotate(X_WB.z(), Eigen::Vector2d(d_m * S1(dpsi_rad), d_m * C1(dpsi_rad)));
  // d(R(yaw) p_B)/d yaw = R(yaw + pi/2) p_B = (-p_W.y, p_W.x).
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  F(0, 2) = -p_W.y();
  F(1, 2) = p_W.x();
  return F;
}

Eigen::Matrix<double, 3, 2> MotionJacobianIncrement(const Eigen::Vector3d& X_WB, const OdometryIncrement& u) {
  const double d_m = u.v_mps * u.dt_s;
  const double dpsi_rad = u.omega_radps * u.dt_s;
  Eigen::Matrix<double, 3, 2> G = Eigen::Matrix<double, 3, 2>::Zero();
  // d p_W / d d = R(yaw) (s1, c1); d p_W / d dpsi = R(yaw) d (s1', c1'); d yaw' / d dpsi = 1.
  G.block<2, 1>(0, 0) = Rotate(X_WB.z(), Eigen::Vector2d(S1(dpsi_rad), C1(dpsi_rad)));
  G.block<2, 1>(0, 1) = Rotate(X_WB.z(), Eigen::Vector2d(d_m * S1Slope(dpsi_rad), d_m * C1Slope(dpsi_rad)));
  G(2, 1) = 1.0;
  return G;
}

Eigen::Matrix3d MotionNoise(const Eigen::Vector3d& X_WB, const OdometryIncrement& u, const EstimatorOptions& o) {
  const double d_abs_m = std::abs(u.v_mps * u.dt_s);
  const double dpsi_abs_rad = std::abs(u.omega_radps * u.dt_s);
  // Noise of the increment, growing linearly with the motion (rate-independent random walks).
  const double var_d = o.translation_var_m2_per_m * d_abs_m;
  const double var_dpsi = o.rotation_var_rad2_per_rad * dpsi_abs_rad + o.rotation_var_rad2_per_m * d_abs_m;
  const Eigen::Matrix<double, 3, 2> G = MotionJacobianIncrement(X_WB, u);
  // Q = G diag(var_d, var_dpsi) G^T + diag(qxy, qxy, qyaw) dt.
  Eigen::Matrix3d Q = G * Eigen::Vector2d(var_d, var_dpsi).asDiagonal() * G.transpose();
  Q(0, 0) += o.diffusion_xy_m2_per_s * u.dt_s;
  Q(1, 1) += o.diffusion_xy_m2_per_s * u.dt_s;
  Q(2, 2) += o.diffusion_yaw_rad2_per_s * u.dt_s;
  return Q;
}

void PredictPose(const OdometryIncrement& u, const EstimatorOptions& options, Eigen::Vector3d* X_WB,
                 Eigen::Matrix3d* P_WB) {
  // Jacobians and noise at the prior mean, then the mean: x' = f(x, u), P' = F P F^T + Q.
  const Eigen::Matrix3d F = MotionJacobianState(*X_WB, u);
  const Eigen::Matrix3d Q = MotionNoise(*X_WB, u, options);
  *P_WB = F * *P_WB * F.transpose() + Q;
  *P_WB = 0.5 * (*P_WB + P_WB->transpose());  // keep it exactly symmetric
  *X_WB = MoveAlongArc(*X_WB, u);
}

}  // namespace topay
