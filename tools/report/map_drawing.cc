#include "tools/report/map_drawing.h"

#include <array>

#include "core/map/voxel_state.h"

namespace topay::report {
namespace {

// The index of the highest occupied voxel of column (ix, iy), or -1.
int TopOccupied(const FinalMap& map, int ix, int iy) {
  for (int iz = map.geometry.dims.z() - 1; iz >= 0; --iz) {
    const auto state = static_cast<VoxelState>(map.states[map.geometry.Index(ix, iy, iz)]);
    if (state == VoxelState::kOccupied) return iz;
  }
  return -1;
}

}  // namespace

viz::ScalarRange MapHeightRange(const FinalMap& map) {
  const Eigen::AlignedBox3d bounds = map.geometry.Bounds();
  return {bounds.min().z(), bounds.max().z()};
}

int DrawOccupiedColumns(viz::WorldCanvas* canvas, const FinalMap& map) {
  const GridGeometry3& g = map.geometry;
  const viz::ScalarRange heights = MapHeightRange(map);
  int drawn = 0;
  for (int iy = 0; iy < g.dims.y(); ++iy) {
    for (int ix = 0; ix < g.dims.x(); ++ix) {
      const int iz = TopOccupied(map, ix, iy);
      if (iz < 0) continue;
      const Eigen::Vector3d low = g.origin_W_m + g.resolution_m * Eigen::Vector3d(ix, iy, iz + 1);
      const double r = g.resolution_m;
      const std::array<Eigen::Vector2d, 4> cell = {low.head<2>(), low.head<2>() + Eigen::Vector2d(r, 0),
                                                   low.head<2>() + Eigen::Vector2d(r, r),
                                                   low.head<2>() + Eigen::Vector2d(0, r)};
      canvas->FillPolygon(cell, viz::GreyRamp(heights.Normalize(low.z())));
      ++drawn;
    }
  }
  return drawn;
}

}  // namespace topay::report
