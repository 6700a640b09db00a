#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"
#include "core/map/occupancy_grid3.h"

namespace topay {

/// An open height interval (z_min_m, z_max_m) of the world, e.g. the band the mobile base
/// sweeps: [0, chassis top 0.155 m]. Obstacles wholly above it (table tops, floating boxes) do
/// not block the base; the arm must clear them in 3D.
struct HeightBand {
  double z_min_m = 0.0;
  double z_max_m = 0.155;
};

/// A 2D occupancy grid in the world xy plane: one byte per cell (1 occupied, 0 free), stored in
/// GridGeometry2's order (x fastest). Starts all free.
class OccupancyGrid2 {
 public:
  /// Throws std::invalid_argument for an invalid geometry (see GridGeometry2::Validate).
  explicit OccupancyGrid2(const GridGeometry2& geometry);

  /// The columns of `grid` with an occupied cell whose z interval overlaps the band's interior
  /// (a layer that only touches the band at a face does not count). Coarser than
  /// AddBoxInBand: a layer counts whole, so a table top at 0.5 m is left out only if its
  /// voxels lie above the band. Throws std::invalid_argument unless the band is finite with
  /// z_min_m < z_max_m.
  static OccupancyGrid2 ProjectBand(const OccupancyGrid3& grid, const HeightBand& band);

  const GridGeometry2& geometry() const { return geometry_; }
  const std::vector<std::uint8_t>& cells() const { return cells_; }

  bool IsOccupied(int ix, int iy) const { return cells_[geometry_.Index(ix, iy)] != 0; }
  void SetOccupied(int ix, int iy, bool occupied) {
    cells_[geometry_.Index(ix, iy)] = occupied ? 1 : 0;
  }

  /// Marks the cells whose interior overlaps the box's footprint, exactly (separating axes,
  /// see FootprintCellOverlap), regardless of the box's height.
  /// Throws std::invalid_argument for a box with NaN/inf values or negative sizes.
  void AddFootprint(const OrientedBox& box);

  /// AddFootprint if the box's z extent overlaps the band's interior, else nothing: a table top
  /// at [0.5, 0.55] m does not count for the band [0, 0.155] m, its legs do. Returns whether
  /// the box counted. Throws std::invalid_argument for a bad box or band.
  bool AddBoxInBand(const OrientedBox& box, const HeightBand& band);

  /// Marks the cell holding p_W; outside points (and NaN) are ignored, counted, and give false.
  bool MarkPoint(const Eigen::Vector2d& p_W);
  std::int64_t num_points_outside() const { return num_points_outside_; }

  /// Frees every cell and resets num_points_outside().
  void ClearAll();

  std::int64_t CountOccupied() const;

 private:
  GridGeometry2 geometry_;
  std::vector<std::uint8_t> cells_;
  std::int64_t num_points_outside_ = 0;
};

/// Throws std::invalid_argument naming `where` unless the band is finite and z_min_m < z_max_m.
void ValidateBand(const HeightBand& band, const char* where);

}  // namespace topay
