#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/planning/base_free_space.h"

namespace topay {

/// Uniform visibility deformation test (Jaillet and Simeon 2008, as used by
/// topological PRM, Zhou et al. 2020): both paths (with common end points) are
/// resampled uniformly by arc length to N = ceil(max(length_a, length_b) /
/// resolution_m) + 1 points, and they are equivalent when every matched pair
/// a(i), b(i) is mutually visible (the segment between them is free).
/// UVD-equivalent paths are homotopic in the free space; the converse is not
/// guaranteed, so the test may split one class, never merge two. resolution_m
/// must be > 0.
bool UvdEquivalent(const BaseFreeSpace& free_space, const std::vector<Eigen::Vector2d>& a_W_m,
                   const std::vector<Eigen::Vector2d>& b_W_m, double resolution_m);

/// Options of PruneEquivalentPaths.
struct UvdPruningOptions {
  double resolution_m = 0.0;      ///< <= 0: the field's cell size.
  double max_length_ratio = 2.0;  ///< Drop paths longer than this times the shortest.
  int max_paths = 6;              ///< Keep at most this many.
  /// The mutual-visibility test runs at the free space's required distance
  /// minus this slack (default: the 0.1 m clearance, i.e. at the bare base
  /// radius). Shortcut paths in one class hug the same obstacles at exactly the
  /// required distance, and a chord between two such points cuts slightly into
  /// the clearance margin; the margin is no topological feature.
  double visibility_slack_m = 0.1;
};

/// Indices of the paths kept: sorts by length (stable), walks from the shortest
/// and keeps a path unless it is UVD-equivalent to a kept one, longer than
/// max_length_ratio x the shortest, or max_paths are kept already. Result in
/// increasing length.
std::vector<int> PruneEquivalentPaths(const BaseFreeSpace& free_space,
                                      const std::vector<std::vector<Eigen::Vector2d>>& paths_W_m,
                                      const UvdPruningOptions& options = {});

}  // namespace topay
