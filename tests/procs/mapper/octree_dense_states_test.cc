#include "procs/mapper/octree_dense_states.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"

namespace topay::mapper {
namespace {

// A small grid aligned with the tree's voxels: 4 x 4 x 1.6 m at 0.05 m (80 x 80 x 32).
GridGeometry3 SmallGrid() {
  return GridGeometry3::FromBounds(
      Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1.6)), 0.05);
}

VoxelState StateOf(const octomap::OcTree& tree, const Eigen::Vector3d& p) {
  const octomap::OcTreeNode* node = tree.search(p.x(), p.y(), p.z());
  if (node == nullptr) return VoxelState::kUnknown;
  return tree.isNodeOccupied(node) ? VoxelState::kOccupied : VoxelState::kFree;
}

TEST(OctreeDenseStatesTest, APriorGivesTheVoxelsInsertedIntoIt) {
  OctomapMirrorOptions options;
  options.bounds_W_m = SmallGrid().Bounds();
  OctomapMirror mirror(options);
  std::vector<Eigen::Vector3f> wall;
  for (int i = 0; i < 30; ++i) wall.emplace_back(1.52f, -0.675f + 0.05f * i, 0.77f);
  mirror.Insert(Eigen::Vector3d(0.01, 0.01, 0.51), wall);
  const GridGeometry3 grid = SmallGrid();
  const std::vector<VoxelState> states = DenseStatesFromOcTree(mirror.tree(), grid);
  ASSERT_EQ(static_cast<std::int64_t>(states.size()), grid.NumCells());
  int occupied = 0, free = 0;
  for (int iz = 0; iz < grid.dims.z(); ++iz) {
    for (int iy = 0; iy < grid.dims.y(); ++iy) {
      for (int ix = 0; ix < grid.dims.x(); ++ix) {
        const VoxelState state = states[grid.Index(ix, iy, iz)];
        ASSERT_EQ(state, StateOf(mirror.tree(), grid.CellCenter(ix, iy, iz)))
            << ix << " " << iy << " " << iz;
        occupied += state == VoxelState::kOccupied;
        free += state == VoxelState::kFree;
      }
    }
  }
  EXPECT_EQ(occupied, 30);
  EXPECT_GT(free, 500);
  const Eigen::Vector3i hit = grid.CellOf(Eigen::Vector3d(1.52, 0.0, 0.77));
  EXPECT_EQ(states[grid.Index(hit.x(), hit.y(), hit.z())], VoxelState::kOccupied);
}

TEST(OctreeDenseStatesTest, DenseToTreeToDenseIsTheIdentity) {
  const GridGeometry3 grid = SmallGrid();
  std::vector<VoxelState> states(grid.NumCells(), VoxelState::kUnknown);
  Rng rng(4);
  for (VoxelState& state : states) {
    const double u = rng.Uniform(0.0, 1.0);
    if (u < 0.1) state = VoxelState::kOccupied;
    else if (u < 0.6) state = VoxelState::kFree;
  }
  // A solid free block of 16^3 voxels that the tree prunes into larger leaves.
  for (int iz = 0; iz < 16; ++iz) {
    for (int iy = 0; iy < 16; ++iy) {
      for (int ix = 40; ix < 56; ++ix) states[grid.Index(ix, iy, iz)] = VoxelState::kFree;
    }
  }
  const std::unique_ptr<octomap::OcTree> tree = OcTreeFromDenseStates(states, grid, {});
  EXPECT_DOUBLE_EQ(tree->getResolution(), 0.05);
  const auto known = std::count_if(states.begin(), states.end(),
                                   [](VoxelState s) { return s != VoxelState::kUnknown; });
  EXPECT_LT(tree->getNumLeafNodes(), known - 4000);  // the block is pruned into 8^3 leaves
  EXPECT_EQ(DenseStatesFromOcTree(*tree, grid), states);
}

TEST(OctreeDenseStatesTest, CoarserTreeLeavesFillEveryVoxelTheyCover) {
  octomap::OcTree tree(0.1);
  // The leaf [0, 0.1) x [0, 0.1) x [0.5, 0.6): 2 x 2 x 2 voxels of the grid.
  tree.updateNode(octomap::point3d(0.05f, 0.05f, 0.55f), true);
  const std::vector<VoxelState> states = DenseStatesFromOcTree(tree, SmallGrid());
  const GridGeometry3 grid = SmallGrid();
  int occupied = 0;
  for (VoxelState s : states) occupied += s == VoxelState::kOccupied;
  EXPECT_EQ(occupied, 8);
  const Eigen::Vector3i cell = grid.CellOf(Eigen::Vector3d(0.075, 0.025, 0.575));
  EXPECT_EQ(states[grid.Index(cell.x(), cell.y(), cell.z())], VoxelState::kOccupied);
}

TEST(OctreeDenseStatesTest, WrongSizesAreRejected) {
  const std::vector<VoxelState> states(10, VoxelState::kFree);
  EXPECT_THROW(OcTreeFromDenseStates(states, SmallGrid(), {}), std::invalid_argument);
}

}  // namespace
}  // namespace topay::mapper
