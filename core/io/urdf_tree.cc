#include "core/io/urdf_tree.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "core/common/error.h"
#include "core/io/urdf_joint_cycles.h"

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

  // Depth-first preorder from `root`: a link, then each child subtree in urdfdom's child
  // order. Iterative (a long chain must not exhaust the stack); CheckIsTree has run, so every
  // link is reached exactly once.
  void Flatten(const urdf::Link& root) {
    std::vector<std::pair<const urdf::Link*, int>> pending{{&root, -1}};
    while (!pending.empty()) {
      const auto [link, parent_index] = pending.back();
      pending.pop_back();
      Link out;
      out.name = link->name;
      out.parent = parent_index;
      if (link->parent_joint) AddJoint(*link->parent_joint, &out);
      const int index = static_cast<int>(tree_->links.size());
      tree_->links.push_back(out);
      for (auto child = link->child_links.rbegin(); child != link->child_links.rend(); ++child) {
        pending.emplace_back(child->get(), index);
      }
    }
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
    // Scaled by its largest entry before it is normalized: the norm of (0, 1e308, 1e308)
    // overflows to inf, and normalized() then gives the zero vector.
    const double largest = axis.allFinite() ? axis.cwiseAbs().maxCoeff() : 0.0;
    const Eigen::Vector3d scaled = largest > 0.0 ? Eigen::Vector3d(axis / largest) : axis;
    if (!(largest > 0.0) || scaled.norm() * largest < 1e-9) {
      throw ConfigError(source_, JointField(joint, "axis"), "must be a finite non-zero vector");
    }
    out->axis_J = scaled.normalized();
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

// The cycle of joints found by following parent joints up from `link`, which is not reached
// from the root (so, one parent per link, the chain never ends at the root): "'j2' -> 'j3'".
std::string CycleAbove(std::string link, const std::map<std::string, std::string>& parent_joint_of,
                       const urdf::ModelInterface& model) {
  std::vector<std::string> chain;  // links from `link` upwards
  while (std::find(chain.begin(), chain.end(), link) == chain.end()) {
    chain.push_back(link);
    const auto joint = parent_joint_of.find(link);
    if (joint == parent_joint_of.end()) return "(none)";  // not reached: cannot happen
    link = model.joints_.at(joint->second)->parent_link_name;
  }
  std::string cycle;
  for (auto it = std::find(chain.begin(), chain.end(), link); it != chain.end(); ++it) {
    cycle += (cycle.empty() ? "'" : " -> '") + parent_joint_of.at(*it) + "'";
  }
  return cycle;
}

// Throws unless the joints make a tree with one root: urdfdom itself rejects malformed XML,
// duplicate link or joint names, a joint naming a missing link, several roots and a cycle
// through every link, but accepts a link with several parent joints, a joint whose parent is
// its child, and a cycle beside the tree (its links hang off nothing); walking those never
// ends.
void CheckIsTree(const urdf::ModelInterface& model, const std::string& source) {
  std::map<std::string, std::string> parent_joint_of;  // child link -> the joint naming it
  for (const auto& [name, joint] : model.joints_) {    // by name: a deterministic first error
    if (joint->parent_link_name == joint->child_link_name) {
      throw ConfigError(source, JointField(*joint, "child"),
                        "link '" + joint->child_link_name +
                            "' is its own parent: a URDF must be a tree");
    }
    const auto [it, inserted] = parent_joint_of.emplace(joint->child_link_name, name);
    if (!inserted) {
      throw ConfigError(source, JointField(*joint, "child"),
                        "link '" + joint->child_link_name + "' already has the parent joint '" +
                            it->second + "': a URDF must be a tree (one parent per link)");
    }
  }
  // One parent per link: a link not reached from the root lies on a cycle (or hangs off one).
  std::set<std::string> reached;
  std::vector<const urdf::Link*> pending{model.getRoot().get()};
  while (!pending.empty()) {
    const urdf::Link* link = pending.back();
    pending.pop_back();
    if (!reached.insert(link->name).second) continue;
    for (const urdf::LinkSharedPtr& child : link->child_links) pending.push_back(child.get());
  }
  for (const auto& [name, link] : model.links_) {
    if (reached.count(name) == 0) {
      throw ConfigError(source, "link[" + name + "]",
                        "is not connected to the root link '" + model.getRoot()->name +
                            "': its parent joints lead to the cycle " +
                            CycleAbove(name, parent_joint_of, model) + "; a URDF must be a tree");
    }
  }
}

// The deepest nesting of XML elements in `text` (comments, CDATA, <?...?> and <!...> skipped;
// quoted attribute values may hold '>'). A rough scan: malformed XML is urdfdom's to reject.
int MaxElementDepth(const std::string& text) {
  int depth = 0;
  int deepest = 0;
  std::size_t i = 0;
  const auto skip_past = [&text](std::size_t from, const char* end) {
    const std::size_t at = text.find(end, from);
    return at == std::string::npos ? text.size() : at + std::strlen(end);
  };
  while ((i = text.find('<', i)) != std::string::npos) {
    if (text.compare(i, 4, "<!--") == 0) {
      i = skip_past(i + 4, "-->");
      continue;
    }
    if (text.compare(i, 9, "<![CDATA[") == 0) {
      i = skip_past(i + 9, "]]>");
      continue;
    }
    std::size_t j = i + 1;
    char quote = 0;
    for (; j < text.size(); ++j) {
      const char c = text[j];
      if (quote != 0) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = c;
      } else if (c == '>') {
        break;
      }
    }
    if (j >= text.size()) break;
    const char kind = i + 1 < text.size() ? text[i + 1] : ' ';
    if (kind == '/') {
      depth = std::max(depth - 1, 0);
    } else if (kind != '?' && kind != '!' && text[j - 1] != '/') {
      deepest = std::max(deepest, ++depth);
    }
    i = j + 1;
  }
  return deepest;
}

