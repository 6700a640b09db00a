#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/robot/robot_model.h"

namespace topay {

/// A collision sphere as the YAML names it (its link by name; resolved against the URDF later).
struct YamlSphere {
  std::string link;
  Eigen::Vector3d p_LS_m = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
};

/// The robot YAML's content (see config/robot/README.md), validated for syntax, types,
/// finiteness and signs; list lengths against the joint count are checked by the loader.
struct RobotYaml {
  std::string base_link;
  BaseCylinder base_cylinder;
  std::vector<YamlSphere> spheres;
  BaseLimits base_limits;
  std::vector<double> qd_max_radps;
  std::vector<double> qdd_max_radps2;
  /// Optional position-limit overrides (empty if absent).
  std::vector<double> q_min_rad;
  std::vector<double> q_max_rad;
  /// Optional stowed arm configuration (empty if absent).
  std::vector<double> stow_q_rad;
  std::string end_effector_link;
  Eigen::Isometry3d X_LE = Eigen::Isometry3d::Identity();
};

/// Parses the robot YAML text; `source` names it in errors.
RobotYaml ParseRobotYaml(const std::string& yaml_text, const std::string& source);

}  // namespace topay
