#include "core/map/occupancy_grid3.h"

#include <algorithm>

#include "core/map/box_cell_overlap.h"

namespace topay {

OccupancyGrid3::OccupancyGrid3(const GridGeometry3& geometry) : geometry_(geometry) {
  geometry_.Validate("OccupancyGrid3");
  cells_.assign(static_cast<std::size_t>(geometry_.NumCells()), 0);
}

void OccupancyGrid3::AddBox(const OrientedBox& box) {
  ValidateBox(box, "OccupancyGrid3::AddBox");
  const GridGeometry3& g = geometry_;
  const Eigen::AlignedBox3d bounds = box.WorldBounds();
  CellRange range[3];
  for (int a = 0; a < 3; ++a) {
    range[a] = CellsOverlapping(bounds.min()(a), bounds.max()(a), g.origin_W_m(a),
                                g.resolution_m, g.dims(a));
    if (range[a].empty()) return;
  }
  const FootprintCellOverlap footprint(box, g.resolution_m);
  // The z range is exact already (upright box): find the footprint's cells once, then mark
  // their z run in every layer.
  for (int iy = range[1].begin; iy < range[1].end; ++iy) {
    for (int ix = range[0].begin; ix < range[0].end; ++ix) {
      const Eigen::Vector3d center = g.CellCenter(ix, iy, 0);
      if (!footprint.Overlaps(center.head<2>())) continue;
      for (int iz = range[2].begin; iz < range[2].end; ++iz) {
        cells_[g.Index(ix, iy, iz)] = 1;
      }
    }
  }
}

bool OccupancyGrid3::MarkPoint(const Eigen::Vector3d& p_W) {
  if (!geometry_.Contains(p_W)) {
    ++num_points_outside_;
    return false;
  }
  const Eigen::Vector3i cell = geometry_.CellOf(p_W);
  // Contains() used the same arithmetic, so the cell is in range (guard the last ulp anyway).
  const Eigen::Vector3i clamped = cell.cwiseMax(0).cwiseMin(geometry_.dims - Eigen::Vector3i::Ones());
  cells_[geometry_.Index(clamped.x(), clamped.y(), clamped.z())] = 1;
  return true;
}

void OccupancyGrid3::ClearAll() {
  std::fill(cells_.begin(), cells_.end(), std::uint8_t{0});
  num_points_outside_ = 0;
}

std::int64_t OccupancyGrid3::CountOccupied() const {
  return std::count(cells_.begin(), cells_.end(), std::uint8_t{1});
}

}  // namespace topay
