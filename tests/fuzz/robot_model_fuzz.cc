// The robot description from untrusted text (core/io/robot_loader.h): the URDF alone
// (ParseUrdfTree), the robot YAML alone (ParseRobotYaml) and both together
// (LoadRobotModelFromStrings). Bad input must be a ConfigError naming its document; what loads
// must pass the model's own checks (tree order, limits, sphere and end-effector links, the
// self-collision pairs, forward kinematics).
// Input: [URDF text][0x00][robot YAML text] (without a 0x00 byte: all URDF, an empty YAML).
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include "core/common/error.h"
#include "core/io/robot_loader.h"
#include "core/io/robot_yaml.h"
#include "core/io/urdf_tree.h"
#include "core/robot/kinematics.h"
#include "core/validate/limit_ratios.h"
#include "tests/fuzz/loader_checks.h"
#include "tests/fuzz/loader_rigid.h"

namespace topay::fuzz {
namespace {

constexpr const char* kUrdfSource = "fuzz_robot.urdf";
constexpr const char* kYamlSource = "fuzz_robot.yaml";

void CheckTree(const UrdfTree& tree) {
  FuzzCheck(!tree.links.empty() && tree.links.front().parent == -1, "the tree starts at its root");
  FuzzCheck(!tree.joint_names.empty(), "a loaded URDF has a movable joint");
  const std::size_t n = tree.joint_names.size();
  FuzzCheck(tree.q_min_rad.size() == n && tree.q_max_rad.size() == n, "one position limit per joint");
  std::set<std::string> names;
  int next_q = 0;
  for (std::size_t i = 0; i < tree.links.size(); ++i) {
    const Link& link = tree.links[i];
    FuzzCheck(names.insert(link.name).second, "link names are unique");
    FuzzCheck(i == 0 || (link.parent >= 0 && static_cast<std::size_t>(link.parent) < i),
              "a link's parent comes before it");
    FuzzCheck(IsRigid(link.X_PJ), "a joint origin is a finite rigid transform");
    if (link.q_index < 0) {
      FuzzCheck(link.joint_type == JointType::kFixed, "only fixed joints have no q index");
      continue;
    }
    FuzzCheck(link.q_index == next_q++, "movable joints are numbered in link order");
    FuzzCheck(link.joint_type != JointType::kFixed, "a numbered joint moves");
    FuzzCheck(std::abs(link.axis_J.norm() - 1.0) < 1e-9, "a joint axis is a unit vector");
    FuzzCheck(tree.joint_names[static_cast<std::size_t>(link.q_index)] == link.joint_name,
              "joint_names follow q order");
  }
  FuzzCheck(static_cast<std::size_t>(next_q) == n, "every movable joint has a link");
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n; ++j) {
    const double lower = tree.q_min_rad[j];
    const double upper = tree.q_max_rad[j];
    FuzzCheck((std::isfinite(lower) && std::isfinite(upper) && lower < upper) ||
                  (lower == -kInf && upper == kInf),
              "position limits are finite lower < upper, or none (continuous)");
  }
}

bool FinitePositive(double value) { return std::isfinite(value) && value > 0.0; }

void CheckYaml(const RobotYaml& yaml) {
  FuzzCheck(!yaml.base_link.empty() && !yaml.end_effector_link.empty(), "link names are given");
  FuzzCheck(FinitePositive(yaml.base_cylinder.radius_m) && FinitePositive(yaml.base_cylinder.height_m),
            "the base cylinder has a finite positive size");
  FuzzCheck(!yaml.spheres.empty(), "a loaded YAML has collision spheres");
  for (const YamlSphere& sphere : yaml.spheres) {
    FuzzCheck(!sphere.link.empty() && sphere.p_LS_m.allFinite() && FinitePositive(sphere.radius_m),
              "a sphere has a link, a finite centre and a finite positive radius");
  }
  const BaseLimits& base = yaml.base_limits;
  FuzzCheck(FinitePositive(base.v_max_mps) && FinitePositive(base.a_max_mps2) &&
                FinitePositive(base.omega_max_radps) && FinitePositive(base.beta_max_radps2),
            "base limits are finite and positive");
  for (const double limit : yaml.qd_max_radps) FuzzCheck(FinitePositive(limit), "rate limits are positive");
  for (const double limit : yaml.qdd_max_radps2) FuzzCheck(FinitePositive(limit), "rate limits are positive");
  for (const double q : yaml.stow_q_rad) FuzzCheck(std::isfinite(q), "the stow pose is finite");
  FuzzCheck(IsRigid(yaml.X_LE), "the end-effector frame is a finite rigid transform");
}

void CheckModel(const RobotModel& model) {
  const int n = model.num_joints();
  const int num_links = static_cast<int>(model.links.size());
  try {
    CheckKinematicLimits(model.base_limits, model.joint_limits, n);
  } catch (const std::invalid_argument&) {
    FuzzCheck(false, "a loaded model's limits pass CheckKinematicLimits");
  }
  FuzzCheck(model.end_effector_link >= 0 && model.end_effector_link < num_links, "the end effector's link exists");
  const int num_spheres = static_cast<int>(model.spheres.size());
  FuzzCheck(num_spheres > 0, "a loaded model has collision spheres");
  for (const CollisionSphere& sphere : model.spheres) {
    FuzzCheck(sphere.link >= 0 && sphere.link < num_links, "a sphere's link exists");
  }
  for (const auto& [i, j] : model.self_collision_pairs) {
    FuzzCheck(0 <= i && i < j && j < num_spheres, "a self-collision pair names two spheres");
  }
  FuzzCheck(model.stow_q_rad.size() == 0 || model.stow_q_rad.size() == n, "the stow pose has every joint");
  for (int j = 0; j < model.stow_q_rad.size(); ++j) {
    FuzzCheck(model.stow_q_rad(j) >= model.joint_limits.q_min_rad(j) &&
                  model.stow_q_rad(j) <= model.joint_limits.q_max_rad(j),
              "the stow pose is within the limits");
  }
  // What every user of the model does next.
  const Kinematics kinematics(model);
  KinematicsCache cache = kinematics.MakeCache();
  WholeBodyState state;
  state.q_rad = model.stow_q_rad.size() == n ? model.stow_q_rad
                                               : Eigen::VectorXd(0.5 * (model.joint_limits.q_min_rad +
                                                                        model.joint_limits.q_max_rad));
  kinematics.Update(state, &cache);
  FuzzCheck(cache.p_WS.size() == model.spheres.size(), "forward kinematics places every sphere");
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay;
  using namespace topay::fuzz;
  const char* text = reinterpret_cast<const char*>(data);
  const void* split = size > 0 ? std::memchr(data, 0, size) : nullptr;
  const std::size_t urdf_size = split ? static_cast<std::size_t>(static_cast<const std::uint8_t*>(split) - data) : size;
  const std::string urdf(text, urdf_size);
  const std::string yaml = urdf_size < size ? std::string(text + urdf_size + 1, size - urdf_size - 1) : std::string();

  try {
    CheckTree(ParseUrdfTree(urdf, kUrdfSource));
  } catch (const ConfigError& e) {
    CheckConfigError(e, kUrdfSource);
  }
  try {
    CheckYaml(ParseRobotYaml(yaml, kYamlSource));
  } catch (const ConfigError& e) {
    CheckConfigError(e, kYamlSource);
  }
  try {
    CheckModel(LoadRobotModelFromStrings(urdf, kUrdfSource, yaml, kYamlSource));
  } catch (const ConfigError& e) {
    CheckErrorNamesSource(e, e.file());
    FuzzCheck(e.file() == kUrdfSource || e.file() == kYamlSource, "a ConfigError names one of the two documents");
  }
  return 0;
}
