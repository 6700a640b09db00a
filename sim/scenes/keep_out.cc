#include "sim/scenes/keep_out.h"

#include "core/geometry/box_overlap.h"
#include "core/geometry/primitive_box_distance.h"

namespace topay {

bool KeepOutRegions::Admits(const OrientedBox& obstacle) const {
  for (const VerticalCylinder& cylinder : cylinders) {
    if (SignedDistanceCylinderToBox(obstacle, cylinder) < 0.0) return false;
  }
  for (const OrientedBox& box : boxes) {
    if (BoxesOverlap(box, obstacle)) return false;
  }
  return true;
}

}  // namespace topay
