#include "core/planning/traversable_grid.h"

#include <limits>

namespace topay {
namespace {

// Traversable cells need this much more than the safe distance, so that bilinear
// interpolation between them (with its rounding) never reads below the safe distance.
constexpr double kCellMargin_m = 1e-6;

}  // namespace

TraversableGrid::TraversableGrid(const SignedDistanceField2& field, double safe_distance_m)
    : nx_(field.geometry().dims.x()),
      ny_(field.geometry().dims.y()),
      values_(field.values().data()),
      threshold_m_(safe_distance_m + kCellMargin_m) {}

int ConnectToGrid(const SignedDistanceField2& field, const TraversableGrid& grid,
                  const BaseFreeSpace& free_space, const Eigen::Vector2d& p_W_m) {
  const GridGeometry2& g = field.geometry();
  const Eigen::Vector2i c = g.CellOf(p_W_m);
  int best = TraversableGrid::kNoCell;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int a = -1; a <= 1; ++a) {
    for (int b = -1; b <= 1; ++b) {
      const int x = c.x() + a, y = c.y() + b;
      if (!grid.Free(x, y)) continue;
      const Eigen::Vector2d centre = g.CellCenter(x, y);
      const double distance = (centre - p_W_m).norm();
      if (distance < best_distance && free_space.IsSegmentFree(p_W_m, centre)) {
        best = grid.Index(x, y);
        best_distance = distance;
      }
    }
  }
  return best;
}

}  // namespace topay
