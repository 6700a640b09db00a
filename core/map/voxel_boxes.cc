#include "core/map/voxel_boxes.h"

#include <algorithm>
#include <cmath>
#include <array>
#include <stdexcept>
#include <string>

#include "core/map/voxel_state.h"

namespace topay {
namespace {

// A run (in a row) or rectangle (in a layer) still growing along the next axis: it continues
// into the next row / layer while a piece there has the same key and extent.
// Runs: key (x0, 0), extent (x1, 0), start y0. Rectangles: key (y0, x0), extent (x1, y1),
// start z0.
struct OpenPiece {
  std::array<int, 2> key;
  std::array<int, 2> extent;
  int start;
};

bool KeyLess(const OpenPiece& a, const OpenPiece& b) { return a.key < b.key; }

// The open pieces continued by `current` (both sorted by key, keys unique in each) go on
// with their start; the others are closed with close(piece, at); the pieces of `current`
// not continuing one start at `at`. `open` becomes the new open list (`scratch` is reused).
template <typename Close>
void ContinueOrClose(const std::vector<OpenPiece>& current, int at, Close&& close,
                     std::vector<OpenPiece>* open, std::vector<OpenPiece>* scratch) {
  scratch->clear();
  std::size_t o = 0;
  for (const OpenPiece& piece : current) {
    while (o < open->size() && KeyLess((*open)[o], piece)) close((*open)[o++], at);
    if (o < open->size() && (*open)[o].key == piece.key && (*open)[o].extent == piece.extent) {
      scratch->push_back((*open)[o++]);
      continue;
    }
    if (o < open->size() && (*open)[o].key == piece.key) close((*open)[o++], at);
    scratch->push_back({piece.key, piece.extent, at});
  }
  while (o < open->size()) close((*open)[o++], at);
  open->swap(*scratch);
}

// The maximal runs of `value` in one row of nx cells, by x0.
void RowRuns(const std::uint8_t* row, int nx, std::uint8_t value, std::vector<OpenPiece>* runs) {
  runs->clear();
  for (int x = 0; x < nx;) {
    if (row[x] != value) {
      ++x;
      continue;
    }
    const int x0 = x;
    while (x < nx && row[x] == value) ++x;
    runs->push_back({{x0, 0}, {x, 0}, 0});
  }
}

}  // namespace

std::vector<CellBox> MergeVoxelsIntoBoxes(const Eigen::Vector3i& dims,
                                          std::span<const std::uint8_t> cells,
                                          std::uint8_t value) {
  const std::int64_t n = std::int64_t{dims.x()} * dims.y() * dims.z();
  if ((dims.array() < 0).any() || static_cast<std::int64_t>(cells.size()) != n) {
    throw std::invalid_argument("MergeVoxelsIntoBoxes: cells.size() must be dims' product");
  }
  std::vector<CellBox> boxes;
  std::vector<OpenPiece> runs, open_runs, rects, open_rects, scratch;
  // A rectangle closed in layer z becomes a piece of that layer; a box closed at layer z is
  // output.
  const auto close_box = [&](const OpenPiece& r, int z) {
    boxes.push_back({{r.key[1], r.key[0], r.start}, {r.extent[0], r.extent[1], z}});
  };
  for (int z = 0; z < dims.z(); ++z) {
    rects.clear();
    const auto close_rect = [&](const OpenPiece& run, int y) {
      rects.push_back({{run.start, run.key[0]}, {run.extent[0], y}, 0});
    };
    open_runs.clear();
    for (int y = 0; y < dims.y(); ++y) {
      const std::uint8_t* row = cells.data() + (std::int64_t{z} * dims.y() + y) * dims.x();
      RowRuns(row, dims.x(), value, &runs);
      ContinueOrClose(runs, y, close_rect, &open_runs, &scratch);
    }
    for (const OpenPiece& run : open_runs) close_rect(run, dims.y());
    std::sort(rects.begin(), rects.end(), KeyLess);
    ContinueOrClose(rects, z, close_box, &open_rects, &scratch);
  }
  for (const OpenPiece& rect : open_rects) close_box(rect, dims.z());
  return boxes;
}

OrientedBox VoxelBoxInWorld(const GridGeometry3& geometry, const CellBox& voxels) {
  OrientedBox box;
  // Voxel i spans [o + i res, o + (i + 1) res): the box from begin's min to end's min corner.
  const Eigen::Vector3d min_W = geometry.origin_W_m + geometry.resolution_m * voxels.begin.cast<double>();
  const Eigen::Vector3d max_W = geometry.origin_W_m + geometry.resolution_m * voxels.end.cast<double>();
  box.center_W_m = 0.5 * (min_W + max_W);
  box.size_m = max_W - min_W;
  return box;
}

std::vector<OrientedBox> OccupiedVoxelBoxes(const GridGeometry3& geometry,
                                            std::span<const std::uint8_t> states) {
  const std::vector<CellBox> voxels = MergeVoxelsIntoBoxes(
      geometry.dims, states, static_cast<std::uint8_t>(VoxelState::kOccupied));
  std::vector<OrientedBox> boxes;
  boxes.reserve(voxels.size());
  for (const CellBox& v : voxels) boxes.push_back(VoxelBoxInWorld(geometry, v));
  return boxes;
}

std::vector<OrientedBox> OccupiedVoxelBoxes(const OccupancyGrid3& grid) {
  // OccupancyGrid3 cells are 1 when occupied, as VoxelState::kOccupied.
  static_assert(static_cast<std::uint8_t>(VoxelState::kOccupied) == 1);
  return OccupiedVoxelBoxes(grid.geometry(), grid.cells());
}

bool VoxelBlocksPlanner(VoxelState state, UnknownVoxelPolicy unknown) {
  if (state == VoxelState::kOccupied) return true;
  return state == VoxelState::kUnknown && unknown == UnknownVoxelPolicy::kOccupied;
}

std::vector<OrientedBox> BlockedVoxelBoxes(const GridGeometry3& geometry,
                                           std::span<const std::uint8_t> states,
                                           UnknownVoxelPolicy unknown, CellBox region) {
  if (static_cast<std::int64_t>(states.size()) != geometry.NumCells()) {
    throw std::invalid_argument("BlockedVoxelBoxes: " + std::to_string(states.size()) +
                                " states for a grid of " + std::to_string(geometry.NumCells()) +
                                " voxels");
  }
  region = {region.begin.cwiseMax(0), region.end.cwiseMin(geometry.dims)};
  if (region.empty()) return {};
  const Eigen::Vector3i n = region.sizes();
  std::vector<std::uint8_t> blocked(static_cast<std::size_t>(region.NumCells()));
  std::size_t k = 0;
  for (int iz = region.begin.z(); iz < region.end.z(); ++iz) {
    for (int iy = region.begin.y(); iy < region.end.y(); ++iy) {
      const std::int64_t row = geometry.Index(region.begin.x(), iy, iz);
      for (int i = 0; i < n.x(); ++i) {
        blocked[k++] = VoxelBlocksPlanner(static_cast<VoxelState>(states[row + i]), unknown);
      }
    }
  }
  std::vector<OrientedBox> boxes;
  for (CellBox box : MergeVoxelsIntoBoxes(n, blocked, 1)) {
    box.begin += region.begin;
    box.end += region.begin;
    boxes.push_back(VoxelBoxInWorld(geometry, box));
  }
  return boxes;
}

std::vector<OrientedBox> BlockedVoxelBoxes(const GridGeometry3& geometry,
                                           std::span<const std::uint8_t> states,
                                           UnknownVoxelPolicy unknown) {
  return BlockedVoxelBoxes(geometry, states, unknown, CellBox{Eigen::Vector3i::Zero(), geometry.dims});
}

CellBox VoxelsOverlapping(const GridGeometry3& geometry, const Eigen::AlignedBox3d& box_W_m) {
  if (box_W_m.isEmpty()) return {};
  // Voxels whose interior meets the box (a box face on a voxel face takes no voxel beyond it;
  // 1e-9 voxel absorbs the rounding of coordinates given on the grid).
  const Eigen::Vector3d lo = (box_W_m.min() - geometry.origin_W_m) / geometry.resolution_m;
  const Eigen::Vector3d hi = (box_W_m.max() - geometry.origin_W_m) / geometry.resolution_m;
  Eigen::Vector3i begin, end;
  for (int a = 0; a < 3; ++a) {
    begin[a] = static_cast<int>(std::clamp(std::floor(lo[a] + 1e-9), 0.0, double(geometry.dims[a])));
    end[a] = static_cast<int>(std::clamp(std::ceil(hi[a] - 1e-9), 0.0, double(geometry.dims[a])));
  }
  // A flat box (a point, a face) still meets the voxel it lies in.
  for (int a = 0; a < 3; ++a) {
    if (end[a] <= begin[a] && begin[a] < geometry.dims[a] && hi[a] >= lo[a]) end[a] = begin[a] + 1;
  }
  return {begin, end};
}

}  // namespace topay
