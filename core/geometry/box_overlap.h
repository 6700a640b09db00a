#pragma once

#include "core/geometry/oriented_box.h"

namespace topay {

/// True if the interiors of two upright boxes intersect (touching faces do not count).
/// Exact: the z intervals must overlap and the footprint rectangles must overlap, the latter
/// by the separating axis theorem for two rectangles (the 4 edge normals are the only
/// candidate axes in 2D).
bool BoxesOverlap(const OrientedBox& a, const OrientedBox& b);

}  // namespace topay
