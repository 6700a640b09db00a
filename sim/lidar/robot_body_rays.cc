#include "sim/lidar/robot_body_rays.h"

#include <algorithm>
#include <cmath>

#include "sim/lidar/ray_primitives.h"

namespace topay::sim {
namespace {

// The entry of a ray into a solid occupied on [t_near, t_far], clipped to t >= 0.
double ClippedEntry(double t_near, double t_far) {
  if (t_far < 0.0 || t_near > t_far) return kNoHit;
  return std::max(t_near, 0.0);
}

}  // namespace

void RobotBodyRays::Update(const RobotModel& model, const KinematicsCache& cache,
                           const Eigen::Vector3d& p_WO) {
  spheres_.resize(model.spheres.size());
  for (std::size_t s = 0; s < spheres_.size(); ++s) {
    const Eigen::Vector3d oc = p_WO - cache.p_WS[s];
    const double r = model.spheres[s].radius_m;
    spheres_[s] = {oc, oc.squaredNorm() - r * r};
  }
  o_xy_ = p_WO.head<2>() - cache.X_WB.translation().head<2>();
  const double r = model.base_cylinder.radius_m;
  cylinder_c_ = o_xy_.squaredNorm() - r * r;
  o_z_ = p_WO.z();
  height_m_ = model.base_cylinder.height_m;
}

double RobotBodyRays::Entry(const Eigen::Vector3d& d_W) const {
  double best = kNoHit;
  // Spheres: t^2 + 2 b t + c = 0 with b = d.oc (|d| = 1): t = -b -+ sqrt(b^2 - c).
  for (const Sphere& s : spheres_) {
    const double b = d_W.dot(s.oc);
    if (b > 0.0 && s.c > 0.0) continue;  // outside and moving away
    const double discriminant = b * b - s.c;
    if (discriminant < 0.0) continue;
    const double root = std::sqrt(discriminant);
    best = std::min(best, ClippedEntry(-b - root, -b + root));
  }
  // Cylinder: the z slab [0, height] and the disc's quadratic a t^2 + 2 b t + c = 0 in xy.
  double t_near = -kNoHit, t_far = kNoHit;
  if (d_W.z() == 0.0) {
    if (o_z_ < 0.0 || o_z_ > height_m_) return best;
  } else {
    const double t0 = -o_z_ / d_W.z(), t1 = (height_m_ - o_z_) / d_W.z();
    t_near = std::min(t0, t1);
    t_far = std::max(t0, t1);
    if (t_far < 0.0 || t_near >= best) return best;  // behind, or not before a nearer sphere
  }
  const double a = d_W.x() * d_W.x() + d_W.y() * d_W.y();
  const double b = d_W.x() * o_xy_.x() + d_W.y() * o_xy_.y();
  if (a == 0.0) {
    if (cylinder_c_ > 0.0) return best;
  } else {
    const double discriminant = b * b - a * cylinder_c_;
    if (discriminant < 0.0) return best;
    const double root = std::sqrt(discriminant);
    t_near = std::max(t_near, (-b - root) / a);
    t_far = std::min(t_far, (-b + root) / a);
  }
  return std::min(best, ClippedEntry(t_near, t_far));
}

}  // namespace topay::sim
