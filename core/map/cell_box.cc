#include "core/map/cell_box.h"

#include <algorithm>
#include <tuple>

namespace topay {

std::vector<CellBox> TileBoundsOfCells(std::span<const Eigen::Vector3i> cells,
                                       const Eigen::Vector3i& tile) {
  // Sort the cells by tile (z, y, x), then take the bounds of each run of one tile.
  auto tile_of = [&tile](const Eigen::Vector3i& c) {
    return std::make_tuple(c.z() / tile.z(), c.y() / tile.y(), c.x() / tile.x());
  };
  std::vector<Eigen::Vector3i> sorted(cells.begin(), cells.end());
  std::sort(sorted.begin(), sorted.end(), [&](const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    return tile_of(a) < tile_of(b);
  });
  std::vector<CellBox> boxes;
  for (std::size_t i = 0; i < sorted.size();) {
    CellBox box{sorted[i], sorted[i] + Eigen::Vector3i::Ones()};
    std::size_t j = i + 1;
    for (; j < sorted.size() && tile_of(sorted[j]) == tile_of(sorted[i]); ++j) {
      box = box.Union({sorted[j], sorted[j] + Eigen::Vector3i::Ones()});
    }
    boxes.push_back(box);
    i = j;
  }
  return boxes;
}

std::vector<CellBox> MergeCellBoxes(std::vector<CellBox> boxes, const Eigen::Vector3i& source_reach,
                                    const Eigen::Vector3i& dims, int max_boxes) {
  if (boxes.empty()) return boxes;
  auto cost = [&](const CellBox& box) { return box.Dilated(source_reach, dims).NumCells(); };
  if (static_cast<int>(boxes.size()) > max_boxes) {
    CellBox all = boxes.front();
    for (const CellBox& box : boxes) all = all.Union(box);
    return {all};
  }
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t i = 0; i < boxes.size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < boxes.size(); ++j) {
        const CellBox both = boxes[i].Union(boxes[j]);
        if (cost(both) <= cost(boxes[i]) + cost(boxes[j])) {
          boxes[i] = both;
          boxes.erase(boxes.begin() + static_cast<std::ptrdiff_t>(j));
          merged = true;
          break;
        }
      }
    }
  }
  std::int64_t total = 0;
  for (const CellBox& box : boxes) total += cost(box);
  const CellBox grid{Eigen::Vector3i::Zero(), dims};
  if (total > grid.NumCells()) return {grid};
  return boxes;
}

}  // namespace topay
