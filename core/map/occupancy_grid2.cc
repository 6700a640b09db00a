#include "core/map/occupancy_grid2.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/map/box_cell_overlap.h"

namespace topay {

void ValidateBand(const HeightBand& band, const char* where) {
  if (!std::isfinite(band.z_min_m) || !std::isfinite(band.z_max_m) ||
      !(band.z_min_m < band.z_max_m)) {
    throw std::invalid_argument(std::string(where) +
                                ": height band must be finite with z_min_m < z_max_m, got [" +
                                std::to_string(band.z_min_m) + ", " +
                                std::to_string(band.z_max_m) + "]");
  }
}

OccupancyGrid2::OccupancyGrid2(const GridGeometry2& geometry) : geometry_(geometry) {
  geometry_.Validate("OccupancyGrid2");
  cells_.assign(static_cast<std::size_t>(geometry_.NumCells()), 0);
}

OccupancyGrid2 OccupancyGrid2::ProjectBand(const OccupancyGrid3& grid, const HeightBand& band) {
  ValidateBand(band, "OccupancyGrid2::ProjectBand");
  const GridGeometry3& g3 = grid.geometry();
  OccupancyGrid2 result(GridGeometry2::FootprintOf(g3));
  const CellRange layers = CellsOverlapping(band.z_min_m, band.z_max_m, g3.origin_W_m.z(),
                                            g3.resolution_m, g3.dims.z());
  const std::int64_t layer_size = result.geometry_.NumCells();
  const std::uint8_t* cells3 = grid.cells().data();
  std::uint8_t* cells2 = result.cells_.data();
  for (int iz = layers.begin; iz < layers.end; ++iz) {
    const std::uint8_t* layer = cells3 + iz * layer_size;
    for (std::int64_t i = 0; i < layer_size; ++i) cells2[i] |= layer[i];
  }
  return result;
}

void OccupancyGrid2::AddFootprint(const OrientedBox& box) {
  ValidateBox(box, "OccupancyGrid2::AddFootprint");
  const GridGeometry2& g = geometry_;
  const Eigen::AlignedBox3d bounds = box.WorldBounds();
  CellRange range[2];
  for (int a = 0; a < 2; ++a) {
    range[a] = CellsOverlapping(bounds.min()(a), bounds.max()(a), g.origin_W_m(a),
                                g.resolution_m, g.dims(a));
    if (range[a].empty()) return;
  }
  const FootprintCellOverlap footprint(box, g.resolution_m);
  for (int iy = range[1].begin; iy < range[1].end; ++iy) {
    for (int ix = range[0].begin; ix < range[0].end; ++ix) {
      if (footprint.Overlaps(g.CellCenter(ix, iy))) cells_[g.Index(ix, iy)] = 1;
    }
  }
}

bool OccupancyGrid2::AddBoxInBand(const OrientedBox& box, const HeightBand& band) {
  ValidateBox(box, "OccupancyGrid2::AddBoxInBand");
  ValidateBand(band, "OccupancyGrid2::AddBoxInBand");
  const double half_height = 0.5 * box.size_m.z();
  const bool overlaps = box.center_W_m.z() - half_height < band.z_max_m &&
                        box.center_W_m.z() + half_height > band.z_min_m;
  if (overlaps) AddFootprint(box);
  return overlaps;
}

bool OccupancyGrid2::MarkPoint(const Eigen::Vector2d& p_W) {
  if (!geometry_.Contains(p_W)) {
    ++num_points_outside_;
    return false;
  }
  const Eigen::Vector2i cell =
      geometry_.CellOf(p_W).cwiseMax(0).cwiseMin(geometry_.dims - Eigen::Vector2i::Ones());
  cells_[geometry_.Index(cell.x(), cell.y())] = 1;
  return true;
}

void OccupancyGrid2::ClearAll() {
  std::fill(cells_.begin(), cells_.end(), std::uint8_t{0});
  num_points_outside_ = 0;
}

std::int64_t OccupancyGrid2::CountOccupied() const {
  return std::count(cells_.begin(), cells_.end(), std::uint8_t{1});
}

}  // namespace topay
