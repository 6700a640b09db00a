#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"

namespace topay {

/// An open height interval (z_min_m, z_max_m) of the world, e.g. the band the mobile base
/// sweeps: [0, chassis top 0.155 m]. Obstacles wholly above it (table tops, floating boxes) do
/// not block the base; the arm must clear them in 3D.
struct HeightBand {
  double z_min_m = 0.0;
  double z_max_m = 0.155;
};

/// Throws std::invalid_argument naming `where` unless the band is finite and z_min_m < z_max_m.
void ValidateBand(const HeightBand& band, const char* where);

/// An occupancy grid of dimension Dim (3: OccupancyGrid3, the world; 2: OccupancyGrid2, the
/// world xy plane): one byte per cell (1 occupied, 0 free), contiguous, stored in the
/// geometry's order (x fastest). Filled from exact geometry (AddBox in 3D, AddFootprint and
/// AddBoxInBand in 2D, one rasteriser for both) or from points (MarkPoint, for the
/// point-cloud mapper). Starts all free. One implementation for both dimensions; the names
/// OccupancyGrid2 and OccupancyGrid3 are aliases.
template <int Dim>
class OccupancyGrid {
  static_assert(Dim == 2 || Dim == 3, "OccupancyGrid: 2 or 3 dimensions");

 public:
  using Geometry = GridGeometry<Dim>;
  using Point = Eigen::Matrix<double, Dim, 1>;

  /// Throws std::invalid_argument for an invalid geometry (see GridGeometry3::Validate).
  explicit OccupancyGrid(const Geometry& geometry);

  const Geometry& geometry() const { return geometry_; }
  /// The cells, 1 occupied and 0 free, indexed by geometry().Index(ix, iy[, iz]).
  const std::vector<std::uint8_t>& cells() const { return cells_; }

  template <typename... Ints>
    requires(sizeof...(Ints) == Dim)
  bool IsOccupied(Ints... index) const {
    return cells_[geometry_.Index(index...)] != 0;
  }
  void SetOccupied(int ix, int iy, bool occupied)
    requires(Dim == 2)
  {
    cells_[geometry_.Index(ix, iy)] = occupied ? 1 : 0;
  }
  void SetOccupied(int ix, int iy, int iz, bool occupied)
    requires(Dim == 3)
  {
    cells_[geometry_.Index(ix, iy, iz)] = occupied ? 1 : 0;
  }

  /// 3D. Conservative exact rasterisation: marks every cell whose interior overlaps the box's
  /// interior (z intervals overlap and the xy footprint overlaps the cell's square, tested
  /// exactly by separating axes, see FootprintCellOverlap). So a part thinner than a cell
  /// (0.05 m table tops and legs at 0.1 m) is never lost, and a cell the box only touches at a
  /// face, edge or corner stays free. Parts outside the grid are clipped. Cost: the cells of
  /// the box's bounds. Throws std::invalid_argument for a box with NaN/inf values or negative
  /// sizes.
  void AddBox(const OrientedBox& box)
    requires(Dim == 3);

  /// 2D. The columns of `grid` with an occupied cell whose z interval overlaps the band's
  /// interior (a layer that only touches the band at a face does not count). Coarser than
  /// AddBoxInBand: a layer counts whole, so a table top at 0.5 m is left out only if its
  /// voxels lie above the band. Throws std::invalid_argument unless the band is finite with
  /// z_min_m < z_max_m.
  static OccupancyGrid ProjectBand(const OccupancyGrid<3>& grid, const HeightBand& band)
    requires(Dim == 2);

  /// 2D. Marks the cells whose interior overlaps the box's footprint, exactly (separating
  /// axes, see FootprintCellOverlap), regardless of the box's height. Throws
  /// std::invalid_argument for a box with NaN/inf values or negative sizes.
  void AddFootprint(const OrientedBox& box)
    requires(Dim == 2);

  /// 2D. AddFootprint if the box's z extent overlaps the band's interior, else nothing: a
  /// table top at [0.5, 0.55] m does not count for the band [0, 0.155] m, its legs do.
  /// Returns whether the box counted. Throws std::invalid_argument for a bad box or band.
  bool AddBoxInBand(const OrientedBox& box, const HeightBand& band)
    requires(Dim == 2);

  /// Marks the cell holding p_W (a point-cloud return) occupied and returns true; a point
  /// outside the grid (or NaN) is ignored, counted in num_points_outside(), and returns false.
  bool MarkPoint(const Point& p_W);

  /// Points ignored by MarkPoint since construction or the last ClearAll.
  std::int64_t num_points_outside() const { return num_points_outside_; }

  /// Frees every cell and resets num_points_outside().
  void ClearAll();

  std::int64_t CountOccupied() const;

 private:
  // Marks the cells of the box's footprint (clipped to the grid) and, in 3D, the layers
  // [z_begin, z_end) above each; `where` names the caller for a bad box.
  void Rasterise(const OrientedBox& box, const char* where);

  Geometry geometry_;
  std::vector<std::uint8_t> cells_;
  std::int64_t num_points_outside_ = 0;
};

// The out-of-line members are instantiated for 2 and 3 in occupancy_grid.cc.

}  // namespace topay
