#pragma once

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"

namespace topay {

/// Test shorthand for an upright box: centre and full size in metres, yaw in radians.
inline OrientedBox MakeBox(const Eigen::Vector3d& center_W_m, const Eigen::Vector3d& size_m,
                           double yaw_rad = 0.0) {
  OrientedBox box;
  box.center_W_m = center_W_m;
  box.size_m = size_m;
  box.yaw_rad = yaw_rad;
  return box;
}

}  // namespace topay
