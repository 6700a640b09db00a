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

/// Deepest XML element nesting ParseUrdfTree accepts (a URDF nests about 5 levels: robot,
/// link, visual, geometry, box).
inline constexpr int kMaxUrdfElementDepth = 100;

/// Parses a URDF document with urdfdom and flattens its tree. The joints must make a tree with
/// one root: a link with several parent joints, a joint that is its own parent, a cycle,
/// several roots, a joint naming a missing link and duplicate link or joint names are
/// ConfigErrors naming the joint or link. `source` names the document in
/// errors (ConfigError(source, "<field>", ...)).
UrdfTree ParseUrdfTree(const std::string& urdf_text, const std::string& source);

}  // namespace topay
