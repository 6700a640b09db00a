#pragma once

#include <Eigen/Core>

namespace topay {

/// An upright solid cylinder in the world W: axis parallel to W's z axis through (x, y) =
/// axis_W_m, radius radius_m, spanning z in [bottom_z_m, bottom_z_m + height_m]. The robot's
/// base collision solid is one with bottom_z_m = 0 (see BaseCylinder in core/robot).
struct VerticalCylinder {
  Eigen::Vector2d axis_W_m = Eigen::Vector2d::Zero();  ///< (x, y) of the axis in W.
  double radius_m = 0.0;
  double bottom_z_m = 0.0;
  double height_m = 0.0;

  double top_z_m() const { return bottom_z_m + height_m; }
};

}  // namespace topay
