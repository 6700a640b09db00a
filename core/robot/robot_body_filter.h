#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"

namespace topay {

/// The robot's own collision model at one state, inflated by a margin, as a point test: what
/// the scan filter removes so that the robot does not map itself. The body is the one the
/// simulator's LiDAR sees (sim/lidar/robot_body_rays.h): the base cylinder
/// (RobotModel::base_cylinder about the base axis, from the ground to the chassis top) and
/// every arm collision sphere at the Kinematics sphere centres; inflated, the cylinder grows
/// by the margin radially and at both ends, each sphere's radius by the margin.
/// Allocation-free after the first Update for a model.
class RobotBodyFilter {
 public:
  /// `margin_m` must be finite and >= 0 (std::invalid_argument otherwise).
  explicit RobotBodyFilter(double margin_m);

  /// The body at the state of `cache` (updated by a Kinematics of `model`).
  void Update(const RobotModel& model, const KinematicsCache& cache);

  /// True if p_W lies in the inflated body (boundary included).
  bool Contains(const Eigen::Vector3f& p_W) const;

  /// Removes the points in the inflated body, keeping the others' order; returns how many
  /// were removed.
  int RemoveFrom(std::vector<Eigen::Vector3f>* p_WP) const;

  double margin_m() const { return margin_m_; }
  /// A box holding the whole inflated body (points outside it are kept at once).
  const Eigen::AlignedBox3f& bounds_W() const { return bounds_W_; }

 private:
  struct Sphere {
    Eigen::Vector3f p_WC;   // centre
    float radius_squared;  // (radius + margin)^2
  };
  double margin_m_ = 0.0;
  std::vector<Sphere> spheres_;
  Eigen::Vector2f p_WA_xy_ = Eigen::Vector2f::Zero();  // the base axis, in xy
  float cylinder_radius_squared_ = 0.0f;
  float cylinder_z_min_ = 0.0f;
  float cylinder_z_max_ = 0.0f;
  Eigen::AlignedBox3f bounds_W_;
};

}  // namespace topay
