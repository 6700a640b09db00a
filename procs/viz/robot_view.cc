#include "procs/viz/robot_view.h"

#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <regex>
#include <stdexcept>

#include "core/common/error.h"
#include "core/io/bounded_text_file.h"
#include "core/io/robot_loader.h"

namespace topay::viz {
namespace {

Eigen::Isometry3d PoseOf(const urdf::Pose& pose) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(pose.position.x, pose.position.y, pose.position.z);
  const urdf::Rotation& r = pose.rotation;
  X.linear() = Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix();
  return X;
}

/// The primitive of a URDF visual, or nullopt for a mesh (or no geometry).
std::optional<LinkVisual> PrimitiveOf(const urdf::Visual& visual) {
  if (!visual.geometry) return std::nullopt;
  LinkVisual out;
  const urdf::Geometry& g = *visual.geometry;
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& box = static_cast<const urdf::Box&>(g);
      out.shape = "box";
      out.size_m = Eigen::Vector3d(box.dim.x, box.dim.y, box.dim.z);
      break;
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      out.shape = "cylinder";
      out.size_m = Eigen::Vector3d(2 * c.radius, 2 * c.radius, c.length);
      break;
    }
    case urdf::Geometry::SPHERE: {
      const auto& s = static_cast<const urdf::Sphere&>(g);
      out.shape = "sphere";
      out.size_m = Eigen::Vector3d::Constant(2 * s.radius);
      break;
    }
    default:
      return std::nullopt;
  }
  out.X_LV = PoseOf(visual.origin);
  if (visual.material) {
    const urdf::Color& c = visual.material->color;
    if (c.a > 0 || c.r > 0 || c.g > 0 || c.b > 0) out.rgba = Eigen::Vector4d(c.r, c.g, c.b, c.a);
  }
  return out;
}

void CheckVisual(const LinkVisual& v, const std::string& source, const std::string& link) {
  if (!v.size_m.allFinite() || (v.size_m.array() <= 0).any() || !v.X_LV.matrix().allFinite()) {
    throw ConfigError(source, "link " + link + " visual", "a " + v.shape + " of non-finite or non-positive size");
  }
}

}  // namespace

std::vector<std::vector<LinkVisual>> ParseLinkVisuals(const RobotModel& model, const std::string& urdf_text,
                                                      const std::string& source) {
  const urdf::ModelInterfaceSharedPtr urdf = urdf::parseURDF(urdf_text);
  if (!urdf) throw ConfigError(source, "robot", "the URDF does not parse");
  std::vector<std::vector<LinkVisual>> visuals(model.links.size());
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const urdf::LinkConstSharedPtr link = urdf->getLink(model.links[i].name);
    if (!link) continue;
    for (const urdf::VisualSharedPtr& visual : link->visual_array) {
      if (!visual) continue;
      if (std::optional<LinkVisual> v = PrimitiveOf(*visual)) {
        CheckVisual(*v, source, link->name);
        visuals[i].push_back(*v);
      }
    }
  }
  return visuals;
}

nlohmann::json QuaternionJson(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }
nlohmann::json VectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

RobotView::RobotView(const std::string& urdf_path, const std::string& yaml_path)
    : model_(std::make_unique<RobotModel>(LoadRobotModel(urdf_path, yaml_path))),
      kinematics_(std::make_unique<Kinematics>(*model_)),
      cache_(kinematics_->MakeCache()) {
  visuals_ = ParseLinkVisuals(*model_, ReadBoundedTextFile(urdf_path, kMaxConfigFileBytes, "robot URDF"), urdf_path);
}

nlohmann::json RobotView::Description() const {
  nlohmann::json links = nlohmann::json::array();
  for (std::size_t i = 0; i < model_->links.size(); ++i) {
    nlohmann::json visuals = nlohmann::json::array();
    for (const LinkVisual& v : visuals_[i]) {
      visuals.push_back({{"shape", v.shape},
                         {"size_m", VectorJson(v.size_m)},
                         {"p_LV_m", VectorJson(v.X_LV.translation())},
                         {"quat_LV", QuaternionJson(Eigen::Quaterniond(v.X_LV.linear()))},
                         {"rgba", {v.rgba[0], v.rgba[1], v.rgba[2], v.rgba[3]}}});
    }
    links.push_back({{"name", model_->links[i].name}, {"visuals", std::move(visuals)}});
  }
  return {{"name", model_->name},
          {"joint_names", model_->joint_names},
          {"base", {{"radius_m", model_->base_cylinder.radius_m}, {"height_m", model_->base_cylinder.height_m}}},
          {"links", std::move(links)}};
}

nlohmann::json RobotView::State(double t, const WholeBodyState& state, double v_mps, double omega_radps,
                                double gripper) const {
  kinematics_->Update(state, &cache_);
  nlohmann::json links = nlohmann::json::array();
  for (const Eigen::Isometry3d& X_WL : cache_.X_WL) {
    links.push_back({{"p_WL_m", VectorJson(X_WL.translation())},
                     {"quat_WL", QuaternionJson(Eigen::Quaterniond(X_WL.linear()))}});
  }
  nlohmann::json q = nlohmann::json::array();
  for (int j = 0; j < state.num_joints(); ++j) q.push_back(state.q_rad[j]);
  return {{"t", t},
          {"x_m", state.x_m},
          {"y_m", state.y_m},
          {"yaw_rad", state.yaw_rad},
          {"v_mps", v_mps},
          {"omega_radps", omega_radps},
          {"q_rad", std::move(q)},
          {"gripper", std::isfinite(gripper) ? nlohmann::json(gripper) : nlohmann::json(nullptr)},
          {"links", std::move(links)},
          {"p_WE_m", VectorJson(cache_.X_WE.translation())}};
}

Eigen::Vector3d RobotView::EndEffectorPosition(const WholeBodyState& state) const {
  kinematics_->Update(state, &cache_);
  return cache_.X_WE.translation();
}

bool RobotView::BodyPlace(const std::string& body, const WholeBodyState& state, Eigen::Vector3d* p_W_m,
                          double* radius_m) const {
  kinematics_->Update(state, &cache_);
  if (body == "base") {
    *p_W_m = cache_.X_WB * Eigen::Vector3d(0, 0, 0.5 * model_->base_cylinder.height_m);
    *radius_m = model_->base_cylinder.radius_m;
    return true;
  }
  static const std::regex kSphere(R"(^(?:self: |chassis: )?sphere (\d+).*)");
  std::smatch match;
  if (!std::regex_match(body, match, kSphere)) return false;
  const long index = std::stol(match[1].str());
  if (index < 0 || index >= static_cast<long>(model_->spheres.size())) return false;
  *p_W_m = cache_.p_WS[index];
  *radius_m = model_->spheres[index].radius_m;
  return true;
}

}  // namespace topay::viz
