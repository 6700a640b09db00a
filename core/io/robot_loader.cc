#include "core/io/robot_loader.h"

#include <cmath>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/robot_yaml.h"
#include "core/io/urdf_tree.h"
#include "core/robot/self_collision.h"

namespace topay {
namespace {

int ResolveLink(const RobotModel& model, const std::string& name, const std::string& yaml_source,
                const std::string& field, const std::string& urdf_source) {
  const int link = model.FindLink(name);
  if (link < 0) {
    throw ConfigError(yaml_source, field, "no link named '" + name + "' in " + urdf_source);
  }
  return link;
}

Eigen::VectorXd ListOfJointCount(const std::vector<double>& values, int num_joints,
                                 const std::string& yaml_source, const std::string& field) {
  if (static_cast<int>(values.size()) != num_joints) {
    throw ConfigError(yaml_source, field,
                      "has " + std::to_string(values.size()) + " entries, the URDF has " +
                          std::to_string(num_joints) + " movable joints");
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), num_joints);
}

// Position limits: the URDF's, or the YAML's joint_limits.position_lower/upper if given (needed
// for continuous joints, which have none in the URDF).
void SetPositionLimits(const UrdfTree& tree, const RobotYaml& yaml, const std::string& yaml_source,
                       RobotModel* model) {
  const int n = model->num_joints();
  JointLimits& limits = model->joint_limits;
  const bool from_yaml = !yaml.q_min_rad.empty();
  const std::vector<double>& lower = from_yaml ? yaml.q_min_rad : tree.q_min_rad;
  const std::vector<double>& upper = from_yaml ? yaml.q_max_rad : tree.q_max_rad;
  limits.q_min_rad = ListOfJointCount(lower, n, yaml_source, "joint_limits.position_lower");
  limits.q_max_rad = ListOfJointCount(upper, n, yaml_source, "joint_limits.position_upper");
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(limits.q_min_rad(i)) || !std::isfinite(limits.q_max_rad(i))) {
      throw ConfigError(yaml_source, "joint_limits.position_lower",
                        "joint '" + model->joint_names[i] +
                            "' is continuous: give joint_limits.position_lower/position_upper");
    }
    if (!(limits.q_min_rad(i) < limits.q_max_rad(i))) {
      throw ConfigError(yaml_source, "joint_limits.position_lower[" + std::to_string(i) + "]",
                        "must be below position_upper");
    }
  }
}

// The optional stow_q: one value per joint, within the position limits.
void SetStowConfiguration(const RobotYaml& yaml, const std::string& yaml_source,
                          RobotModel* model) {
  if (yaml.stow_q_rad.empty()) return;
  const int n = model->num_joints();
  model->stow_q_rad = ListOfJointCount(yaml.stow_q_rad, n, yaml_source, "stow_q");
  for (int i = 0; i < n; ++i) {
    const double q = model->stow_q_rad(i);
    if (!(q >= model->joint_limits.q_min_rad(i) && q <= model->joint_limits.q_max_rad(i))) {
      throw ConfigError(yaml_source, "stow_q[" + std::to_string(i) + "]",
                        "is " + std::to_string(q) + ", outside the joint's position limits [" +
                            std::to_string(model->joint_limits.q_min_rad(i)) + ", " +
                            std::to_string(model->joint_limits.q_max_rad(i)) + "]");
    }
  }
}

}  // namespace

RobotModel LoadRobotModel(const std::string& urdf_path, const std::string& yaml_path) {
  const std::string urdf_text = ReadBoundedTextFile(urdf_path, kMaxConfigFileBytes, "robot URDF");
  const std::string yaml_text = ReadBoundedTextFile(yaml_path, kMaxConfigFileBytes, "robot YAML");
  return LoadRobotModelFromStrings(urdf_text, urdf_path, yaml_text, yaml_path);
}

RobotModel LoadRobotModelFromStrings(const std::string& urdf_text, const std::string& urdf_source,
                                     const std::string& yaml_text, const std::string& yaml_source) {
  const UrdfTree tree = ParseUrdfTree(urdf_text, urdf_source);
  const RobotYaml yaml = ParseRobotYaml(yaml_text, yaml_source);

  RobotModel model;
  model.name = tree.robot_name;
  model.links = tree.links;
  model.joint_names = tree.joint_names;
  if (model.links.front().name != yaml.base_link) {
    throw ConfigError(yaml_source, "base_link",
                      "is '" + yaml.base_link + "' but the root link of " + urdf_source + " is '" +
                          model.links.front().name + "'");
  }
  model.base_cylinder = yaml.base_cylinder;
  for (std::size_t i = 0; i < yaml.spheres.size(); ++i) {
    const std::string field = "spheres[" + std::to_string(i) + "].link";
    CollisionSphere sphere;
    sphere.link = ResolveLink(model, yaml.spheres[i].link, yaml_source, field, urdf_source);
    sphere.p_LS_m = yaml.spheres[i].p_LS_m;
    sphere.radius_m = yaml.spheres[i].radius_m;
    model.spheres.push_back(sphere);
  }
  model.base_limits = yaml.base_limits;
  const int n = model.num_joints();
  model.joint_limits.qd_max_radps =
      ListOfJointCount(yaml.qd_max_radps, n, yaml_source, "joint_limits.velocity");
  model.joint_limits.qdd_max_radps2 =
      ListOfJointCount(yaml.qdd_max_radps2, n, yaml_source, "joint_limits.acceleration");
  SetPositionLimits(tree, yaml, yaml_source, &model);
  model.end_effector_link =
      ResolveLink(model, yaml.end_effector_link, yaml_source, "end_effector.link", urdf_source);
  model.X_LE = yaml.X_LE;
  model.self_collision_pairs = FindSelfCollisionPairs(model);
  SetStowConfiguration(yaml, yaml_source, &model);
  return model;
}

}  // namespace topay
