#include "core/optimization/trajectory_problem.h"

#include <cmath>
#include <cstdio>
#include <vector>

namespace topay {
namespace {

std::string Format(const char* format, double a, double b = 0.0) {
  char buffer[128];
  std::snprintf(buffer, sizeof(buffer), format, a, b);
  return buffer;
}

std::string CheckStart(const WholeBodyState& start, const RobotModel& model) {
  if (start.num_joints() != model.num_joints()) {
    return "start state has " + std::to_string(start.num_joints()) + " joints, the robot " +
           std::to_string(model.num_joints());
  }
  if (!start.IsFinite()) return "start state is not finite";
  for (int k = 0; k < model.num_joints(); ++k) {
    const double q = start.q_rad(k);
    if (q < model.joint_limits.q_min_rad(k) || q > model.joint_limits.q_max_rad(k)) {
      return "start joint " + std::to_string(k + 1) + " = " + std::to_string(q) +
             " rad is outside its limits";
    }
  }
  return "";
}

std::string CheckGoal(const Eigen::Isometry3d& goal, const SignedDistanceField3& arm_field,
                      const ReachHeights& reach) {
  if (!goal.matrix().allFinite()) return "goal pose X_WE_goal is not finite";
  if (!(goal.linear().transpose() * goal.linear()).isIdentity(1e-6)) {
    return "goal pose X_WE_goal's rotation is not orthonormal";
  }
  const double z = goal.translation().z();
  if (z < reach.min_z_m || z > reach.max_z_m) {
    return "target out of reach: its height " + Format("%.3f m", z) +
           " is outside the arm's reach " + Format("[%.3f, %.3f] m", reach.min_z_m, reach.max_z_m);
  }
  // Clearly inside an obstacle: the 3D field, within one cell of the exact distance, is
  // negative by more than a cell.
  const double resolution = arm_field.geometry().resolution_m;
  const double distance = arm_field.Distance(goal.translation());
  if (distance < -resolution) {
    return "target inside an obstacle (3D field distance " + Format("%.3f m)", distance);
  }
  return "";
}

}  // namespace

ReachHeights ComputeReachHeights(const Kinematics& kinematics) {
  const RobotModel& model = kinematics.model();
  std::vector<int> chain;  // E's link up to the root
  for (int link = model.end_effector_link; link >= 0; link = model.links[link].parent) {
    chain.push_back(link);
  }
  int first_joint = -1;  // the movable joint nearest the root
  for (int i = static_cast<int>(chain.size()) - 1; i >= 0; --i) {
    if (model.links[chain[i]].joint_type != JointType::kFixed) {
      first_joint = i;
      break;
    }
  }
  KinematicsCache cache = kinematics.MakeCache();
  WholeBodyState zero;
  zero.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  kinematics.Update(zero, &cache);
  ReachHeights reach;
  if (first_joint < 0) {  // no arm: E is rigid on the base
    reach.min_z_m = reach.max_z_m = cache.X_WE.translation().z();
    return reach;
  }
  const double joint_z = cache.X_WL[chain[first_joint]].translation().z();
  double length = model.X_LE.translation().norm();
  for (int i = 0; i < first_joint; ++i) length += model.links[chain[i]].X_PJ.translation().norm();
  reach.min_z_m = joint_z - length;
  reach.max_z_m = joint_z + length;
  return reach;
}

std::string CheckTrajectoryProblem(const TrajectoryProblem& problem, const Kinematics& kinematics,
                                   const SignedDistanceField3& arm_field,
                                   const ReachHeights& reach) {
  const std::string start_error = CheckStart(problem.start, kinematics.model());
  if (!start_error.empty()) return start_error;
  if (!problem.start_rates.HasJointCount(kinematics.num_joints())) {
    return "start rates have joint vectors of " +
           std::to_string(problem.start_rates.qd_radps.size()) + " / " +
           std::to_string(problem.start_rates.qdd_radps2.size()) + " entries, the robot " +
           std::to_string(kinematics.num_joints()) + " joints";
  }
  if (!problem.start_rates.IsFinite()) return "start rates are not finite";
  const BaseLimits& l = problem.base_limits;
  for (double limit : {l.v_max_mps, l.a_max_mps2, l.omega_max_radps, l.beta_max_radps2}) {
    if (!(std::isfinite(limit) && limit > 0.0)) return "base limits must be finite and > 0";
  }
  return CheckGoal(problem.X_WE_goal, arm_field, reach);
}

std::string CheckExactPathStretches(const TrajectoryProblem& problem, int path_size) {
  const auto check = [&](int count, const char* name) -> std::string {
    if (count >= 0 && count <= path_size) return "";
    return std::string(name) + " = " + std::to_string(count) + " is outside [0, " +
           std::to_string(path_size) + "] (the initial path has " + std::to_string(path_size) +
           " states)";
  };
  const std::string prefix = check(problem.exact_prefix_states, "exact_prefix_states");
  return prefix.empty() ? check(problem.exact_suffix_states, "exact_suffix_states") : prefix;
}

}  // namespace topay
