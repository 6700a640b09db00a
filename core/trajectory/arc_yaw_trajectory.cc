#include "core/trajectory/arc_yaw_trajectory.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/trajectory/quintic_basis.h"

namespace topay {

ArcYawTrajectory::ArcYawTrajectory(int num_joints, int num_pieces, const Options& options)
    : num_joints_(num_joints),
      minco_(num_joints + 2, num_pieces),
      positions_(num_pieces, options.integrator) {
  if (num_joints < 0) {
    throw std::invalid_argument("ArcYawTrajectory: negative joint count " +
                                std::to_string(num_joints));
  }
}

void ArcYawTrajectory::Update(const Eigen::Vector2d& p0_W,
                              const Eigen::Ref<const Eigen::MatrixXd>& head,
                              const Eigen::Ref<const Eigen::MatrixXd>& tail,
                              const Eigen::Ref<const Eigen::MatrixXd>& waypoints,
                              const Eigen::Ref<const Eigen::VectorXd>& durations_s) {
  minco_.Solve(head, tail, waypoints, durations_s);
  positions_.Integrate(p0_W, minco_.coefficients(), minco_.durations());
}

TrajectorySample ArcYawTrajectory::MakePoint() const {
  TrajectorySample point = MakeTrajectorySample(num_joints_);
  point.jerk.setZero(num_dims());
  return point;
}

void ArcYawTrajectory::Evaluate(double t_s, TrajectorySample* point) const {
  if (std::isnan(t_s)) throw std::invalid_argument("ArcYawTrajectory::Evaluate: t is NaN");
  if (!minco_.solved()) throw std::invalid_argument("ArcYawTrajectory::Evaluate: no Update yet");
  if (point->state.q_rad.size() != num_joints_ || point->jerk.size() != num_dims() ||
      point->qd_radps.size() != num_joints_ || point->qdd_radps2.size() != num_joints_) {
    throw std::invalid_argument("ArcYawTrajectory::Evaluate: point not sized (use MakePoint)");
  }
  double tau = 0.0;
  const int piece = minco_.LocatePiece(t_s, &tau);
  const auto c = minco_.coefficients().middleRows<kQuinticCoefficients>(
      kQuinticCoefficients * piece);
  const auto joints = c.rightCols(num_joints_);
  const auto beta0 = QuinticBasis(tau, 0);
  const auto beta1 = QuinticBasis(tau, 1);
  const auto beta2 = QuinticBasis(tau, 2);
  point->t_s = minco_.total_duration() > 0.0 ? std::clamp(t_s, 0.0, minco_.total_duration())
                                             : 0.0;
  const Eigen::Vector2d p_W = positions_.Interpolate(piece, tau);
  point->state.x_m = p_W.x();
  point->state.y_m = p_W.y();
  point->s_m = c.col(0).dot(beta0);
  point->state.yaw_rad = c.col(1).dot(beta0);
  point->v_mps = c.col(0).dot(beta1);
  point->omega_radps = c.col(1).dot(beta1);
  point->a_mps2 = c.col(0).dot(beta2);
  point->beta_radps2 = c.col(1).dot(beta2);
  point->jerk.noalias() = c.transpose() * QuinticBasis(tau, 3);
  point->state.q_rad.noalias() = joints.transpose() * beta0;
  point->qd_radps.noalias() = joints.transpose() * beta1;
  point->qdd_radps2.noalias() = joints.transpose() * beta2;
}

const Eigen::Isometry3d& ArcYawTrajectory::EndEffectorPose(double t_s,
                                                           const Kinematics& kinematics,
                                                           KinematicsCache* cache,
                                                           TrajectorySample* point) const {
  Evaluate(t_s, point);
  kinematics.Update(point->state, cache);
  return cache->X_WE;
}

Eigen::Vector2d ArcYawTrajectory::PropagateGradient(const Eigen::Ref<const Eigen::Matrix2Xd>& dC_dp,
                                                    Eigen::Ref<Eigen::MatrixXd> dC_dc,
                                                    Eigen::Ref<Eigen::VectorXd> dC_dT,
                                                    MincoGradient* gradient) {
  const Eigen::Vector2d dC_dp0 = positions_.AddGradient(dC_dp, dC_dc, dC_dT);
  minco_.PropagateGradient(dC_dc, dC_dT, gradient);
  return dC_dp0;
}

}  // namespace topay
