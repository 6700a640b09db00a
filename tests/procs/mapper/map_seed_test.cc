#include "procs/mapper/map_seed.h"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace topay::mapper {
namespace {

TEST(MapSeedTest, KnownVoxelsAtTheClampsAndUnknownOnesUntouched) {
  OccupancyMapOptions options;
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0.5));
  OccupancyMap map(options);
  const GridGeometry3& g = map.geometry();
  std::vector<VoxelState> states(g.NumCells(), VoxelState::kUnknown);
  states[g.Index(3, 4, 5)] = VoxelState::kOccupied;
  states[g.Index(6, 7, 8)] = VoxelState::kFree;
  EXPECT_EQ(SeedKnownVoxels(states, &map), 2);
  EXPECT_EQ(map.state(3, 4, 5), VoxelState::kOccupied);
  EXPECT_NEAR(map.log_odds(3, 4, 5), options.log_odds_max, 1e-3);
  EXPECT_EQ(map.state(6, 7, 8), VoxelState::kFree);
  EXPECT_NEAR(map.log_odds(6, 7, 8), options.log_odds_min, 1e-3);
  EXPECT_EQ(map.state(0, 0, 0), VoxelState::kUnknown);
  const VoxelStateCounts counts = map.CountStates();
  EXPECT_EQ(counts.occupied, 1);
  EXPECT_EQ(counts.free, 1);
}

TEST(MapSeedTest, AnotherCountOfStatesIsRefused) {
  OccupancyMapOptions options;
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 0.5));
  OccupancyMap map(options);
  const std::vector<VoxelState> states(10, VoxelState::kOccupied);
  EXPECT_THROW(SeedKnownVoxels(states, &map), std::invalid_argument);
  EXPECT_EQ(map.CountStates().occupied, 0);
}

TEST(MapSeedTest, StateBytesAreReadAsVoxelStates) {
  const std::vector<std::uint8_t> bytes{static_cast<std::uint8_t>(VoxelState::kFree),
                                        static_cast<std::uint8_t>(VoxelState::kOccupied),
                                        static_cast<std::uint8_t>(VoxelState::kUnknown)};
  EXPECT_EQ(VoxelStatesOf(bytes), (std::vector<VoxelState>{VoxelState::kFree, VoxelState::kOccupied, VoxelState::kUnknown}));
}

}  // namespace
}  // namespace topay::mapper
