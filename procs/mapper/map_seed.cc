#include "procs/mapper/map_seed.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace topay::mapper {

std::vector<VoxelState> VoxelStatesOf(std::span<const std::uint8_t> bytes) {
  std::vector<VoxelState> states(bytes.size());
  std::transform(bytes.begin(), bytes.end(), states.begin(), [](std::uint8_t b) { return static_cast<VoxelState>(b); });
  return states;
}

std::int64_t SeedKnownVoxels(std::span<const VoxelState> states, OccupancyMap* map) {
  const GridGeometry3& g = map->geometry();
  if (states.size() != static_cast<std::size_t>(g.NumCells())) {
    throw std::invalid_argument("SeedKnownVoxels: " + std::to_string(states.size()) + " states for a map of " +
                                std::to_string(g.NumCells()) + " voxels");
  }
  std::int64_t seeded = 0;
  for (int iz = 0; iz < g.dims.z(); ++iz) {
    for (int iy = 0; iy < g.dims.y(); ++iy) {
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        const VoxelState s = states[g.Index(ix, iy, iz)];
        if (s == VoxelState::kUnknown) continue;
        const float log_odds = s == VoxelState::kOccupied ? map->options().log_odds_max : map->options().log_odds_min;
        map->SetVoxel({ix, iy, iz}, log_odds, nullptr);
        ++seeded;
      }
    }
  }
  return seeded;
}

}  // namespace topay::mapper
