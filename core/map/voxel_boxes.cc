#include "core/map/voxel_boxes.h"

#include <algorithm>
#include <array>
#include <stdexcept>

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

}  // namespace topay
