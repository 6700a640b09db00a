#include "core/validate/limit_ratios.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

void RequirePositive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw std::invalid_argument(std::string("kinematic limits: ") + field +
                                " must be finite and > 0, got " + std::to_string(value));
  }
}

void RequireSize(const Eigen::VectorXd& values, int num_joints, const char* field) {
  if (values.size() != num_joints) {
    throw std::invalid_argument(std::string("kinematic limits: joint_limits.") + field +
                                " has " + std::to_string(values.size()) + " entries, expected " +
                                std::to_string(num_joints));
  }
}

// Replaces *worst if ratio is strictly larger (ties keep the earlier limit).
void Consider(double ratio, Limit limit, int joint, double value, double bound,
              LimitRatio* worst) {
  if (ratio > worst->ratio || worst->limit == Limit::kNone) {
    worst->ratio = ratio;
    worst->limit = limit;
    worst->joint = joint;
    worst->value = value;
    worst->bound = bound;
  }
}

}  // namespace

void CheckKinematicLimits(const BaseLimits& base, const JointLimits& joints, int num_joints) {
  RequirePositive(base.v_max_mps, "base_limits.v_max_mps");
  RequirePositive(base.a_max_mps2, "base_limits.a_max_mps2");
  RequirePositive(base.omega_max_radps, "base_limits.omega_max_radps");
  RequirePositive(base.beta_max_radps2, "base_limits.beta_max_radps2");
  RequireSize(joints.q_min_rad, num_joints, "q_min_rad");
  RequireSize(joints.q_max_rad, num_joints, "q_max_rad");
  RequireSize(joints.qd_max_radps, num_joints, "qd_max_radps");
  RequireSize(joints.qdd_max_radps2, num_joints, "qdd_max_radps2");
  for (int j = 0; j < num_joints; ++j) {
    const std::string where = " of joint index " + std::to_string(j);
    if (!(std::isfinite(joints.q_min_rad(j)) && std::isfinite(joints.q_max_rad(j)) &&
          joints.q_min_rad(j) < joints.q_max_rad(j))) {
      throw std::invalid_argument("kinematic limits: joint_limits q_min_rad < q_max_rad (finite)"
                                  " does not hold" + where);
    }
    RequirePositive(joints.qd_max_radps(j), ("joint_limits.qd_max_radps" + where).c_str());
    RequirePositive(joints.qdd_max_radps2(j), ("joint_limits.qdd_max_radps2" + where).c_str());
  }
}

LimitRatio WorstRateRatio(const TrajectorySample& sample, const BaseLimits& base,
                          const JointLimits& joints) {
  LimitRatio worst;
  const double v = sample.v_mps;
  const double omega = sample.omega_radps;
  Consider(std::abs(v) / base.v_max_mps, Limit::kLinearVelocity, -1, v, base.v_max_mps, &worst);
  Consider(std::abs(omega) / base.omega_max_radps, Limit::kYawRate, -1, omega,
           base.omega_max_radps, &worst);
  // Eq. (9): |v_max omega +- omega_max v| <= v_max omega_max, divided by v_max omega_max.
  const double v_ratio = v / base.v_max_mps;
  const double omega_ratio = omega / base.omega_max_radps;
  const double coupled = std::max(std::abs(omega_ratio + v_ratio), std::abs(omega_ratio - v_ratio));
  Consider(coupled, Limit::kCoupledVelocity, -1, coupled, 1.0, &worst);
  // Eq. (10): a^2 <= a_max^2, beta^2 <= beta_max^2.
  Consider(std::abs(sample.a_mps2) / base.a_max_mps2, Limit::kLinearAcceleration, -1,
           sample.a_mps2, base.a_max_mps2, &worst);
  Consider(std::abs(sample.beta_radps2) / base.beta_max_radps2, Limit::kYawAcceleration, -1,
           sample.beta_radps2, base.beta_max_radps2, &worst);
  // Eqs. (11)-(12): qd o qd <= qd_max2, qdd o qdd <= qdd_max2 (element-wise).
  for (int j = 0; j < sample.qd_radps.size(); ++j) {
    Consider(std::abs(sample.qd_radps(j)) / joints.qd_max_radps(j), Limit::kJointVelocity, j,
             sample.qd_radps(j), joints.qd_max_radps(j), &worst);
  }
  for (int j = 0; j < sample.qdd_radps2.size(); ++j) {
    Consider(std::abs(sample.qdd_radps2(j)) / joints.qdd_max_radps2(j),
             Limit::kJointAcceleration, j, sample.qdd_radps2(j), joints.qdd_max_radps2(j),
             &worst);
  }
  return worst;
}

LimitRatio WorstJointPositionRatio(const Eigen::VectorXd& q_rad, const JointLimits& joints) {
  LimitRatio worst;
  for (int j = 0; j < q_rad.size(); ++j) {
    const double mid = 0.5 * (joints.q_min_rad(j) + joints.q_max_rad(j));
    const double half = 0.5 * (joints.q_max_rad(j) - joints.q_min_rad(j));
    const double bound = q_rad(j) >= mid ? joints.q_max_rad(j) : joints.q_min_rad(j);
    Consider(std::abs(q_rad(j) - mid) / half, Limit::kJointPosition, j, q_rad(j), bound, &worst);
  }
  return worst;
}

double MaxJointPositionExcess(const Eigen::VectorXd& q_rad, const JointLimits& joints,
                              int* joint) {
  double max_excess = -std::numeric_limits<double>::infinity();
  *joint = -1;
  for (int j = 0; j < q_rad.size(); ++j) {
    const double excess =
        std::max(joints.q_min_rad(j) - q_rad(j), q_rad(j) - joints.q_max_rad(j));
    if (excess > max_excess) {
      max_excess = excess;
      *joint = j;
    }
  }
  return max_excess;
}

}  // namespace topay
