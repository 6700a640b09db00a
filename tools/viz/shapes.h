#pragma once

#include <array>

#include <Eigen/Core>

namespace topay::viz {

/// Corners, counter-clockwise, of a rectangle of full side lengths size_m (along its own x, y)
/// centred at centre_W and turned by yaw_rad about the vertical:
///   p_i = centre + R(yaw) (+-size_x / 2, +-size_y / 2).
std::array<Eigen::Vector2d, 4> RectangleCorners(const Eigen::Vector2d& centre_W_m,
                                                const Eigen::Vector2d& size_m, double yaw_rad);

/// The three corners of an arrow head: tip at `tip`, pointing along the unit vector
/// `direction`, `length` long and `width` wide at its base (any consistent unit).
std::array<Eigen::Vector2d, 3> ArrowHead(const Eigen::Vector2d& tip,
                                         const Eigen::Vector2d& direction, double length,
                                         double width);

}  // namespace topay::viz
