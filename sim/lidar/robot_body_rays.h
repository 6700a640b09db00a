#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/robot/kinematics.h"
#include "core/robot/robot_model.h"

namespace topay::sim {

/// First hits of rays from one origin (the sensor) with the robot's own body at one state:
/// the base cylinder (RobotModel::base_cylinder about the base axis, from the ground to the
/// chassis top) and every arm collision sphere. All rays of a scan share the origin, so the
/// terms of the ray-sphere and ray-cylinder quadratics that do not depend on the direction
/// are computed once per scan (Update); Entry then costs a few products per primitive.
/// Same results as RaySphereEntry / RayCylinderEntry (ray_primitives.h) up to rounding.
class RobotBodyRays {
 public:
  /// The robot at the state of `cache` (updated by a Kinematics of `model`), rays from p_WO.
  /// Allocation-free after the first call for a model.
  void Update(const RobotModel& model, const KinematicsCache& cache, const Eigen::Vector3d& p_WO);

  /// The smallest t >= 0 at which p_WO + t d_W (d_W unit) is in the body; kNoHit if never.
  double Entry(const Eigen::Vector3d& d_W) const;

 private:
  struct Sphere {
    Eigen::Vector3d oc;  // p_WO - centre
    double c;            // |oc|^2 - r^2 (< 0: the origin is inside)
  };
  std::vector<Sphere> spheres_;
  Eigen::Vector2d o_xy_ = Eigen::Vector2d::Zero();  // p_WO - axis, in xy
  double cylinder_c_ = 0.0;                         // |o_xy|^2 - r^2
  double o_z_ = 0.0;
  double height_m_ = 0.0;
};

}  // namespace topay::sim
