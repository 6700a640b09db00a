#include "procs/viz/map_blocks.h"

#include <algorithm>

#include "procs/viz/base64.h"

namespace topay::viz {
namespace {

constexpr std::uint8_t kOccupied = static_cast<std::uint8_t>(VoxelState::kOccupied);

}  // namespace

msgs::MapAcceptResult MapBlocks::Accept(const map_update_t& msg) {
  msgs::MapAcceptResult result = receiver_.Accept(msg);
  if (result.outcome == msgs::MapUpdateOutcome::kSnapshotApplied) {
    ResetBlocks();
  } else if (result.outcome == msgs::MapUpdateOutcome::kDeltaApplied) {
    // Recount only the blocks this delta touched (the earlier dirty ones are counted already).
    std::vector<int> touched;
    for (const VoxelChange& change : result.changes) {
      touched.push_back(BlockOf(change.voxel.x(), change.voxel.y(), change.voxel.z()));
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (int block : touched) {
      CountBlock(block);
      if (!is_dirty_[block]) {
        is_dirty_[block] = 1;
        dirty_blocks_.push_back(block);
      }
    }
  }
  return result;
}

void MapBlocks::ResetBlocks() {
  const Eigen::Vector3i& dims = receiver_.geometry().dims;
  blocks_per_axis_ = (dims.array() + kMapBlockEdge - 1) / kMapBlockEdge;
  const int num_blocks = blocks_per_axis_.prod();
  block_occupied_.assign(num_blocks, 0);
  is_dirty_.assign(num_blocks, 0);
  dirty_blocks_.clear();
  occupied_total_ = 0;
  for (int block = 0; block < num_blocks; ++block) CountBlock(block);
  reset_pending_ = true;
}

int MapBlocks::BlockOf(int ix, int iy, int iz) const {
  const int bx = ix / kMapBlockEdge, by = iy / kMapBlockEdge, bz = iz / kMapBlockEdge;
  return (bz * blocks_per_axis_.y() + by) * blocks_per_axis_.x() + bx;
}

// Calls f(local index, voxel occupied) for every voxel of a block inside the grid.
template <class F>
void ForEachVoxel(const msgs::MapReceiver& map, const Eigen::Vector3i& blocks, int block, F f) {
  const Eigen::Vector3i& dims = map.geometry().dims;
  const int bx = block % blocks.x(), by = (block / blocks.x()) % blocks.y(), bz = block / (blocks.x() * blocks.y());
  const std::span<const std::uint8_t> states = map.states();
  for (int lz = 0; lz < kMapBlockEdge; ++lz) {
    const int iz = bz * kMapBlockEdge + lz;
    if (iz >= dims.z()) break;
    for (int ly = 0; ly < kMapBlockEdge; ++ly) {
      const int iy = by * kMapBlockEdge + ly;
      if (iy >= dims.y()) break;
      const std::int64_t row = map.geometry().Index(0, iy, iz);
      for (int lx = 0; lx < kMapBlockEdge; ++lx) {
        const int ix = bx * kMapBlockEdge + lx;
        if (ix >= dims.x()) break;
        f(lx + kMapBlockEdge * (ly + kMapBlockEdge * lz), states[row + ix] == kOccupied);
      }
    }
  }
}

void MapBlocks::CountBlock(int block) {
  int count = 0;
  ForEachVoxel(receiver_, blocks_per_axis_, block, [&](int, bool occupied) { count += occupied; });
  occupied_total_ += count - block_occupied_[block];
  block_occupied_[block] = count;
}

nlohmann::json MapBlocks::BlockJson(int block) const {
  std::vector<std::uint16_t> occupied;
  occupied.reserve(block_occupied_[block]);
  ForEachVoxel(receiver_, blocks_per_axis_, block, [&](int local, bool is_occupied) {
    if (is_occupied) occupied.push_back(static_cast<std::uint16_t>(local));
  });
  const int bx = block % blocks_per_axis_.x();
  const int by = (block / blocks_per_axis_.x()) % blocks_per_axis_.y();
  const int bz = block / (blocks_per_axis_.x() * blocks_per_axis_.y());
  return {{"key", {bx, by, bz}}, {"occupied", Base64OfUint16(occupied)}};
}

nlohmann::json MapBlocks::Payload(double t, bool reset, nlohmann::json blocks) const {
  const GridGeometry3& g = receiver_.geometry();
  return {{"map_seq", receiver_.map_seq()},
          {"t", t},
          {"resolution_m", g.resolution_m},
          {"origin_W_m", {g.origin_W_m.x(), g.origin_W_m.y(), g.origin_W_m.z()}},
          {"dims", {g.dims.x(), g.dims.y(), g.dims.z()}},
          {"block_edge", kMapBlockEdge},
          {"reset", reset},
          {"blocks", std::move(blocks)},
          {"occupied_total", occupied_total_}};
}

std::optional<nlohmann::json> MapBlocks::Changes(double t) {
  if (!receiver_.has_map() || !dirty()) return std::nullopt;
  if (reset_pending_) {
    std::optional<nlohmann::json> full = Full(t);
    reset_pending_ = false;
    for (int block : dirty_blocks_) is_dirty_[block] = 0;
    dirty_blocks_.clear();
    return full;
  }
  nlohmann::json blocks = nlohmann::json::array();
  for (int block : dirty_blocks_) {
    blocks.push_back(BlockJson(block));
    is_dirty_[block] = 0;
  }
  dirty_blocks_.clear();
  return Payload(t, false, std::move(blocks));
}

std::optional<nlohmann::json> MapBlocks::Full(double t) const {
  if (!receiver_.has_map()) return std::nullopt;
  nlohmann::json blocks = nlohmann::json::array();
  for (int block = 0; block < static_cast<int>(block_occupied_.size()); ++block) {
    if (block_occupied_[block] > 0) blocks.push_back(BlockJson(block));
  }
  return Payload(t, true, std::move(blocks));
}

}  // namespace topay::viz
