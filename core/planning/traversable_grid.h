#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/map/signed_distance_field2.h"
#include "core/planning/base_free_space.h"

namespace topay {

/// The cells of the base's 2D field whose centre value is at least a safe distance (base
/// radius + clearance) plus 1e-6 m, a guard against rounding in the bilinear interpolation
/// between such cells. Read from the field's values on demand (no copy: a search touches few
/// cells of a fine grid); the field must outlive the grid. Moves are 8-connected without corner cutting: a diagonal step needs
/// both orthogonal neighbours traversable, so two cells are connected exactly when they are
/// 4-connected. Shared by JumpPointSearch and BaseReachableRegion, so that both agree on
/// which positions the base can reach.
class TraversableGrid {
 public:
  static constexpr int kNoCell = -1;

  TraversableGrid(const SignedDistanceField2& field, double safe_distance_m);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int num_cells() const { return nx_ * ny_; }
  int Index(int x, int y) const { return y * nx_ + x; }
  bool Free(int x, int y) const {
    return x >= 0 && y >= 0 && x < nx_ && y < ny_ &&
           static_cast<double>(values_[Index(x, y)]) >= threshold_m_;
  }
  /// A diagonal step needs the target and both orthogonal neighbours free (no corner cutting).
  bool CanStep(int x, int y, int dx, int dy) const {
    if (!Free(x + dx, y + dy)) return false;
    return dx == 0 || dy == 0 || (Free(x + dx, y) && Free(x, y + dy));
  }

 private:
  int nx_;
  int ny_;
  const float* values_;  // the field's, x fastest
  double threshold_m_;   // safe distance + the rounding guard
};

/// Index of the traversable cell (p_W_m's own or one of the 8 around it) whose centre is
/// nearest to p_W_m among those p_W_m sees (segment free in `free_space`), or
/// TraversableGrid::kNoCell: how a continuous position joins the grid.
int ConnectToGrid(const SignedDistanceField2& field, const TraversableGrid& grid,
                  const BaseFreeSpace& free_space, const Eigen::Vector2d& p_W_m);

}  // namespace topay
