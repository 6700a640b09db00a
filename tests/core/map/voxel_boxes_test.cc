#include "core/map/voxel_boxes.h"

#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/map/occupancy_map.h"
#include "tests/common/make_box.h"
#include "tests/core/map/scanned_room.h"

namespace topay {
namespace {

// Each voxel's count of boxes covering it (rasterising the index boxes back).
std::vector<int> CoverCounts(const Eigen::Vector3i& dims, const std::vector<CellBox>& boxes) {
  std::vector<int> counts(static_cast<std::size_t>(dims.prod()), 0);
  for (const CellBox& b : boxes) {
    EXPECT_FALSE(b.empty());
    EXPECT_TRUE((b.begin.array() >= 0).all() && (b.end.array() <= dims.array()).all());
    for (int z = b.begin.z(); z < b.end.z(); ++z)
      for (int y = b.begin.y(); y < b.end.y(); ++y)
        for (int x = b.begin.x(); x < b.end.x(); ++x) ++counts[(z * dims.y() + y) * dims.x() + x];
  }
  return counts;
}

// The boxes cover the voxels equal to `value` once each and no other voxel.
void ExpectExactDisjointCover(const Eigen::Vector3i& dims, const std::vector<std::uint8_t>& cells,
                              std::uint8_t value, const std::vector<CellBox>& boxes) {
  const std::vector<int> counts = CoverCounts(dims, boxes);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    ASSERT_EQ(counts[i], cells[i] == value ? 1 : 0) << "voxel " << i;
  }
}

TEST(VoxelBoxesTest, RandomGridsAreCoveredExactlyByDisjointBoxes) {
  Rng rng(5);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3i dims(static_cast<int>(rng.UniformInt(1, 12)),
                               static_cast<int>(rng.UniformInt(1, 12)),
                               static_cast<int>(rng.UniformInt(1, 6)));
    const double density = rng.Uniform(0.05, 0.95);
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(dims.prod()));
    for (auto& c : cells) c = rng.Uniform01() < density ? 1 : (rng.Uniform01() < 0.5 ? 0 : 2);
    ExpectExactDisjointCover(dims, cells, 1, MergeVoxelsIntoBoxes(dims, cells, 1));
    ExpectExactDisjointCover(dims, cells, 2, MergeVoxelsIntoBoxes(dims, cells, 2));
    if (HasFatalFailure()) return;
  }
}

TEST(VoxelBoxesTest, ASolidBlockIsOneBoxAndAnEmptyGridNone) {
  const Eigen::Vector3i dims(10, 8, 6);
  std::vector<std::uint8_t> cells(dims.prod(), 0);
  EXPECT_TRUE(MergeVoxelsIntoBoxes(dims, cells, 1).empty());
  for (int z = 1; z < 5; ++z)
    for (int y = 2; y < 7; ++y)
      for (int x = 3; x < 9; ++x) cells[(z * dims.y() + y) * dims.x() + x] = 1;
  const std::vector<CellBox> boxes = MergeVoxelsIntoBoxes(dims, cells, 1);
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(boxes[0].begin, Eigen::Vector3i(3, 2, 1));
  EXPECT_EQ(boxes[0].end, Eigen::Vector3i(9, 7, 5));
  EXPECT_THROW(MergeVoxelsIntoBoxes(dims, std::span(cells).first(10), 1), std::invalid_argument);
}

TEST(VoxelBoxesTest, WorldBoxesRasteriseBackToTheSameVoxels) {
  // Dyadic geometry: box faces fall exactly on voxel boundaries, so the conservative
  // rasteriser (OccupancyGrid3::AddBox) leaves the merely touched neighbours free.
  const GridGeometry3 g = GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-2, -1, 0), Eigen::Vector3d(2, 1, 1)), 0.0625);
  OccupancyGrid3 grid(g);
  grid.AddBox(MakeBox({0.3, 0.2, 0.4}, {0.7, 0.33, 0.5}, 0.4));  // rotated: a staircase
  grid.AddBox(MakeBox({-1.0, -0.4, 0.2}, {0.5, 0.1, 0.4}));
  grid.AddBox(MakeBox({1.2, 0.5, 0.7}, {0.2, 0.6, 0.05}, -0.9));
  const std::vector<OrientedBox> boxes = OccupiedVoxelBoxes(grid);
  OccupancyGrid3 back(g);
  for (const OrientedBox& box : boxes) {
    EXPECT_EQ(box.yaw_rad, 0.0);
    back.AddBox(box);
  }
  EXPECT_EQ(back.cells(), grid.cells());
  EXPECT_LT(static_cast<std::int64_t>(boxes.size()), grid.CountOccupied() / 4);
}

TEST(VoxelBoxesTest, AScannedRoomNeedsFewerBoxesThanVoxels) {
  const testing::ScannedRoom room = testing::ScanRoom(SceneKind::kTables, 2, 4, 0.02);
  OccupancyMapOptions options;
  options.bounds_W_m = room.scene.bounds_W_m;
  OccupancyMap map(options);
  for (const testing::WorldScan& scan : room.scans) map.InsertScan(scan.p_WS, scan.p_WP, nullptr);
  const GridGeometry3& g = map.geometry();
  const std::vector<std::uint8_t> states(map.states().begin(), map.states().end());
  const std::vector<CellBox> voxel_boxes =
      MergeVoxelsIntoBoxes(g.dims, states, static_cast<std::uint8_t>(VoxelState::kOccupied));
  ExpectExactDisjointCover(g.dims, states, static_cast<std::uint8_t>(VoxelState::kOccupied),
                           voxel_boxes);
  const std::vector<OrientedBox> boxes = OccupiedVoxelBoxes(g, map.states());
  ASSERT_EQ(boxes.size(), voxel_boxes.size());
  const std::int64_t occupied = map.CountStates().occupied;
  ASSERT_GT(occupied, 10000);
  std::cout << "scanned room: occupied voxels " << occupied << " -> boxes " << boxes.size()
            << "\n";
  // Surfaces sensed with 2 cm noise are ragged shells 1-2 voxels thick: about two voxels a
  // box (11,907 boxes for 20,281 voxels here; a greedy box growing along x, y, z in turn gave
  // 11,203, no better).
  EXPECT_LT(static_cast<std::int64_t>(boxes.size()), occupied * 2 / 3);
  // A box and its voxels: the world box spans them exactly.
  const OrientedBox& b = boxes.front();
  const CellBox& v = voxel_boxes.front();
  EXPECT_NEAR(b.size_m.x(), g.resolution_m * (v.end.x() - v.begin.x()), 1e-9);
  EXPECT_NEAR(b.center_W_m.z(), g.origin_W_m.z() + 0.5 * g.resolution_m * (v.begin.z() + v.end.z()),
              1e-9);
}

TEST(VoxelBoxesTest, ARasterisedRoomNeedsFarFewerBoxesThanVoxels) {
  const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 2).scene;
  OccupancyGrid3 grid(GridGeometry3::FromBounds(scene.bounds_W_m, 0.05));
  for (const OrientedBox& box : scene.boxes) grid.AddBox(box);
  const std::vector<CellBox> boxes =
      MergeVoxelsIntoBoxes(grid.geometry().dims, grid.cells(), 1);
  ExpectExactDisjointCover(grid.geometry().dims, grid.cells(), 1, boxes);
  std::cout << "rasterised room: " << scene.boxes.size() << " boxes, occupied voxels "
            << grid.CountOccupied() << " -> boxes " << boxes.size() << "\n";
  EXPECT_LT(static_cast<std::int64_t>(boxes.size()), grid.CountOccupied() / 20);
}

}  // namespace
}  // namespace topay
