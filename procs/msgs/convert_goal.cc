#include "procs/msgs/convert_goal.h"

#include <cmath>

namespace topay::msgs {

goal_t ToMessage(const PlanGoal& goal) {
  goal_t msg;
  msg.utime = goal.utime;
  msg.goal_id = goal.goal_id;
  const Eigen::Vector3d p = goal.X_WE.translation();
  const Eigen::Quaterniond q(goal.X_WE.rotation());
  for (int i = 0; i < 3; ++i) msg.p_WE[i] = p(i);
  msg.quat_WE[0] = q.w();
  msg.quat_WE[1] = q.x();
  msg.quat_WE[2] = q.y();
  msg.quat_WE[3] = q.z();
  msg.has_hint = goal.hint.has_value();
  msg.hint.utime = 0;
  msg.hint.num_joints = 0;
  if (goal.hint) {
    msg.hint.x_m = goal.hint->x_m;
    msg.hint.y_m = goal.hint->y_m;
    msg.hint.yaw_rad = goal.hint->yaw_rad;
    msg.hint.num_joints = goal.hint->num_joints();
    msg.hint.q_rad.assign(goal.hint->q_rad.data(),
                          goal.hint->q_rad.data() + goal.hint->q_rad.size());
  } else {
    msg.hint.x_m = msg.hint.y_m = msg.hint.yaw_rad = 0.0;
  }
  return msg;
}

std::optional<PlanGoal> FromMessage(const goal_t& msg, std::string* error) {
  const Eigen::Vector3d p(msg.p_WE[0], msg.p_WE[1], msg.p_WE[2]);
  Eigen::Quaterniond q(msg.quat_WE[0], msg.quat_WE[1], msg.quat_WE[2], msg.quat_WE[3]);
  if (!p.allFinite()) {
    *error = "goal_t.p_WE: not finite";
    return std::nullopt;
  }
  if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-3) {
    *error = "goal_t.quat_WE: not a unit quaternion";
    return std::nullopt;
  }
  PlanGoal goal;
  goal.utime = msg.utime;
  goal.goal_id = msg.goal_id;
  goal.X_WE.linear() = q.normalized().toRotationMatrix();
  goal.X_WE.translation() = p;
  if (msg.has_hint) {
    if (msg.hint.num_joints < 0 ||
        msg.hint.q_rad.size() != static_cast<std::size_t>(msg.hint.num_joints)) {
      *error = "goal_t.hint.q_rad: size does not match num_joints";
      return std::nullopt;
    }
    WholeBodyState hint;
    hint.x_m = msg.hint.x_m;
    hint.y_m = msg.hint.y_m;
    hint.yaw_rad = msg.hint.yaw_rad;
    hint.q_rad = Eigen::Map<const Eigen::VectorXd>(msg.hint.q_rad.data(), msg.hint.num_joints);
    if (!hint.IsFinite()) {
      *error = "goal_t.hint: not finite";
      return std::nullopt;
    }
    goal.hint = hint;
  }
  return goal;
}

}  // namespace topay::msgs
