#pragma once

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay {

enum class JointType { kFixed, kRevolute, kPrismatic };

/// One link of the kinematic tree and the joint that connects it to its parent.
/// Follows URDF: the child link frame C coincides with the joint frame J, placed at X_PJ in the
/// parent link frame P; the joint moves C about/along axis_J (a unit vector in J):
///   X_PC(q) = X_PJ * Rot(axis_J, q)   or   X_PJ * Trans(axis_J * q).
struct Link {
  std::string name;
  int parent = -1;  ///< Index of the parent link; -1 for the root (the base frame B).
  std::string joint_name;
  JointType joint_type = JointType::kFixed;
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d axis_J = Eigen::Vector3d::UnitZ();
  int q_index = -1;  ///< Index of this link's joint in q, or -1 for a fixed joint.
};

/// A collision sphere rigidly attached to a link: centre p_LS in the link frame L.
struct CollisionSphere {
  int link = -1;
  Eigen::Vector3d p_LS_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

/// The base's collision solid: a vertical cylinder centred on the base frame's z axis,
/// from the ground (z = 0) to height_m.
struct BaseCylinder {
  double radius_m = 0.40;
  double height_m = 0.155;
};

struct BaseLimits {
  double v_max_mps = 1.0;           ///< Linear speed.
  double a_max_mps2 = 0.8;          ///< Linear acceleration.
  double omega_max_radps = 0.9;     ///< Yaw rate.
  double beta_max_radps2 = 1.0;     ///< Yaw acceleration.
};

/// Per-joint limits, all of size N (joint count), in q order.
struct JointLimits {
  Eigen::VectorXd q_min_rad;
  Eigen::VectorXd q_max_rad;
  Eigen::VectorXd qd_max_radps;     ///< Symmetric velocity limit.
  Eigen::VectorXd qdd_max_radps2;   ///< Symmetric acceleration limit.
};

/// Everything the planner knows of the robot, loaded from the URDF (kinematic tree) and the
/// robot YAML (collision model, limits, end-effector frame) by core/io/robot_loader.h.
/// Nothing kinematic is hard-coded in C++.
struct RobotModel {
  std::string name;
  std::vector<Link> links;                ///< Topological order: parent index < own index.
  std::vector<std::string> joint_names;   ///< Movable joints in q order (depth-first).
  BaseCylinder base_cylinder;
  std::vector<CollisionSphere> spheres;   ///< Bottom to top as listed in the YAML.
  BaseLimits base_limits;
  JointLimits joint_limits;
  int end_effector_link = -1;             ///< Link L the end-effector frame E is fixed to.
  Eigen::Isometry3d X_LE = Eigen::Isometry3d::Identity();
  /// Sphere index pairs checked for self-collision (see core/robot/self_collision.h):
  /// spheres on non-adjacent links that do not overlap at q = 0.
  std::vector<std::pair<int, int>> self_collision_pairs;
  /// Optional stowed arm configuration (N joints, within the limits): the arm folded low and
  /// close to the base axis, the pose a robot drives through tight spaces with. Planners may
  /// steer the arm towards it (ArmRrtStarOptions::stow_bias). Empty: none.
  Eigen::VectorXd stow_q_rad;

  int num_joints() const { return static_cast<int>(joint_names.size()); }
  /// Index of the link with this name, or -1.
  int FindLink(const std::string& link_name) const;
};

}  // namespace topay
