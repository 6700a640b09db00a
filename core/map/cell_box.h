#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace topay {

/// A box of grid cells, half-open: the cells i with begin <= i < end on every axis (x, y, z;
/// a 2D grid uses z = [0, 1)). Used to name the windows of a field that a map change forces to
/// recompute (core/map/voxel_map_fields.h).
struct CellBox {
  Eigen::Vector3i begin = Eigen::Vector3i::Zero();
  Eigen::Vector3i end = Eigen::Vector3i::Zero();

  bool empty() const { return (end.array() <= begin.array()).any(); }
  Eigen::Vector3i sizes() const { return (end - begin).cwiseMax(0); }
  std::int64_t NumCells() const {
    const Eigen::Vector3i s = sizes();
    return std::int64_t{s.x()} * s.y() * s.z();
  }
  /// The box grown by `by` cells on each side of each axis, clipped to [0, dims).
  CellBox Dilated(const Eigen::Vector3i& by, const Eigen::Vector3i& dims) const {
    return {(begin - by).cwiseMax(0), (end + by).cwiseMin(dims)};
  }
  /// The smallest box holding both.
  CellBox Union(const CellBox& other) const {
    return {begin.cwiseMin(other.begin), end.cwiseMax(other.end)};
  }
  bool Contains(const Eigen::Vector3i& cell) const {
    return (cell.array() >= begin.array()).all() && (cell.array() < end.array()).all();
  }
};

/// The boxes of changed cells grouped by tiles of `tile` cells per axis: one box per tile
/// that holds a cell, the bounds of its cells. `cells` must lie in [0, dims) (not checked).
/// Allocation: the result and a sorted copy of the cells.
std::vector<CellBox> TileBoundsOfCells(std::span<const Eigen::Vector3i> cells,
                                       const Eigen::Vector3i& tile);

/// Covers `boxes` with fewer, larger boxes where that saves work: two boxes are replaced by
/// their union while the union's cost is at most the sum of theirs, the cost of a box being
/// the cells of the box grown by `source_reach` (clipped to [0, dims)), the cells a window
/// recomputation reads. Repeats until no pair merges. Every input cell stays covered; the
/// result's boxes may overlap (a cell recomputed twice gets the same value). Quadratic in the
/// boxes per round: above `max_boxes` boxes, returns the single union instead. When the
/// boxes' costs add up to more than the whole grid's cells, returns the whole grid (one
/// recomputation of everything reads less).
std::vector<CellBox> MergeCellBoxes(std::vector<CellBox> boxes, const Eigen::Vector3i& source_reach,
                                    const Eigen::Vector3i& dims, int max_boxes = 256);

}  // namespace topay
