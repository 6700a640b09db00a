#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"

namespace topay {

/// Half-open range [begin, end) of cell indices.
struct CellRange {
  int begin = 0;
  int end = 0;
  bool empty() const { return end <= begin; }
};

/// The cells of one grid axis (minimum corner origin_m, cell size resolution_m, num_cells
/// cells) whose interior overlaps the open interval (low_m, high_m): cell i spans
/// (origin + i res, origin + (i + 1) res), and overlaps iff i > (low - origin) / res - 1 and
/// i < (high - origin) / res, i.e. i in [floor((low - o) / res), ceil((high - o) / res)),
/// clipped to [0, num_cells). Intervals that merely touch a cell's face do not overlap it.
inline CellRange CellsOverlapping(double low_m, double high_m, double origin_m,
                                  double resolution_m, int num_cells) {
  const double begin = std::floor((low_m - origin_m) / resolution_m);
  const double end = std::ceil((high_m - origin_m) / resolution_m);
  return {static_cast<int>(std::clamp(begin, 0.0, static_cast<double>(num_cells))),
          static_cast<int>(std::clamp(end, 0.0, static_cast<double>(num_cells)))};
}

/// Exact overlap test between the xy footprint of an upright box (a rectangle rotated by yaw)
/// and axis-aligned square cells of one size, by the separating-axis theorem: two convex
/// polygons have overlapping interiors iff their projections overlap as open intervals on each
/// of the candidate axes, here the world x, y axes and the box's own x, y axes
/// (Gottschalk et al. 1996, "OBBTree", the 2D case). Constant per box, precomputed here.
class FootprintCellOverlap {
 public:
  FootprintCellOverlap(const OrientedBox& box, double cell_size_m)
      : center_W_(box.center_W_m.head<2>()),
        cos_(std::cos(box.yaw_rad)),
        sin_(std::sin(box.yaw_rad)) {
    const double half_cell = 0.5 * cell_size_m;
    const double abs_c = std::abs(cos_);
    const double abs_s = std::abs(sin_);
    const Eigen::Vector2d half_box = box.HalfSize().head<2>();
    // Overlap radius on each axis: the sum of both shapes' projected half widths.
    limit_box_x_ = half_box.x() + half_cell * (abs_c + abs_s);
    limit_box_y_ = half_box.y() + half_cell * (abs_c + abs_s);
    limit_world_x_ = half_cell + half_box.x() * abs_c + half_box.y() * abs_s;
    limit_world_y_ = half_cell + half_box.x() * abs_s + half_box.y() * abs_c;
  }

  /// True if the open square cell centred at cell_center_W overlaps the open footprint.
  bool Overlaps(const Eigen::Vector2d& cell_center_W) const {
    const Eigen::Vector2d d = cell_center_W - center_W_;
    return std::abs(d.x()) < limit_world_x_ && std::abs(d.y()) < limit_world_y_ &&
           std::abs(cos_ * d.x() + sin_ * d.y()) < limit_box_x_ &&
           std::abs(-sin_ * d.x() + cos_ * d.y()) < limit_box_y_;
  }

 private:
  Eigen::Vector2d center_W_;
  double cos_ = 1.0;
  double sin_ = 0.0;
  double limit_box_x_ = 0.0;
  double limit_box_y_ = 0.0;
  double limit_world_x_ = 0.0;
  double limit_world_y_ = 0.0;
};

/// Throws std::invalid_argument naming `where` unless the box's centre, size and yaw are finite
/// and its sizes non-negative.
void ValidateBox(const OrientedBox& box, const char* where);

}  // namespace topay
