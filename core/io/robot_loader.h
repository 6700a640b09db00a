#pragma once

#include <string>

#include "core/robot/robot_model.h"

namespace topay {

/// Loads the robot description: the kinematic tree and joint position limits from a URDF
/// (urdfdom) and the collision model, base and joint rate limits, base link name and
/// end-effector frame from the robot YAML (yaml-cpp). Fields and conventions:
/// config/robot/README.md.
///
/// The result: links in topological order (depth-first from the URDF root, siblings in the
/// order of their joint names, as urdfdom keeps them), fixed joints kept as links with
/// q_index -1, movable joints (revolute, continuous = revolute, prismatic) numbered q1..qN in
/// that order; self_collision_pairs filled (core/robot/self_collision.h).
///
/// Throws ConfigError("<file>", "<field>", "<what>") for a missing or unreadable file,
/// malformed XML/YAML, a missing/unknown field, a non-finite or out-of-range number, a link
/// that does not exist, a list whose length differs from the joint count, a root link other
/// than the YAML's base_link, or an unsupported joint type (floating, planar, mimic).
RobotModel LoadRobotModel(const std::string& urdf_path, const std::string& yaml_path);

/// Same, from the two documents' text; the source names stand for the files in errors.
RobotModel LoadRobotModelFromStrings(const std::string& urdf_text, const std::string& urdf_source,
                                     const std::string& yaml_text, const std::string& yaml_source);

}  // namespace topay
