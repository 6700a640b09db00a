#include "core/io/robot_yaml.h"

#include <cmath>
#include <set>

#include <yaml-cpp/yaml.h>

#include "core/common/error.h"

namespace topay {
namespace {

// Reads typed, validated values from YAML nodes; every error names the file and field path.
class YamlReader {
 public:
  explicit YamlReader(const std::string& source) : source_(source) {}

  [[noreturn]] void Fail(const std::string& path, const std::string& message) const {
    throw ConfigError(source_, path, message);
  }

  YAML::Node Map(const YAML::Node& node, const std::string& path,
                 const std::set<std::string>& allowed_keys) const {
    if (!node.IsMap()) Fail(path, "must be a map");
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      if (!allowed_keys.count(key)) Fail(Join(path, key), "unknown field");
    }
    return node;
  }

  YAML::Node Required(const YAML::Node& map, const std::string& path,
                      const std::string& key) const {
    const YAML::Node child = map[key];
    if (!child) Fail(Join(path, key), "missing");
    return child;
  }

  double Number(const YAML::Node& node, const std::string& path) const {
    double value = 0.0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
      Fail(path, "must be a number");
    }
    if (!std::isfinite(value)) Fail(path, "must be finite");
    return value;
  }

  double Positive(const YAML::Node& node, const std::string& path) const {
    const double value = Number(node, path);
    if (!(value > 0.0)) Fail(path, "must be positive, got " + std::to_string(value));
    return value;
  }

  std::string String(const YAML::Node& node, const std::string& path) const {
    if (!node.IsScalar() || node.Scalar().empty()) Fail(path, "must be a non-empty string");
    return node.Scalar();
  }

  std::vector<double> Numbers(const YAML::Node& node, const std::string& path,
                              bool positive) const {
    if (!node.IsSequence()) Fail(path, "must be a list of numbers");
    std::vector<double> values;
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string item = path + "[" + std::to_string(i) + "]";
      values.push_back(positive ? Positive(node[i], item) : Number(node[i], item));
    }
    return values;
  }

  Eigen::Vector3d Vector3(const YAML::Node& node, const std::string& path) const {
    const std::vector<double> values = Numbers(node, path, false);
    if (values.size() != 3) Fail(path, "must have 3 numbers, got " + std::to_string(values.size()));
    return Eigen::Vector3d(values[0], values[1], values[2]);
  }

  static std::string Join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  const std::string& source_;
};

BaseCylinder ReadBaseCylinder(const YamlReader& in, const YAML::Node& root) {
  const std::string path = "base_cylinder";
  const YAML::Node node = in.Map(in.Required(root, "", path), path, {"radius", "height"});
  BaseCylinder cylinder;
  cylinder.radius_m = in.Positive(in.Required(node, path, "radius"), path + ".radius");
  cylinder.height_m = in.Positive(in.Required(node, path, "height"), path + ".height");
  return cylinder;
}

std::vector<YamlSphere> ReadSpheres(const YamlReader& in, const YAML::Node& root) {
  const YAML::Node list = in.Required(root, "", "spheres");
  if (!list.IsSequence() || list.size() == 0) in.Fail("spheres", "must be a non-empty list");
  std::vector<YamlSphere> spheres;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = "spheres[" + std::to_string(i) + "]";
    const YAML::Node node = in.Map(list[i], path, {"link", "xyz", "radius"});
    YamlSphere sphere;
    sphere.link = in.String(in.Required(node, path, "link"), path + ".link");
    sphere.p_LS_m = in.Vector3(in.Required(node, path, "xyz"), path + ".xyz");
    sphere.radius_m = in.Positive(in.Required(node, path, "radius"), path + ".radius");
    spheres.push_back(sphere);
  }
  return spheres;
}

BaseLimits ReadBaseLimits(const YamlReader& in, const YAML::Node& root) {
  const std::string path = "base_limits";
  const YAML::Node node =
      in.Map(in.Required(root, "", path), path, {"v_max", "a_max", "omega_max", "beta_max"});
  auto read = [&](const char* key) {
    return in.Positive(in.Required(node, path, key), path + "." + key);
  };
  BaseLimits limits;
  limits.v_max_mps = read("v_max");
  limits.a_max_mps2 = read("a_max");
  limits.omega_max_radps = read("omega_max");
  limits.beta_max_radps2 = read("beta_max");
  return limits;
}

void ReadJointLimits(const YamlReader& in, const YAML::Node& root, RobotYaml* out) {
  const std::string path = "joint_limits";
  const YAML::Node node = in.Map(in.Required(root, "", path), path,
                                 {"velocity", "acceleration", "position_lower", "position_upper"});
  out->qd_max_radps = in.Numbers(in.Required(node, path, "velocity"), path + ".velocity", true);
  out->qdd_max_radps2 =
      in.Numbers(in.Required(node, path, "acceleration"), path + ".acceleration", true);
  if (node["position_lower"] || node["position_upper"]) {
    out->q_min_rad =
        in.Numbers(in.Required(node, path, "position_lower"), path + ".position_lower", false);
    out->q_max_rad =
        in.Numbers(in.Required(node, path, "position_upper"), path + ".position_upper", false);
  }
}

// E fixed to `link`: X_LE = Trans(xyz) * Rz(yaw) * Ry(pitch) * Rx(roll) (URDF rpy convention).
void ReadEndEffector(const YamlReader& in, const YAML::Node& root, RobotYaml* out) {
  const std::string path = "end_effector";
  const YAML::Node node = in.Map(in.Required(root, "", path), path, {"link", "xyz", "rpy"});
  out->end_effector_link = in.String(in.Required(node, path, "link"), path + ".link");
  const Eigen::Vector3d xyz = in.Vector3(in.Required(node, path, "xyz"), path + ".xyz");
  const Eigen::Vector3d rpy = in.Vector3(in.Required(node, path, "rpy"), path + ".rpy");
  out->X_LE = Eigen::Isometry3d::Identity();
  out->X_LE.translation() = xyz;
  out->X_LE.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                        Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                        Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                           .toRotationMatrix();
}

YAML::Node LoadYaml(const std::string& yaml_text, const std::string& source) {
  try {
    return YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source, "line " + std::to_string(e.mark.line + 1),
                      "malformed YAML: " + e.msg);
  }
}

}  // namespace

RobotYaml ParseRobotYaml(const std::string& yaml_text, const std::string& source) {
  const YAML::Node document = LoadYaml(yaml_text, source);
  const YamlReader in(source);
  if (!document.IsMap())
    in.Fail("(document)", "must be a map of the fields in config/robot/README.md");
  RobotYaml out;
  try {
    const YAML::Node root = in.Map(
        document, "",
        {"base_link", "base_cylinder", "spheres", "base_limits", "joint_limits", "end_effector",
         "stow_q"});
    out.base_link = in.String(in.Required(root, "", "base_link"), "base_link");
    out.base_cylinder = ReadBaseCylinder(in, root);
    out.spheres = ReadSpheres(in, root);
    out.base_limits = ReadBaseLimits(in, root);
    ReadJointLimits(in, root, &out);
    ReadEndEffector(in, root, &out);
    if (root["stow_q"]) out.stow_q_rad = in.Numbers(root["stow_q"], "stow_q", false);
  } catch (const YAML::Exception& e) {  // e.g. a key that is not a string
    throw ConfigError(source, "line " + std::to_string(e.mark.line + 1), e.msg);
  }
  return out;
}

}  // namespace topay
