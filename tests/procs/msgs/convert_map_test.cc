// map_update_t <-> OccupancyGrid3 (procs/msgs/convert_map.h): full snapshots round trip,
// unknown voxels follow the caller's choice, deltas apply, bad messages are refused.

#include "procs/msgs/convert_map.h"

#include <gtest/gtest.h>

namespace topay::msgs {
namespace {

OccupancyGrid<3> SampleGrid() {
  const GridGeometry3 geometry = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-1.0, -2.0, 0.0), Eigen::Vector3d(1.0, 1.0, 1.0)), 0.1);
  OccupancyGrid<3> grid(geometry);
  grid.SetOccupied(0, 0, 0, true);
  grid.SetOccupied(5, 7, 3, true);
  grid.SetOccupied(19, 29, 9, true);
  return grid;
}

TEST(ConvertMap, FullSnapshotRoundTrips) {
  const OccupancyGrid<3> grid = SampleGrid();
  const map_update_t msg = ToFullMapMessage(grid, 123, 7);
  EXPECT_TRUE(msg.is_full);
  EXPECT_EQ(msg.map_seq, 7);
  EXPECT_EQ(msg.num_values, grid.geometry().NumCells());
  std::string error;
  const auto back = FromFullMapMessage(msg, true, &error);
  ASSERT_TRUE(back) << error;
  EXPECT_EQ(back->cells(), grid.cells());
  EXPECT_EQ(back->geometry().dims, grid.geometry().dims);
  EXPECT_EQ(back->geometry().origin_W_m, grid.geometry().origin_W_m);
  EXPECT_EQ(back->geometry().resolution_m, grid.geometry().resolution_m);
  EXPECT_EQ(back->CountOccupied(), 3);
}

TEST(ConvertMap, UnknownVoxelsFollowTheCallersChoice) {
  map_update_t msg = ToFullMapMessage(SampleGrid(), 0, 1);
  msg.values[1] = map_update_t::UNKNOWN;
  std::string error;
  EXPECT_EQ(FromFullMapMessage(msg, true, &error)->CountOccupied(), 4);
  EXPECT_EQ(FromFullMapMessage(msg, false, &error)->CountOccupied(), 3);
}

TEST(ConvertMap, AppliesDeltas) {
  OccupancyGrid<3> grid = SampleGrid();
  map_update_t delta = ToFullMapMessage(grid, 0, 2);
  delta.is_full = false;
  delta.indices = {0, static_cast<std::int32_t>(grid.geometry().Index(1, 2, 3))};
  delta.values = {map_update_t::FREE, map_update_t::OCCUPIED};
  delta.num_indices = delta.num_values = 2;
  std::string error;
  ASSERT_TRUE(ApplyMapDelta(delta, true, &grid, &error)) << error;
  EXPECT_FALSE(grid.IsOccupied(0, 0, 0));
  EXPECT_TRUE(grid.IsOccupied(1, 2, 3));
  EXPECT_EQ(grid.CountOccupied(), 3);
  delta.indices[1] = static_cast<std::int32_t>(grid.geometry().NumCells());
  EXPECT_FALSE(ApplyMapDelta(delta, true, &grid, &error));
  EXPECT_TRUE(grid.IsOccupied(1, 2, 3));  // unchanged by a refused delta
}

TEST(ConvertMap, RejectsBadSnapshots) {
  std::string error;
  map_update_t msg = ToFullMapMessage(SampleGrid(), 0, 1);
  msg.values.pop_back();
  EXPECT_FALSE(FromFullMapMessage(msg, true, &error));
  EXPECT_NE(error.find("values"), std::string::npos);
  msg = ToFullMapMessage(SampleGrid(), 0, 1);
  msg.values[3] = 7;
  EXPECT_FALSE(FromFullMapMessage(msg, true, &error));
  msg = ToFullMapMessage(SampleGrid(), 0, 1);
  msg.resolution_m = -0.1;
  EXPECT_FALSE(FromFullMapMessage(msg, true, &error));
  msg = ToFullMapMessage(SampleGrid(), 0, 1);
  msg.is_full = false;
  EXPECT_FALSE(FromFullMapMessage(msg, true, &error));
}

}  // namespace
}  // namespace topay::msgs
