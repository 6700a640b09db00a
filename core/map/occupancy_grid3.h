#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/map/grid_geometry.h"

namespace topay {

/// A 3D occupancy grid: one byte per cell (1 occupied, 0 free), contiguous, stored in
/// GridGeometry3's order (x fastest). Filled from exact geometry (AddBox) or from points
/// (MarkPoint, for the point-cloud mapper). Starts all free.
class OccupancyGrid3 {
 public:
  /// Throws std::invalid_argument for an invalid geometry (see GridGeometry3::Validate).
  explicit OccupancyGrid3(const GridGeometry3& geometry);

  const GridGeometry3& geometry() const { return geometry_; }
  /// The cells, 1 occupied and 0 free, indexed by geometry().Index(ix, iy, iz).
  const std::vector<std::uint8_t>& cells() const { return cells_; }

  bool IsOccupied(int ix, int iy, int iz) const {
    return cells_[geometry_.Index(ix, iy, iz)] != 0;
  }
  void SetOccupied(int ix, int iy, int iz, bool occupied) {
    cells_[geometry_.Index(ix, iy, iz)] = occupied ? 1 : 0;
  }

  /// Conservative exact rasterisation: marks every cell whose interior overlaps the box's
  /// interior (z intervals overlap and the xy footprint overlaps the cell's square, tested
  /// exactly by separating axes, see FootprintCellOverlap). So a part thinner than a cell
  /// (0.05 m table tops and legs at 0.1 m) is never lost, and a cell the box only touches at a
  /// face, edge or corner stays free. Parts outside the grid are clipped.
  /// Throws std::invalid_argument for a box with NaN/inf values or negative sizes.
  void AddBox(const OrientedBox& box);

  /// Marks the cell holding p_W (a point-cloud return) occupied and returns true; a point
  /// outside the grid (or NaN) is ignored, counted in num_points_outside(), and returns false.
  bool MarkPoint(const Eigen::Vector3d& p_W);

  /// Points ignored by MarkPoint since construction or the last ClearAll.
  std::int64_t num_points_outside() const { return num_points_outside_; }

  /// Frees every cell and resets num_points_outside().
  void ClearAll();

  std::int64_t CountOccupied() const;

 private:
  GridGeometry3 geometry_;
  std::vector<std::uint8_t> cells_;
  std::int64_t num_points_outside_ = 0;
};

}  // namespace topay
