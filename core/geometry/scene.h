#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/oriented_box.h"

namespace topay {

/// The exact geometry of a world: upright boxes (walls, obstacles, table parts) and the volume
/// the maps cover. This is the ground truth that distance fields approximate and that the
/// independent validator checks against. Files: sim/scenes/scene_json.h.
struct Scene {
  std::vector<OrientedBox> boxes;
  /// Volume covered by maps built from this scene (for the benchmark rooms: the 20 x 20 m
  /// floor with its walls, z from 0 to 1.6 m).
  Eigen::AlignedBox3d bounds_W_m{Eigen::Vector3d(-10.0, -10.0, 0.0),
                                 Eigen::Vector3d(10.0, 10.0, 1.6)};
  std::string kind;   ///< "cuboids", "tables", or free text for hand-made scenes.
  std::uint64_t seed = 0;  ///< Generator seed, 0 for hand-made scenes.
};

}  // namespace topay
