#include "sim/lidar/ray_primitives.h"

#include <algorithm>
#include <cmath>

namespace topay::sim {
namespace {

// Intersects [*t_near, *t_far] with the t interval on which o + t d lies in [lo, hi] along one
// axis. Returns false if the result is empty.
bool ClipSlab(double o, double d, double lo, double hi, double* t_near, double* t_far) {
  if (d == 0.0) return o >= lo && o <= hi;  // parallel: inside for all t or never
  const double inv = 1.0 / d;
  double t0 = (lo - o) * inv;
  double t1 = (hi - o) * inv;
  if (t0 > t1) std::swap(t0, t1);
  *t_near = std::max(*t_near, t0);
  *t_far = std::min(*t_far, t1);
  return *t_near <= *t_far;
}

// The entry of a ray into a solid occupied on [t_near, t_far]: clipped to t >= 0.
double Entry(double t_near, double t_far) {
  if (t_far < 0.0 || t_near > t_far) return kNoHit;
  return std::max(t_near, 0.0);
}

}  // namespace

double RayBoxEntry(const OrientedBox& box, const Eigen::Vector3d& p_WO,
                   const Eigen::Vector3d& d_W) {
  // R_WB = Rz(yaw), so a vector v_W is v_B = Rz(yaw)^T v_W.
  const double c = std::cos(box.yaw_rad), s = std::sin(box.yaw_rad);
  const Eigen::Vector3d r = p_WO - box.center_W_m;
  const Eigen::Vector3d o_B(c * r.x() + s * r.y(), -s * r.x() + c * r.y(), r.z());
  const Eigen::Vector3d d_B(c * d_W.x() + s * d_W.y(), -s * d_W.x() + c * d_W.y(), d_W.z());
  return RayCenteredBoxEntry(o_B, d_B, box.HalfSize());
}

double RaySphereEntry(const Eigen::Vector3d& p_WC, double radius_m, const Eigen::Vector3d& p_WO,
                      const Eigen::Vector3d& d_W) {
  const Eigen::Vector3d oc = p_WO - p_WC;
  const double b = d_W.dot(oc);
  const double c = oc.squaredNorm() - radius_m * radius_m;
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return kNoHit;
  const double root = std::sqrt(discriminant);
  return Entry(-b - root, -b + root);
}

double RayCylinderEntry(const VerticalCylinder& cylinder, const Eigen::Vector3d& p_WO,
                        const Eigen::Vector3d& d_W) {
  double t_near = -kNoHit;
  double t_far = kNoHit;
  if (!ClipSlab(p_WO.z(), d_W.z(), cylinder.bottom_z_m, cylinder.top_z_m(), &t_near, &t_far)) {
    return kNoHit;
  }
  const Eigen::Vector2d o = p_WO.head<2>() - cylinder.axis_W_m;
  const Eigen::Vector2d d = d_W.head<2>();
  const double a = d.squaredNorm();
  const double b = d.dot(o);
  const double c = o.squaredNorm() - cylinder.radius_m * cylinder.radius_m;
  if (a == 0.0) {  // vertical ray: inside the disc for all t or never
    if (c > 0.0) return kNoHit;
  } else {
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) return kNoHit;
    const double root = std::sqrt(discriminant);
    t_near = std::max(t_near, (-b - root) / a);
    t_far = std::min(t_far, (-b + root) / a);
  }
  return Entry(t_near, t_far);
}

double RayGroundEntry(const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W) {
  if (p_WO.z() <= 0.0) return 0.0;  // at or below the floor: inside the solid ground
  if (d_W.z() >= 0.0) return kNoHit;
  return -p_WO.z() / d_W.z();
}

}  // namespace topay::sim
