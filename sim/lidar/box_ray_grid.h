#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "sim/lidar/ray_primitives.h"

namespace topay::sim {

/// First-hit ray casting against many upright boxes: a uniform grid of square cells over the
/// boxes' xy extent (the scenes are flat rooms, so a 2D grid with a per-cell z range does the
/// work of a 3D one with far fewer cells), each cell listing the boxes whose world AABB
/// (grown by kPadM) overlaps it, walked cell by cell along the ray with the 2D digital
/// differential analyser of Amanatides and Woo (1987). In each cell the ray's z interval is
/// compared with the cell's boxes' z range first; a box in several cells is tested once per ray
/// (a per-box stamp). The walk stops as soon as the nearest hit so far lies strictly before the
/// current cell's exit: every box not yet tested lies in later cells, so it cannot be hit
/// earlier. Ties (equal t) go to the lowest box index, so the result equals
/// FirstHitBruteForce's exactly (both use the same box test).
///
/// Not thread-safe (the stamps); one grid per thread. Build allocates; FirstHit does not.
class BoxRayGrid {
 public:
  struct Hit {
    double t_m = kNoHit;  ///< Distance along the unit ray; +infinity: no hit.
    int box = -1;         ///< Index in the vector given to Build.
  };

  /// The AABBs listed in cells are grown by this margin so that rounding in the walk never
  /// skips a box whose surface touches a cell border.
  static constexpr double kPadM = 1e-6;

  /// cell_m > 0: side of the square cells (m). The grid has at most max_cells cells: the side
  /// grows until the boxes' extent fits.
  explicit BoxRayGrid(double cell_m = 0.5, std::int64_t max_cells = std::int64_t{1} << 22);

  /// Lists `boxes` (copied into a packed form). Non-finite boxes are kept out of the grid.
  void Build(const std::vector<OrientedBox>& boxes);

  /// Nearest box entry with t in [0, t_max_m] along p_WO + t d_W (d_W unit), or no hit.
  Hit FirstHit(const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W, double t_max_m);

  /// The same by testing every box (the reference for tests).
  Hit FirstHitBruteForce(const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W,
                         double t_max_m) const;

  int num_boxes() const { return static_cast<int>(boxes_.size()); }
  double cell_m() const { return cell_m_; }
  Eigen::Vector2i dims() const { return {nx_, ny_}; }
  /// Box tests made by FirstHit since Build (a measure of the grid's work).
  std::int64_t box_tests() const { return box_tests_; }

 private:
  struct PackedBox {
    double cos_yaw, sin_yaw;
    Eigen::Vector3d center_m, half_m;
    bool finite;
  };
  // The exact entry t of the ray into box i (RayCenteredBoxEntry in the box frame).
  double Entry(int i, const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W) const;
  void TestCell(std::int64_t cell, const Eigen::Vector3d& p_WO, const Eigen::Vector3d& d_W,
                double t_max_m, Hit* best);
  void NextStamp();

  double requested_cell_m_;
  std::int64_t max_cells_;
  double cell_m_;
  std::vector<PackedBox> boxes_;
  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  Eigen::Vector3d lo_m_ = Eigen::Vector3d::Zero();  // grown union of the AABBs
  Eigen::Vector3d hi_m_ = Eigen::Vector3d::Zero();
  int nx_ = 0;
  int ny_ = 0;
  std::vector<std::int32_t> cell_start_;  // CSR: cell c lists ids_[start[c], start[c + 1])
  std::vector<std::int32_t> ids_;
  std::vector<double> cell_z_lo_;        // z range of each cell's boxes (grown)
  std::vector<double> cell_z_hi_;
  std::vector<std::uint32_t> stamp_;      // per box: the ray that last tested it
  std::uint32_t ray_stamp_ = 0;
  std::int64_t box_tests_ = 0;
};

}  // namespace topay::sim
