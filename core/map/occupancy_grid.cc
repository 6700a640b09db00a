#include "core/map/occupancy_grid.h"

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

template <int Dim>
OccupancyGrid<Dim>::OccupancyGrid(const Geometry& geometry) : geometry_(geometry) {
  geometry_.Validate(Dim == 2 ? "OccupancyGrid2" : "OccupancyGrid3");
  cells_.assign(static_cast<std::size_t>(geometry_.NumCells()), 0);
}

template <int Dim>
void OccupancyGrid<Dim>::Rasterise(const OrientedBox& box, const char* where) {
  ValidateBox(box, where);
  const Geometry& g = geometry_;
  const Eigen::AlignedBox3d bounds = box.WorldBounds();
  CellRange range[3] = {{0, 0}, {0, 0}, {0, 1}};  // one layer in 2D
  for (int a = 0; a < Dim; ++a) {
    range[a] = CellsOverlapping(bounds.min()(a), bounds.max()(a), g.origin_W_m(a),
                                g.resolution_m, g.dims(a));
    if (range[a].empty()) return;
  }
  const FootprintCellOverlap footprint(box, g.resolution_m);
  // The z range is exact already (upright box): find the footprint's cells once, then mark
  // their z run in every layer.
  const std::int64_t layer = std::int64_t{g.dims.x()} * g.dims.y();
  for (int iy = range[1].begin; iy < range[1].end; ++iy) {
    for (int ix = range[0].begin; ix < range[0].end; ++ix) {
      const Eigen::Vector2d center =
          g.origin_W_m.template head<2>() + g.resolution_m * Eigen::Vector2d(ix + 0.5, iy + 0.5);
      if (!footprint.Overlaps(center)) continue;
      const std::int64_t column = std::int64_t{iy} * g.dims.x() + ix;
      for (int iz = range[2].begin; iz < range[2].end; ++iz) cells_[iz * layer + column] = 1;
    }
  }
}

template <int Dim>
void OccupancyGrid<Dim>::AddBox(const OrientedBox& box)
  requires(Dim == 3)
{
  Rasterise(box, "OccupancyGrid3::AddBox");
}

template <int Dim>
void OccupancyGrid<Dim>::AddFootprint(const OrientedBox& box)
  requires(Dim == 2)
{
  Rasterise(box, "OccupancyGrid2::AddFootprint");
}

template <int Dim>
bool OccupancyGrid<Dim>::AddBoxInBand(const OrientedBox& box, const HeightBand& band)
  requires(Dim == 2)
{
  ValidateBox(box, "OccupancyGrid2::AddBoxInBand");
  ValidateBand(band, "OccupancyGrid2::AddBoxInBand");
  const double half_height = 0.5 * box.size_m.z();
  const bool overlaps = box.center_W_m.z() - half_height < band.z_max_m &&
                        box.center_W_m.z() + half_height > band.z_min_m;
  if (overlaps) AddFootprint(box);
  return overlaps;
}

template <int Dim>
OccupancyGrid<Dim> OccupancyGrid<Dim>::ProjectBand(const OccupancyGrid<3>& grid,
                                                   const HeightBand& band)
  requires(Dim == 2)
{
  ValidateBand(band, "OccupancyGrid2::ProjectBand");
  const GridGeometry3& g3 = grid.geometry();
  OccupancyGrid result(GridGeometry2::FootprintOf(g3));
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

template <int Dim>
bool OccupancyGrid<Dim>::MarkPoint(const Point& p_W) {
  if (!geometry_.Contains(p_W)) {
    ++num_points_outside_;
    return false;
  }
  using Cell = Eigen::Matrix<int, Dim, 1>;
  // Contains() used the same arithmetic, so the cell is in range (guard the last ulp anyway).
  const Cell cell = geometry_.CellOf(p_W).cwiseMax(0).cwiseMin(geometry_.dims - Cell::Ones());
  std::int64_t index = 0;
  for (int a = Dim - 1; a >= 0; --a) index = index * geometry_.dims(a) + cell(a);
  cells_[index] = 1;
  return true;
}

template <int Dim>
void OccupancyGrid<Dim>::ClearAll() {
  std::fill(cells_.begin(), cells_.end(), std::uint8_t{0});
  num_points_outside_ = 0;
}

template <int Dim>
std::int64_t OccupancyGrid<Dim>::CountOccupied() const {
  return std::count(cells_.begin(), cells_.end(), std::uint8_t{1});
}

// Member by member rather than `template class`: clang 14 (Debian 12's, used by `make fuzz`)
// instantiates the members constrained to the other dimension too and fails.
template OccupancyGrid<2>::OccupancyGrid(const GridGeometry2&);
template OccupancyGrid<3>::OccupancyGrid(const GridGeometry3&);
template void OccupancyGrid<2>::Rasterise(const OrientedBox&, const char*);
template void OccupancyGrid<3>::Rasterise(const OrientedBox&, const char*);
template void OccupancyGrid<3>::AddBox(const OrientedBox&);
template void OccupancyGrid<2>::AddFootprint(const OrientedBox&);
template bool OccupancyGrid<2>::AddBoxInBand(const OrientedBox&, const HeightBand&);
template OccupancyGrid<2> OccupancyGrid<2>::ProjectBand(const OccupancyGrid<3>&, const HeightBand&);
template bool OccupancyGrid<2>::MarkPoint(const Point&);
template bool OccupancyGrid<3>::MarkPoint(const Point&);
template void OccupancyGrid<2>::ClearAll();
template void OccupancyGrid<3>::ClearAll();
template std::int64_t OccupancyGrid<2>::CountOccupied() const;
template std::int64_t OccupancyGrid<3>::CountOccupied() const;

}  // namespace topay
