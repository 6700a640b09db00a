#include "core/robot/whole_body_state.h"

#include <cmath>

namespace topay {

Eigen::VectorXd WholeBodyState::ToVector() const {
  Eigen::VectorXd z(3 + q_rad.size());
  z << x_m, y_m, yaw_rad, q_rad;
  return z;
}

WholeBodyState WholeBodyState::FromVector(const Eigen::VectorXd& z) {
  WholeBodyState state;
  state.x_m = z(0);
  state.y_m = z(1);
  state.yaw_rad = z(2);
  state.q_rad = z.tail(z.size() - 3);
  return state;
}

Eigen::Isometry3d WholeBodyState::BasePose() const {
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();
  X_WB.linear() = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  X_WB.translation() = Eigen::Vector3d(x_m, y_m, 0.0);
  return X_WB;
}

bool WholeBodyState::IsFinite() const {
  return std::isfinite(x_m) && std::isfinite(y_m) && std::isfinite(yaw_rad) &&
         q_rad.allFinite();
}

}  // namespace topay
