#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay {

/// A box standing upright in the world W: rotated by yaw about the world z axis only. This is
/// the obstacle primitive of the benchmark scenes (walls, cuboids, table tops and legs).
struct OrientedBox {
  Eigen::Vector3d center_W_m = Eigen::Vector3d::Zero();  ///< Centre of the box in W.
  Eigen::Vector3d size_m = Eigen::Vector3d::Ones();      ///< Full side lengths (x, y, z) in B.
  double yaw_rad = 0.0;                                  ///< Rotation of B about W's z axis.

  Eigen::Vector3d HalfSize() const { return 0.5 * size_m; }

  /// Position of a world point expressed in the box frame B (origin at the centre).
  Eigen::Vector3d ToBoxFrame(const Eigen::Vector3d& p_W) const;

  /// Axis-aligned bounding box in W.
  Eigen::AlignedBox3d WorldBounds() const;
};

/// Exact signed Euclidean distance (m) from p_W to the box surface: positive outside, negative
/// inside (minus the depth to the nearest face). If gradient_W is not null it receives the
/// unit gradient of the distance with respect to p_W (the zero vector only at the exact centre
/// of a cube, where the distance is not differentiable).
double SignedDistanceToBox(const OrientedBox& box, const Eigen::Vector3d& p_W,
                           Eigen::Vector3d* gradient_W = nullptr);

/// Exact signed distance (m) in the xy plane from a point to the box's footprint rectangle.
double SignedDistanceToFootprint(const OrientedBox& box, const Eigen::Vector2d& p_W);

}  // namespace topay
