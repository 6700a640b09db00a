// Occupied columns from above, in the grey of their top.

#include "tools/report/map_drawing.h"

#include <gtest/gtest.h>

#include "core/map/voxel_state.h"

namespace topay::report {
namespace {

TEST(MapDrawing, EachOccupiedColumnInTheGreyOfItsTop) {
  FinalMap map;
  map.geometry.origin_W_m = Eigen::Vector3d(0.0, 0.0, 0.0);
  map.geometry.resolution_m = 0.5;
  map.geometry.dims = Eigen::Vector3i(4, 4, 4);  // 2 x 2 x 2 m
  map.states.assign(64, static_cast<std::uint8_t>(VoxelState::kUnknown));
  map.states[map.geometry.Index(0, 0, 0)] = static_cast<std::uint8_t>(VoxelState::kOccupied);  // top 0.5 m
  map.states[map.geometry.Index(3, 3, 1)] = static_cast<std::uint8_t>(VoxelState::kOccupied);
  map.states[map.geometry.Index(3, 3, 3)] = static_cast<std::uint8_t>(VoxelState::kOccupied);  // top 2 m
  EXPECT_DOUBLE_EQ(MapHeightRange(map).max, 2.0);
  const viz::ViewTransform view(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 2)), 50.0);
  viz::WorldCanvas canvas(viz::Image(100, 100), view);
  EXPECT_EQ(DrawOccupiedColumns(&canvas, map), 2);
  EXPECT_EQ(canvas.image().At(12, 87), viz::GreyRamp(0.25));  // column (0, 0): x, y 0..0.5 m
  EXPECT_EQ(canvas.image().At(87, 12), viz::GreyRamp(1.0));   // column (3, 3)
  EXPECT_EQ(canvas.image().At(50, 50), viz::colors::kWhite);  // nothing occupied
}

}  // namespace
}  // namespace topay::report
