#pragma once

// Test helper, independent of the separating-axis code under test: area of the intersection
// of an upright box's footprint with an axis-aligned square, by Sutherland-Hodgman clipping of
// the footprint rectangle against the square's four half-planes, then the shoelace formula.

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"

namespace topay::testing {

inline std::vector<Eigen::Vector2d> FootprintCorners(const OrientedBox& box) {
  const double c = std::cos(box.yaw_rad), s = std::sin(box.yaw_rad);
  const Eigen::Vector2d hx = 0.5 * box.size_m.x() * Eigen::Vector2d(c, s);
  const Eigen::Vector2d hy = 0.5 * box.size_m.y() * Eigen::Vector2d(-s, c);
  const Eigen::Vector2d o = box.center_W_m.head<2>();
  return {o - hx - hy, o + hx - hy, o + hx + hy, o - hx + hy};
}

// Keeps the part of the polygon where sign * (p(axis) - limit) <= 0.
inline std::vector<Eigen::Vector2d> ClipHalfPlane(const std::vector<Eigen::Vector2d>& polygon,
                                                  int axis, double limit, double sign) {
  std::vector<Eigen::Vector2d> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % n];
    const double fa = sign * (a(axis) - limit);
    const double fb = sign * (b(axis) - limit);
    if (fa <= 0.0) out.push_back(a);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0)) {
      out.push_back(a + (fa / (fa - fb)) * (b - a));
    }
  }
  return out;
}

inline double PolygonArea(const std::vector<Eigen::Vector2d>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * std::abs(twice);
}

// Area of footprint(box) intersected with the square [lo, hi].
inline double FootprintSquareOverlapArea(const OrientedBox& box, const Eigen::Vector2d& lo,
                                         const Eigen::Vector2d& hi) {
  std::vector<Eigen::Vector2d> polygon = FootprintCorners(box);
  for (int axis = 0; axis < 2; ++axis) {
    polygon = ClipHalfPlane(polygon, axis, hi(axis), 1.0);
    polygon = ClipHalfPlane(polygon, axis, lo(axis), -1.0);
  }
  return PolygonArea(polygon);
}

}  // namespace topay::testing
