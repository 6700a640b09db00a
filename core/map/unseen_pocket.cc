#include "core/map/unseen_pocket.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/map/voxel_state.h"

namespace topay {
namespace {

std::string Metres(double value_m) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", value_m);
  return text;
}

VoxelState StateAt(const GridGeometry3& grid, std::span<const std::uint8_t> states, int ix, int iy, int iz) {
  return static_cast<VoxelState>(states[grid.Index(ix, iy, iz)]);
}

void CheckInputs(const GridGeometry3& grid, std::span<const std::uint8_t> states, const Eigen::Vector3d& p_W,
                 const UnseenPocketOptions& options) {
  if (static_cast<std::int64_t>(states.size()) != grid.NumCells()) {
    throw std::invalid_argument("FindUnseenPocket: " + std::to_string(states.size()) +
                                " voxel states for a grid of " + std::to_string(grid.NumCells()) + " voxels");
  }
  if (!p_W.allFinite()) throw std::invalid_argument("FindUnseenPocket: the target is not finite");
  if (!(options.min_occupied_rim_share >= 0.0 && options.min_occupied_rim_share <= 1.0)) {
    throw std::invalid_argument("FindUnseenPocket: min_occupied_rim_share = " +
                                std::to_string(options.min_occupied_rim_share) + " must lie in [0, 1]");
  }
  if (!(options.max_reach_m > 0.0) || !std::isfinite(options.max_reach_m)) {
    throw std::invalid_argument("FindUnseenPocket: max_reach_m = " + std::to_string(options.max_reach_m) +
                                " must be positive and finite");
  }
}

}  // namespace

UnseenPocket FindUnseenPocket(const GridGeometry3& grid, std::span<const std::uint8_t> states,
                              const Eigen::Vector3d& p_W, const UnseenPocketOptions& options) {
  CheckInputs(grid, states, p_W, options);
  UnseenPocket pocket;
  if (!grid.Contains(p_W)) {
    pocket.open_because = "the target is outside the map";
    return pocket;
  }
  const Eigen::Vector3i target = grid.CellOf(p_W);
  const int iz = target.z();
  const VoxelState own = StateAt(grid, states, target.x(), target.y(), iz);
  if (own != VoxelState::kUnknown) {
    pocket.open_because = own == VoxelState::kFree ? "the target's voxel was seen free" : "the target's voxel is occupied";
    return pocket;
  }
  // The window: cells within reach of the target's cell along x and y (clipped to the grid).
  const int reach = static_cast<int>(std::ceil(options.max_reach_m / grid.resolution_m));
  const Eigen::Vector2i lo(target.x() - reach, target.y() - reach);
  const int side = 2 * reach + 1;
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(side) * side, 0);
  std::vector<Eigen::Vector2i> stack{target.head<2>()};
  seen[static_cast<std::size_t>(reach) * side + reach] = 1;
  constexpr int kStep[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  while (!stack.empty()) {
    const Eigen::Vector2i cell = stack.back();
    stack.pop_back();
    ++pocket.voxels;
    const Eigen::Vector2d corner_W = grid.origin_W_m.head<2>() + grid.resolution_m * cell.cast<double>();
    pocket.extent_W_m.extend(corner_W);
    pocket.extent_W_m.extend(corner_W + Eigen::Vector2d::Constant(grid.resolution_m));
    for (const auto& step : kStep) {
      const Eigen::Vector2i next(cell.x() + step[0], cell.y() + step[1]);
      const Eigen::Vector2i w = next - lo;
      if (w.x() < 0 || w.y() < 0 || w.x() >= side || w.y() >= side) {
        pocket.open_because = "its unseen pocket reaches farther than " + Metres(options.max_reach_m) + " m";
        return pocket;
      }
      if (next.x() < 0 || next.y() < 0 || next.x() >= grid.dims.x() || next.y() >= grid.dims.y()) {
        pocket.open_because = "its unseen pocket reaches the map's edge";
        return pocket;
      }
      std::uint8_t& mark = seen[static_cast<std::size_t>(w.y()) * side + w.x()];
      if (mark) continue;
      mark = 1;
      const VoxelState s = StateAt(grid, states, next.x(), next.y(), iz);
      if (s != VoxelState::kUnknown) {  // the pocket's rim: a surface seen, or a ray through
        ++(s == VoxelState::kOccupied ? pocket.rim_occupied : pocket.rim_free);
        continue;
      }
      stack.push_back(next);
    }
  }
  const int rim = pocket.rim_occupied + pocket.rim_free;
  if (pocket.rim_occupied < options.min_occupied_rim_share * rim) {
    pocket.open_because = "its unseen pocket's rim is mostly seen free (" + std::to_string(pocket.rim_occupied) +
                          " of " + std::to_string(rim) + " voxels occupied): a gap between rays, not a body";
    return pocket;
  }
  pocket.enclosed = true;
  return pocket;
}

}  // namespace topay
