#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/map/signed_distance_field2.h"
#include "core/planning/base_free_space.h"
#include "core/planning/traversable_grid.h"

namespace topay {

/// The positions the base can reach from a start position on its 2D field at a safe distance
/// (base radius + clearance): the 4-connected component of traversable cells (TraversableGrid,
/// the grid JumpPointSearch walks) that the start joins, found by one flood fill. JPS between
/// the start and any position Contains() accepts finds a path, so the front end uses the
/// region to choose goal base poses the base can get to (a grid of n cells: O(n) time, n bytes).
class BaseReachableRegion {
 public:
  /// `field` must outlive this object.
  BaseReachableRegion(const SignedDistanceField2& field, const Eigen::Vector2d& start_W_m,
                      double safe_distance_m);

  /// False if the start is not free or sees no traversable cell (then Contains is always false).
  bool start_joins_grid() const { return num_cells_ > 0; }
  /// Cells in the start's component.
  int num_cells() const { return num_cells_; }
  /// True if p_W_m is free at the safe distance and joins the grid (ConnectToGrid) at a cell of
  /// the start's component.
  bool Contains(const Eigen::Vector2d& p_W_m) const;

 private:
  void FloodFill(int seed);

  const SignedDistanceField2* field_;
  BaseFreeSpace free_space_;
  TraversableGrid grid_;
  std::vector<std::uint8_t> in_region_;
  int num_cells_ = 0;
};

}  // namespace topay
