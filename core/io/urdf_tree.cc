#include "core/io/urdf_tree.h"

#include <cmath>
#include <limits>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "core/common/error.h"

namespace topay {
namespace {

std::string JointField(const urdf::Joint& joint, const std::string& what) {
  return "joint[" + joint.name + "]." + what;
}

bool Finite(const urdf::Vector3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// X_PJ from the joint's <origin xyz rpy> (urdfdom stores the rotation as a quaternion).
Eigen::Isometry3d JointOrigin(const urdf::Joint& joint, const std::string& source) {
  const urdf::Pose& pose = joint.parent_to_joint_origin_transform;
  const urdf::Rotation& r = pose.rotation;
  if (!Finite(pose.position) || !std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z) ||
      !std::isfinite(r.w)) {
    throw ConfigError(source, JointField(joint, "origin"), "must be finite numbers");
  }
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();
  X_PJ.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  X_PJ.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  return X_PJ;
}

JointType MovableType(const urdf::Joint& joint, const std::string& source) {
  switch (joint.type) {
    case urdf::Joint::FIXED:
      return JointType::kFixed;
    case urdf::Joint::REVOLUTE:
    case urdf::Joint::CONTINUOUS:
      return JointType::kRevolute;
    case urdf::Joint::PRISMATIC:
      return JointType::kPrismatic;
    default:
      throw ConfigError(source, JointField(joint, "type"),
                        "unsupported joint type (only fixed, revolute, continuous, prismatic)");
  }
}

// While alive, collects urdfdom's error messages (it reports through console_bridge and returns
// null) instead of printing them, so they can go into the ConfigError; restores the previous
// handler on destruction. console_bridge's handler is process-wide: loads on several threads
// at once may mix their messages (never lose an error: each load still throws).
class UrdfMessageCapture : public console_bridge::OutputHandler {
 public:
  UrdfMessageCapture() : previous_(console_bridge::getOutputHandler()) {
    console_bridge::useOutputHandler(this);
  }
  ~UrdfMessageCapture() override { console_bridge::useOutputHandler(previous_); }
  UrdfMessageCapture(const UrdfMessageCapture&) = delete;
  UrdfMessageCapture& operator=(const UrdfMessageCapture&) = delete;

  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
    messages_ += messages_.empty() ? text : "; " + text;
  }
  const std::string& messages() const { return messages_; }

 private:
  console_bridge::OutputHandler* previous_;
  std::string messages_;
};

class TreeFlattener {
 public:
  TreeFlattener(const std::string& source, UrdfTree* tree) : source_(source), tree_(tree) {}

  // Depth-first: the link, then each child subtree in urdfdom's child order.
  void Visit(const urdf::Link& link, int parent_index) {
    Link out;
    out.name = link.name;
    out.parent = parent_index;
    if (link.parent_joint) AddJoint(*link.parent_joint, &out);
    const int index = static_cast<int>(tree_->links.size());
    tree_->links.push_back(out);
    for (const urdf::LinkSharedPtr& child : link.child_links) Visit(*child, index);
  }

 private:
  void AddJoint(const urdf::Joint& joint, Link* out) {
    out->joint_name = joint.name;
    out->joint_type = MovableType(joint, source_);
    out->X_PJ = JointOrigin(joint, source_);
    if (out->joint_type == JointType::kFixed) return;
    if (joint.mimic) {
      throw ConfigError(source_, JointField(joint, "mimic"), "mimic joints are not supported");
    }
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (!axis.allFinite() || axis.norm() < 1e-9) {
      throw ConfigError(source_, JointField(joint, "axis"), "must be a finite non-zero vector");
    }
    out->axis_J = axis.normalized();
    out->q_index = static_cast<int>(tree_->joint_names.size());
    tree_->joint_names.push_back(joint.name);
    AddPositionLimits(joint);
  }

  void AddPositionLimits(const urdf::Joint& joint) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    if (joint.type == urdf::Joint::CONTINUOUS) {
      tree_->q_min_rad.push_back(-kInf);
      tree_->q_max_rad.push_back(kInf);
      return;
    }
    if (!joint.limits) {
      throw ConfigError(source_, JointField(joint, "limit"), "missing <limit lower upper>");
    }
    const double lower = joint.limits->lower;
    const double upper = joint.limits->upper;
    if (!std::isfinite(lower) || !std::isfinite(upper) || !(lower < upper)) {
      throw ConfigError(source_, JointField(joint, "limit"),
                        "needs finite lower < upper, got [" + std::to_string(lower) + ", " +
                            std::to_string(upper) + "]");
    }
    tree_->q_min_rad.push_back(lower);
    tree_->q_max_rad.push_back(upper);
  }

  const std::string& source_;
  UrdfTree* tree_;
};

}  // namespace

UrdfTree ParseUrdfTree(const std::string& urdf_text, const std::string& source) {
  // urdfdom returns null for malformed XML, a missing <robot>, a bad number, a joint naming an
  // unknown link, several roots, ...; its reasons come through console_bridge.
  urdf::ModelInterfaceSharedPtr urdf_model;
  std::string reasons;
  {
    const UrdfMessageCapture capture;
    urdf_model = urdf::parseURDF(urdf_text);
    reasons = capture.messages();
  }
  if (!urdf_model || !urdf_model->getRoot()) {
    throw ConfigError(
        source, "robot",
        "malformed URDF: " + (reasons.empty() ? "urdfdom could not parse it" : reasons));
  }
  UrdfTree tree;
  tree.robot_name = urdf_model->getName();
  TreeFlattener(source, &tree).Visit(*urdf_model->getRoot(), -1);
  if (tree.joint_names.empty()) {
    throw ConfigError(source, "robot", "has no movable joint");
  }
  return tree;
}

}  // namespace topay
