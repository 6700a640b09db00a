#include "core/robot/whole_body_rates.h"

#include <algorithm>
#include <cmath>

namespace topay {
namespace {

Eigen::VectorXd OrZeros(const Eigen::VectorXd& values, int num_joints) {
  return values.size() == 0 ? Eigen::VectorXd::Zero(num_joints) : values;
}

double MaxAbs(const Eigen::VectorXd& values) {
  return values.size() == 0 ? 0.0 : values.cwiseAbs().maxCoeff();
}

}  // namespace

WholeBodyRates WholeBodyRates::Zero(int num_joints) {
  WholeBodyRates rates;
  rates.qd_radps.setZero(num_joints);
  rates.qdd_radps2.setZero(num_joints);
  return rates;
}

bool WholeBodyRates::IsFinite() const {
  return std::isfinite(v_mps) && std::isfinite(omega_radps) && std::isfinite(a_mps2) &&
         std::isfinite(beta_radps2) && qd_radps.allFinite() && qdd_radps2.allFinite();
}

bool WholeBodyRates::HasJointCount(int num_joints) const {
  const auto fits = [num_joints](const Eigen::VectorXd& v) {
    return v.size() == 0 || v.size() == num_joints;
  };
  return fits(qd_radps) && fits(qdd_radps2);
}

bool WholeBodyRates::IsAtRest(double tolerance) const {
  // A NaN is never "at rest".
  const double largest = std::max({std::abs(v_mps), std::abs(omega_radps), std::abs(a_mps2),
                                   std::abs(beta_radps2), MaxAbs(qd_radps), MaxAbs(qdd_radps2)});
  return IsFinite() && largest <= tolerance;
}

Eigen::VectorXd WholeBodyRates::JointVelocities(int num_joints) const {
  return OrZeros(qd_radps, num_joints);
}

Eigen::VectorXd WholeBodyRates::JointAccelerations(int num_joints) const {
  return OrZeros(qdd_radps2, num_joints);
}

}  // namespace topay
