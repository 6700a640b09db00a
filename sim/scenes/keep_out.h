#pragma once

#include <vector>

#include "core/geometry/oriented_box.h"
#include "core/geometry/vertical_cylinder.h"

namespace topay {

/// Regions no generated obstacle may enter (e.g. around a task's start and goal base poses),
/// given by the caller as upright cylinders ("discs" extruded over a height) and boxes.
struct KeepOutRegions {
  std::vector<VerticalCylinder> cylinders;
  std::vector<OrientedBox> boxes;

  /// True if `obstacle` enters none of the regions: its signed distance to every cylinder is
  /// >= 0 (exact, SignedDistanceCylinderToBox) and its interior meets no box (BoxesOverlap).
  bool Admits(const OrientedBox& obstacle) const;
};

}  // namespace topay
