#include "core/geometry/primitive_box_distance.h"

#include <algorithm>
#include <cmath>

namespace topay {

double SignedDistanceSphereToBox(const OrientedBox& box, const Eigen::Vector3d& p_WS,
                                 double radius_m) {
  // Rounded-box identity: phi = d_box(p_WS) - r.
  return SignedDistanceToBox(box, p_WS) - radius_m;
}

double CombineProductSignedDistance(double phi_xy_m, double phi_z_m) {
  if (phi_xy_m > 0.0 || phi_z_m > 0.0) {
    // Distance between products: sqrt(d_xy^2 + d_z^2) of the non-negative parts.
    const double dxy = std::max(phi_xy_m, 0.0);
    const double dz = std::max(phi_z_m, 0.0);
    return std::hypot(dxy, dz);
  }
  // Both overlap: the shorter of the two separating translations.
  return std::max(phi_xy_m, phi_z_m);
}

double SignedDistanceCylinderToBox(const OrientedBox& box, const VerticalCylinder& cylinder) {
  // Disc vs rectangle: phi_xy = d_rect(axis) - r (rounded rectangle).
  const double phi_xy = SignedDistanceToFootprint(box, cylinder.axis_W_m) - cylinder.radius_m;
  // Signed gap of the z intervals [box_bottom, box_top] and [cyl_bottom, cyl_top].
  const double half_height = 0.5 * box.size_m.z();
  const double box_bottom = box.center_W_m.z() - half_height;
  const double box_top = box.center_W_m.z() + half_height;
  const double phi_z =
      std::max(box_bottom - cylinder.top_z_m(), cylinder.bottom_z_m - box_top);
  return CombineProductSignedDistance(phi_xy, phi_z);
}

}  // namespace topay
