#include "core/optimization/end_effector_alm_term.h"

namespace topay {

EndEffectorAlmTerm::EndEffectorAlmTerm(const Kinematics& kinematics,
                                       const Eigen::Isometry3d& X_WE_goal)
    : kinematics_(kinematics), X_WE_goal_(X_WE_goal), cache_(kinematics.MakeCache()) {
  J_WE_.setZero(6, kinematics.num_states());
  dr_dz_.setZero(6, kinematics.num_states());
  dL_dz_.setZero(kinematics.num_states());
}

double EndEffectorAlmTerm::Evaluate(const WholeBodyState& state, const Vector6d& lambda,
                                    double rho, bool enabled, bool with_gradient) {
  kinematics_.Update(state, &cache_);
  residual_ = PoseResidual(cache_.X_WE, X_WE_goal_);
  if (!enabled) return 0.0;
  const Vector6d shifted = residual_ + lambda / rho;  // eq. (7), PHR form
  if (with_gradient) {
    kinematics_.EndEffectorJacobian(cache_, J_WE_);
    PoseResidualJacobian(residual_, J_WE_, dr_dz_);
    dL_dz_.noalias() = dr_dz_.transpose() * (rho * shifted);
  }
  return 0.5 * rho * shifted.squaredNorm();
}

}  // namespace topay
