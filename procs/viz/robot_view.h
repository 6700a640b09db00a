#pragma once
// The robot as the viewer draws it: each link's visual geometry from the URDF (boxes,
// cylinders, spheres; meshes are skipped) and, per robot state, every link's pose X_WL from the
// core's forward kinematics (docs/viewer.md: RobotDescription, RobotState).

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"

namespace topay::viz {

/// One visual of a link: a primitive at X_LV in the link frame L.
struct LinkVisual {
  std::string shape;          ///< "box", "cylinder" (axis z of V) or "sphere"
  Eigen::Vector3d size_m;     ///< box edges; cylinder 2r, 2r, length; sphere 2r, 2r, 2r
  Eigen::Isometry3d X_LV = Eigen::Isometry3d::Identity();
  Eigen::Vector4d rgba{0.7, 0.7, 0.72, 1.0};
};

/// The visuals of every link of `model`, in model order (a link without a primitive visual has
/// none). Reads the URDF text with urdfdom; throws topay::ConfigError naming `source` and the
/// link if the document does not parse or a visual's size is not finite and positive.
std::vector<std::vector<LinkVisual>> ParseLinkVisuals(const RobotModel& model, const std::string& urdf_text,
                                                      const std::string& source);

/// The robot's model and visuals, and its drawing per state.
class RobotView {
 public:
  /// Loads the URDF and the robot YAML (core/io/robot_loader.h); throws ConfigError.
  RobotView(const std::string& urdf_path, const std::string& yaml_path);

  const RobotModel& model() const { return *model_; }
  const Kinematics& kinematics() const { return *kinematics_; }

  /// The RobotDescription payload.
  nlohmann::json Description() const;

  /// The RobotState payload for a state (t in s); throws std::invalid_argument if the state
  /// does not fit the model (wrong joint count, NaN).
  nlohmann::json State(double t, const WholeBodyState& state, double v_mps, double omega_radps,
                       double gripper) const;

  /// p_WE of a state (for the end-effector path).
  Eigen::Vector3d EndEffectorPosition(const WholeBodyState& state) const;

  /// Centre and radius of a collision body named as the simulator's monitor names it
  /// ("base", "sphere 5 (link link4)", "self: sphere 3 - sphere 11" and "chassis: sphere 4 (...)": the first sphere), placed
  /// at `state`; false if the name is none of those.
  bool BodyPlace(const std::string& body, const WholeBodyState& state, Eigen::Vector3d* p_W_m,
                 double* radius_m) const;

 private:
  std::unique_ptr<RobotModel> model_;
  std::unique_ptr<Kinematics> kinematics_;
  std::vector<std::vector<LinkVisual>> visuals_;
  mutable KinematicsCache cache_;
};

/// [w, x, y, z] and [x, y, z] of a pose, for JSON.
nlohmann::json QuaternionJson(const Eigen::Quaterniond& q);
nlohmann::json VectorJson(const Eigen::Vector3d& v);

}  // namespace topay::viz
