#include "core/planning/uvd_equivalence.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/planning/base_path.h"
#include "core/planning/path_shortcut.h"

namespace topay {

bool UvdEquivalent(const BaseFreeSpace& free_space, const std::vector<Eigen::Vector2d>& a_W_m,
                   const std::vector<Eigen::Vector2d>& b_W_m, double resolution_m) {
  if (a_W_m.empty() || b_W_m.empty() || !(resolution_m > 0.0)) return false;
  const double max_length = std::max(PolylineLength(a_W_m), PolylineLength(b_W_m));
  // N = ceil(max length / resolution) intervals, N + 1 matched points.
  const int num_points = static_cast<int>(std::ceil(max_length / resolution_m)) + 1;
  const std::vector<Eigen::Vector2d> a = ResampleUniform(a_W_m, num_points);
  const std::vector<Eigen::Vector2d> b = ResampleUniform(b_W_m, num_points);
  for (int i = 0; i < num_points; ++i) {
    if (!free_space.IsSegmentFree(a[i], b[i])) return false;
  }
  return true;
}

std::vector<int> PruneEquivalentPaths(const BaseFreeSpace& free_space,
                                      const std::vector<std::vector<Eigen::Vector2d>>& paths_W_m,
                                      const UvdPruningOptions& options) {
  const double resolution = options.resolution_m > 0.0 ? options.resolution_m
                                                       : free_space.field().geometry().resolution_m;
  const BaseFreeSpace visibility(free_space.field(),
                                 free_space.required_distance_m() - options.visibility_slack_m);
  std::vector<double> lengths(paths_W_m.size());
  for (std::size_t i = 0; i < paths_W_m.size(); ++i) lengths[i] = PolylineLength(paths_W_m[i]);
  std::vector<int> order(paths_W_m.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int i, int j) { return lengths[i] < lengths[j]; });
  std::vector<int> kept;
  for (int index : order) {
    if (static_cast<int>(kept.size()) >= options.max_paths) break;
    if (!kept.empty() && lengths[index] > options.max_length_ratio * lengths[kept.front()]) break;
    const bool duplicate = std::any_of(kept.begin(), kept.end(), [&](int k) {
      return UvdEquivalent(visibility, paths_W_m[k], paths_W_m[index], resolution);
    });
    if (!duplicate) kept.push_back(index);
  }
  return kept;
}

}  // namespace topay
