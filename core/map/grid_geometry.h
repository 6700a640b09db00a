#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace topay {

/// Where a regular 3D grid of cubic cells lies in the world W.
///
/// Cell (ix, iy, iz) covers [o + i res, o + (i + 1) res) on each axis, where o = origin_W_m is
/// the grid's minimum corner; its centre is o + (i + 1/2) res. Cells are stored x fastest:
/// linear index (iz ny + iy) nx + ix. Made by FromBounds, which validates its input.
struct GridGeometry3 {
  Eigen::Vector3d origin_W_m = Eigen::Vector3d::Zero();  ///< Minimum corner of cell (0,0,0).
  double resolution_m = 0.1;                             ///< Side length of a cell.
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();        ///< Number of cells per axis.

  /// The grid with its minimum corner at bounds_W_m.min() and ceil(extent / resolution) cells
  /// per axis (at least 2, so that interpolation always has two samples per axis). It covers
  /// bounds_W_m and may extend past its maximum corner by less than one cell.
  /// Throws std::invalid_argument when bounds_W_m is empty or not finite, the resolution is not
  /// finite and positive, or the grid would have more than 2^31 - 1 cells.
  static GridGeometry3 FromBounds(const Eigen::AlignedBox3d& bounds_W_m, double resolution_m);

  /// Throws std::invalid_argument (naming `where`) unless the origin is finite, the resolution
  /// finite and positive, and every axis has 2 to 2^31 - 1 cells in all (FromBounds's output
  /// always passes; this guards hand-made geometries).
  void Validate(const char* where) const;

  std::int64_t NumCells() const {
    return std::int64_t{dims.x()} * dims.y() * dims.z();
  }
  std::int64_t Index(int ix, int iy, int iz) const {
    return (std::int64_t{iz} * dims.y() + iy) * dims.x() + ix;
  }
  /// The cell at linear index `index` (0 <= index < NumCells()), the inverse of Index.
  Eigen::Vector3i CellAt(std::int64_t index) const {
    const std::int64_t row = index / dims.x();
    return {static_cast<int>(index % dims.x()), static_cast<int>(row % dims.y()), static_cast<int>(row / dims.y())};
  }
  Eigen::Vector3d CellCenter(int ix, int iy, int iz) const {
    return origin_W_m + resolution_m * Eigen::Vector3d(ix + 0.5, iy + 0.5, iz + 0.5);
  }
  /// Index of the cell holding p_W; may lie outside [0, dims) (check with Contains).
  Eigen::Vector3i CellOf(const Eigen::Vector3d& p_W) const {
    const Eigen::Vector3d u = (p_W - origin_W_m) / resolution_m;
    return {static_cast<int>(std::floor(u.x())), static_cast<int>(std::floor(u.y())),
            static_cast<int>(std::floor(u.z()))};
  }
  /// True if p_W lies in the half-open box the cells cover (false for NaN).
  bool Contains(const Eigen::Vector3d& p_W) const {
    const Eigen::Vector3d u = (p_W - origin_W_m) / resolution_m;
    for (int a = 0; a < 3; ++a) {
      if (!(u(a) >= 0.0 && u(a) < dims(a))) return false;
    }
    return true;
  }
  /// The box the cells cover.
  Eigen::AlignedBox3d Bounds() const {
    return {origin_W_m, origin_W_m + resolution_m * dims.cast<double>()};
  }
};

/// True if `a` and `b` are the same grid: origin, resolution and dims exactly equal (as a grid
/// sent in a message or written to a file comes back).
inline bool SameGeometry(const GridGeometry3& a, const GridGeometry3& b) {
  return a.origin_W_m == b.origin_W_m && a.resolution_m == b.resolution_m && a.dims == b.dims;
}

/// The 2D counterpart of GridGeometry3 in the world xy plane: cell (ix, iy) covers
/// [o + i res, o + (i + 1) res) per axis, stored x fastest (linear index iy nx + ix).
struct GridGeometry2 {
  Eigen::Vector2d origin_W_m = Eigen::Vector2d::Zero();
  double resolution_m = 0.1;
  Eigen::Vector2i dims = Eigen::Vector2i::Zero();

  /// As GridGeometry3::FromBounds, in 2D.
  static GridGeometry2 FromBounds(const Eigen::AlignedBox2d& bounds_W_m, double resolution_m);

  /// The xy footprint of a 3D grid (same origin, resolution and nx, ny).
  static GridGeometry2 FootprintOf(const GridGeometry3& grid) {
    return {grid.origin_W_m.head<2>(), grid.resolution_m, grid.dims.head<2>()};
  }

  /// As GridGeometry3::Validate.
  void Validate(const char* where) const;

  std::int64_t NumCells() const { return std::int64_t{dims.x()} * dims.y(); }
  std::int64_t Index(int ix, int iy) const { return std::int64_t{iy} * dims.x() + ix; }
  Eigen::Vector2d CellCenter(int ix, int iy) const {
    return origin_W_m + resolution_m * Eigen::Vector2d(ix + 0.5, iy + 0.5);
  }
  Eigen::Vector2i CellOf(const Eigen::Vector2d& p_W) const {
    const Eigen::Vector2d u = (p_W - origin_W_m) / resolution_m;
    return {static_cast<int>(std::floor(u.x())), static_cast<int>(std::floor(u.y()))};
  }
  bool Contains(const Eigen::Vector2d& p_W) const {
    const Eigen::Vector2d u = (p_W - origin_W_m) / resolution_m;
    for (int a = 0; a < 2; ++a) {
      if (!(u(a) >= 0.0 && u(a) < dims(a))) return false;
    }
    return true;
  }
  Eigen::AlignedBox2d Bounds() const {
    return {origin_W_m, origin_W_m + resolution_m * dims.cast<double>()};
  }
};

/// The grid geometry of dimension Dim (2 or 3), for code shared by the 2D and 3D grids and
/// fields (OccupancyGrid<Dim>, SignedDistanceField<Dim>).
template <int Dim>
using GridGeometry = std::conditional_t<Dim == 2, GridGeometry2, GridGeometry3>;

}  // namespace topay
