#pragma once

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/geometry/vertical_cylinder.h"

namespace topay {

// Exact signed distances (m) between the robot's collision primitives and an OrientedBox.
//
// Sign convention (same as SignedDistanceToBox): positive is the Euclidean distance between
// the two solids when they are apart; zero when they touch; negative when they overlap, and
// then minus the penetration depth, i.e. minus the length of the shortest translation of one
// solid that separates them (brings them to touching).

/// Sphere (centre p_WS, radius radius_m) to box. The set of centres at distance d from a box
/// is the box grown by d (a rounded box), so the sphere's signed distance is the centre's
/// signed distance minus the radius, exact both outside and inside:
///   phi = SignedDistanceToBox(box, p_WS) - r.
double SignedDistanceSphereToBox(const OrientedBox& box, const Eigen::Vector3d& p_WS,
                                 double radius_m);

/// Upright cylinder to box. Both solids are products (xy shape) x (z interval) in the same
/// world frame, so with
///   phi_xy = SignedDistanceToFootprint(box, axis) - r   (disc vs rectangle, exact as above)
///   phi_z  = max(box_bottom - cyl_top, cyl_bottom - box_top)   (signed interval gap)
/// the distance of the products is, when apart (either factor apart),
///   phi = sqrt(max(phi_xy, 0)^2 + max(phi_z, 0)^2)
/// (distance between Cartesian products: the squared distances of the factors add), and when
/// overlapping (both factors overlap) a separating translation needs to separate the xy shapes
/// or the z intervals, whichever is shorter:
///   phi = max(phi_xy, phi_z) = -min(depth_xy, depth_z).
double SignedDistanceCylinderToBox(const OrientedBox& box, const VerticalCylinder& cylinder);

/// Combines the signed distances of the two factors of a product of sets (xy shape x
/// z interval) into the signed distance of the products, as documented above.
double CombineProductSignedDistance(double phi_xy_m, double phi_z_m);

}  // namespace topay
