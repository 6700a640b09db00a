#include "core/planning/base_reachable_region.h"

namespace topay {

BaseReachableRegion::BaseReachableRegion(const SignedDistanceField2& field,
                                         const Eigen::Vector2d& start_W_m, double safe_distance_m)
    : field_(&field),
      free_space_(field, safe_distance_m),
      grid_(field, safe_distance_m),
      in_region_(static_cast<std::size_t>(grid_.num_cells()), 0) {
  if (!start_W_m.allFinite() || !free_space_.IsFree(start_W_m)) return;
  const int seed = ConnectToGrid(field, grid_, free_space_, start_W_m);
  if (seed != TraversableGrid::kNoCell) FloodFill(seed);
}

void BaseReachableRegion::FloodFill(int seed) {
  std::vector<int> stack{seed};
  in_region_[seed] = 1;
  constexpr int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  while (!stack.empty()) {
    const int cell = stack.back();
    stack.pop_back();
    ++num_cells_;
    const int x = cell % grid_.nx(), y = cell / grid_.nx();
    for (const auto& step : kSteps) {
      const int nx = x + step[0], ny = y + step[1];
      if (!grid_.Free(nx, ny)) continue;
      const int next = grid_.Index(nx, ny);
      if (in_region_[next]) continue;
      in_region_[next] = 1;
      stack.push_back(next);
    }
  }
}

bool BaseReachableRegion::Contains(const Eigen::Vector2d& p_W_m) const {
  if (num_cells_ == 0 || !p_W_m.allFinite() || !free_space_.IsFree(p_W_m)) return false;
  const int cell = ConnectToGrid(*field_, grid_, free_space_, p_W_m);
  return cell != TraversableGrid::kNoCell && in_region_[cell] != 0;
}

}  // namespace topay
