#include "procs/mapper/octree_dense_states.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace topay::mapper {
namespace {

// The cells whose centres lie in [lo, hi) on axis a, clamped to the grid: [*first, *last].
bool CellRange(const GridGeometry3& grid, int a, double lo, double hi, int* first, int* last) {
  const double o = grid.origin_W_m(a), r = grid.resolution_m;
  *first = std::max(0, static_cast<int>(std::ceil((lo - o) / r - 0.5)));
  *last = std::min(grid.dims(a) - 1, static_cast<int>(std::ceil((hi - o) / r - 0.5)) - 1);
  return *first <= *last;
}

// Sets every cell whose centre lies in the cube of side `size` about `center`.
void FillLeaf(const GridGeometry3& grid, const octomap::point3d& center, double size,
              VoxelState state, std::vector<VoxelState>* states) {
  int first[3], last[3];
  for (int a = 0; a < 3; ++a) {
    if (!CellRange(grid, a, center(a) - 0.5 * size, center(a) + 0.5 * size, &first[a],
                   &last[a])) {
      return;
    }
  }
  for (int iz = first[2]; iz <= last[2]; ++iz) {
    for (int iy = first[1]; iy <= last[1]; ++iy) {
      const std::int64_t row = grid.Index(0, iy, iz);
      std::fill(states->begin() + row + first[0], states->begin() + row + last[0] + 1, state);
    }
  }
}

}  // namespace

std::vector<VoxelState> DenseStatesFromOcTree(const octomap::OcTree& tree,
                                              const GridGeometry3& grid) {
  grid.Validate("DenseStatesFromOcTree");
  std::vector<VoxelState> states(grid.NumCells(), VoxelState::kUnknown);
  // Leaves touching the grid's box (its outer voxel centres, so no neighbour key is asked).
  const Eigen::Vector3d inset = Eigen::Vector3d::Constant(0.5 * grid.resolution_m);
  const Eigen::AlignedBox3d bounds = grid.Bounds();
  const octomap::point3d min = ToOctomapPoint(bounds.min() + inset);
  const octomap::point3d max = ToOctomapPoint(bounds.max() - inset);
  for (auto it = tree.begin_leafs_bbx(min, max); it != tree.end_leafs_bbx(); ++it) {
    const VoxelState state = tree.isNodeOccupied(*it) ? VoxelState::kOccupied : VoxelState::kFree;
    FillLeaf(grid, it.getCoordinate(), it.getSize(), state, &states);
  }
  return states;
}

std::unique_ptr<octomap::OcTree> OcTreeFromDenseStates(std::span<const VoxelState> states,
                                                       const GridGeometry3& grid,
                                                       const OctomapMirrorOptions& options) {
  grid.Validate("OcTreeFromDenseStates");
  if (static_cast<std::int64_t>(states.size()) != grid.NumCells()) {
    throw std::invalid_argument("OcTreeFromDenseStates: " + std::to_string(states.size()) +
                                " states for a grid of " + std::to_string(grid.NumCells()) +
                                " cells");
  }
  auto tree = std::make_unique<octomap::OcTree>(grid.resolution_m);
  ApplySensorModel(options, tree.get());
  const float occupied = tree->getClampingThresMaxLog(), free = tree->getClampingThresMinLog();
  for (int iz = 0; iz < grid.dims.z(); ++iz) {
    for (int iy = 0; iy < grid.dims.y(); ++iy) {
      for (int ix = 0; ix < grid.dims.x(); ++ix) {
        const VoxelState state = states[grid.Index(ix, iy, iz)];
        if (state == VoxelState::kUnknown) continue;
        const octomap::point3d center = ToOctomapPoint(grid.CellCenter(ix, iy, iz));
        // lazy_eval: inner nodes are updated once, below.
        tree->setNodeValue(center, state == VoxelState::kOccupied ? occupied : free, true);
      }
    }
  }
  tree->updateInnerOccupancy();
  tree->prune();
  return tree;
}

}  // namespace topay::mapper
