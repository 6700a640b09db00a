#include "core/robot/joint_turns.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace topay {
namespace {

// Per joint index: true for a revolute joint.
std::vector<bool> RevoluteJoints(const RobotModel& model) {
  std::vector<bool> revolute(model.num_joints(), false);
  for (const Link& link : model.links) {
    if (link.q_index >= 0 && link.q_index < model.num_joints()) {
      revolute[link.q_index] = link.joint_type == JointType::kRevolute;
    }
  }
  return revolute;
}

}  // namespace

Eigen::VectorXd NearestJointTurns(const RobotModel& model, const Eigen::VectorXd& q_rad,
                                  const Eigen::VectorXd& q_reference_rad) {
  const int n = model.num_joints();
  if (q_rad.size() != n || q_reference_rad.size() != n) {
    throw std::invalid_argument("NearestJointTurns: q has " + std::to_string(q_rad.size()) +
                                " joints and the reference " + std::to_string(q_reference_rad.size()) +
                                ", the robot " + std::to_string(n));
  }
  constexpr double kTurn = 2.0 * std::numbers::pi;
  const std::vector<bool> revolute = RevoluteJoints(model);
  const JointLimits& limits = model.joint_limits;
  Eigen::VectorXd q = q_rad;
  for (int i = 0; i < n; ++i) {
    if (!revolute[i] || !std::isfinite(q(i)) || !std::isfinite(q_reference_rad(i))) continue;
    // For a reference within the limits, the nearest turn within them is one of k - 1, k, k + 1
    // (k: the nearest without limits).
    const double k = std::round((q_reference_rad(i) - q_rad(i)) / kTurn);
    for (double turns = k - 1.0; turns <= k + 1.0; turns += 1.0) {
      const double turned = q_rad(i) + turns * kTurn;
      if (turns != 0.0 && turned >= limits.q_min_rad(i) && turned <= limits.q_max_rad(i) &&
          std::abs(turned - q_reference_rad(i)) < std::abs(q(i) - q_reference_rad(i))) {
        q(i) = turned;
      }
    }
  }
  return q;
}

}  // namespace topay