// NUL bytes after a text TinyXML parses (it may skip up to a UTF-8 sequence past the end).
constexpr std::size_t kTinyXmlPadding = 16;

// Empties every link's list of children when the parse ends (a throw included): a model that
// holds a cycle of links (rejected by CheckIsTree) would otherwise never be freed.
struct ChildLinksReleaser {
  const urdf::ModelInterfaceSharedPtr* model;
  ~ChildLinksReleaser() {
    if (*model == nullptr) return;
    for (auto& [name, link] : (*model)->links_) link->child_links.clear();
  }
};

}  // namespace

UrdfTree ParseUrdfTree(const std::string& urdf_text, const std::string& source) {
  // urdfdom returns null for malformed XML, a missing <robot>, a bad number, a joint naming an
  // unknown link, several roots, ...; its reasons come through console_bridge.
  // urdfdom's XML parser recurses per nesting level: a deep enough document overflows the
  // stack (a URDF nests about 5 levels).
  if (MaxElementDepth(urdf_text) > kMaxUrdfElementDepth) {
    throw ConfigError(source, "robot",
                      "XML elements nest deeper than " + std::to_string(kMaxUrdfElementDepth) +
                          " levels: not a URDF");
  }
  // TinyXML 2.6.2 (under urdfdom and CheckNoJointCycle) can step over the terminating NUL of
  // malformed text and read past the buffer (found by the robot_model fuzz target, ASan
  // heap-buffer-overflow in TiXmlBase::ReadName): it reads a copy followed by NUL padding.
  const std::string padded_text = urdf_text + std::string(kTinyXmlPadding, '\0');
  CheckNoJointCycle(padded_text, source);
  urdf::ModelInterfaceSharedPtr urdf_model;
  const ChildLinksReleaser releaser{&urdf_model};
  std::string reasons;
  {
    const UrdfMessageCapture capture;
    urdf_model = urdf::parseURDF(padded_text);
    reasons = capture.messages();
  }
  if (!urdf_model || !urdf_model->getRoot()) {
    throw ConfigError(
        source, "robot",
        "malformed URDF: " + (reasons.empty() ? "urdfdom could not parse it" : reasons));
  }
  CheckIsTree(*urdf_model, source);
  UrdfTree tree;
  tree.robot_name = urdf_model->getName();
  TreeFlattener(source, &tree).Flatten(*urdf_model->getRoot());
  if (tree.joint_names.empty()) {
    throw ConfigError(source, "robot", "has no movable joint");
  }
  return tree;
}

}  // namespace topay
