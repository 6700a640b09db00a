#pragma once

#include <string>
#include <vector>

#include "core/robot/robot_model.h"

namespace topay {

/// The part of a RobotModel a URDF defines.
struct UrdfTree {
  std::string robot_name;
  std::vector<Link> links;               ///< Depth-first from the root; parent index < own.
  std::vector<std::string> joint_names;  ///< Movable joints in q order.
  /// Position limits in q order; a continuous joint has -inf / +inf (the YAML must give them).
  std::vector<double> q_min_rad;
  std::vector<double> q_max_rad;
};

/// Parses a URDF document with urdfdom and flattens its tree. `source` names the document in
/// errors (ConfigError(source, "<field>", ...)).
UrdfTree ParseUrdfTree(const std::string& urdf_text, const std::string& source);

}  // namespace topay
