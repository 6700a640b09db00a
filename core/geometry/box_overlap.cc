#include "core/geometry/box_overlap.h"

#include <cmath>

namespace topay {
namespace {

// Half extent of a yawed rectangle (half sizes h, yaw) projected on the unit axis u:
// |u . e_x| h_x + |u . e_y| h_y, with e_x, e_y the rectangle's edge directions.
double ProjectedHalfExtent(const Eigen::Vector2d& half_size, double yaw_rad,
                           const Eigen::Vector2d& u) {
  const Eigen::Vector2d ex(std::cos(yaw_rad), std::sin(yaw_rad));
  const Eigen::Vector2d ey(-ex.y(), ex.x());
  return std::abs(u.dot(ex)) * half_size.x() + std::abs(u.dot(ey)) * half_size.y();
}

bool FootprintsOverlap(const OrientedBox& a, const OrientedBox& b) {
  const Eigen::Vector2d d = b.center_W_m.head<2>() - a.center_W_m.head<2>();
  const Eigen::Vector2d ha = a.HalfSize().head<2>();
  const Eigen::Vector2d hb = b.HalfSize().head<2>();
  for (const double yaw : {a.yaw_rad, b.yaw_rad}) {
    const Eigen::Vector2d ex(std::cos(yaw), std::sin(yaw));
    for (const Eigen::Vector2d& u : {ex, Eigen::Vector2d(-ex.y(), ex.x())}) {
      // Separating axis theorem: separated along u if |d.u| >= r_a(u) + r_b(u).
      const double reach = ProjectedHalfExtent(ha, a.yaw_rad, u) +
                           ProjectedHalfExtent(hb, b.yaw_rad, u);
      if (std::abs(d.dot(u)) >= reach) return false;
    }
  }
  return true;
}

}  // namespace

bool BoxesOverlap(const OrientedBox& a, const OrientedBox& b) {
  const double gap_z = std::abs(a.center_W_m.z() - b.center_W_m.z()) -
                       0.5 * (a.size_m.z() + b.size_m.z());
  if (gap_z >= 0.0) return false;
  return FootprintsOverlap(a, b);
}

}  // namespace topay
