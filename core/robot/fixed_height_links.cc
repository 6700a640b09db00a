#include "core/robot/fixed_height_links.h"

namespace topay {
namespace {

// A tilt of 1e-6 rad moves a point 1 m from the axis by 1 um: rounding in a URDF's rpy.
constexpr double kTiltTolerance = 1e-6;

// True when the non-zero `v` is parallel to e_z (either way), within kTiltTolerance.
bool IsVertical(const Eigen::Vector3d& v) {
  return v.head<2>().norm() <= kTiltTolerance * v.norm() && v.norm() > 0.0;
}

// The joint keeps its child level when its parent is: the joint frame's z axis is vertical in
// the parent and the joint does not move the child out of that (fixed, or revolute about it).
bool KeepsLevel(const Link& link) {
  if (!IsVertical(link.X_PJ.linear() * Eigen::Vector3d::UnitZ())) return false;
  switch (link.joint_type) {
    case JointType::kFixed: return true;
    case JointType::kRevolute: return IsVertical(link.axis_J);
    case JointType::kPrismatic: return false;
  }
  return false;
}

}  // namespace

std::vector<bool> FixedHeightLinks(const RobotModel& model) {
  std::vector<bool> fixed(model.links.size(), false);
  for (std::size_t l = 0; l < model.links.size(); ++l) {
    const Link& link = model.links[l];
    // Topological order: the parent is decided first; -1 is the base frame, level by definition.
    const bool parent_level = link.parent < 0 || fixed[static_cast<std::size_t>(link.parent)];
    fixed[l] = parent_level && KeepsLevel(link);
  }
  return fixed;
}

}  // namespace topay
