#pragma once

#include <algorithm>
#include <limits>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/geometry/vertical_cylinder.h"

namespace topay::sim {

// Exact first hits of a ray p(t) = p_WO + t d_W (d_W a unit vector, t >= 0 in metres) with
// the solids the simulated LiDAR sees. Each returns the smallest t >= 0 at which the ray is in
// the closed solid (0 if the origin is inside it), or +infinity if it never is.

inline constexpr double kNoHit = std::numeric_limits<double>::infinity();

/// Slab test for an axis-aligned box of half sizes h centred at the origin, the ray given in
/// the box's own frame (o_B, d_B): on each axis the ray is between the two faces for
/// t in [(-h - o) / d, (h - o) / d] (sorted; all t if d = 0 and |o| <= h, none if d = 0 and
/// |o| > h); the ray is in the box on the intersection [t_near, t_far] of the three intervals.
/// Inline: the ray-casting grid's inner loop.
inline double RayCenteredBoxEntry(const Eigen::Vector3d& o_B, const Eigen::Vector3d& d_B,
                                  const Eigen::Vector3d& half_size_m) {
  double t_near = -kNoHit;
  double t_far = kNoHit;
  for (int i = 0; i < 3; ++i) {
    const double o = o_B(i), d = d_B(i), h = half_size_m(i);
    if (d == 0.0) {  // parallel to the faces: between them for all t or never
      if (o < -h || o > h) return kNoHit;
      continue;
    }
    const double inv = 1.0 / d;
    const double t0 = (-h - o) * inv, t1 = (h - o) * inv;
    t_near = std::max(t_near, std::min(t0, t1));
    t_far = std::min(t_far, std::max(t0, t1));
  }
  if (t_far < 0.0 || t_near > t_far) return kNoHit;
  return std::max(t_near, 0.0);
}

/// An upright box: the ray taken into the box frame B (rotation by -yaw about z, translation
/// by the centre), then the slab test.
double RayBoxEntry(const OrientedBox& box, const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W);

/// A sphere: |o + t d - c|^2 = r^2 is t^2 + 2 b t + c' = 0 with b = d.(o - c),
/// c' = |o - c|^2 - r^2, so t = -b -+ sqrt(b^2 - c').
double RaySphereEntry(const Eigen::Vector3d& p_WC, double radius_m, const Eigen::Vector3d& p_WO,
                      const Eigen::Vector3d& d_W);

/// An upright cylinder: the xy disc gives an interval from the quadratic of the projected ray
/// (a t^2 + 2 b t + c = 0, a = |d_xy|^2, b = d_xy.(o_xy - axis), c = |o_xy - axis|^2 - r^2),
/// the z extent a slab interval; the ray is in the cylinder on their intersection.
double RayCylinderEntry(const VerticalCylinder& cylinder, const Eigen::Vector3d& p_WO,
                        const Eigen::Vector3d& d_W);

/// The floor z = 0 (the half space z <= 0): t = -o_z / d_z for a descending ray.
double RayGroundEntry(const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W);

}  // namespace topay::sim
