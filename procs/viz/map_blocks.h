#pragma once
// The map as the viewer forwards it: MAP_UPDATE messages kept in a receiver's grid, and the
// occupied voxels sent as 16^3 blocks, only the blocks that changed since the last message
// (docs/viewer.md: MapBlocks). A full Tables map is a few hundred kB once; then a scan changes a
// few blocks.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "procs/msgs/map_receiver.h"
#include "topay/map_update_t.hpp"

namespace topay::viz {

/// Edge of a block, voxels (local indices fit a uint16).
inline constexpr int kMapBlockEdge = 16;

class MapBlocks {
 public:
  MapBlocks() = default;

  /// Applies a message (msgs::MapReceiver: malformed ones and deltas out of sequence are
  /// ignored) and marks the blocks it touched. Returns the receiver's outcome.
  msgs::MapAcceptResult Accept(const map_update_t& msg);

  /// True if blocks changed since the last Changes() (or a snapshot is pending).
  bool dirty() const { return reset_pending_ || !dirty_blocks_.empty(); }

  /// The MapBlocks payload of what changed since the last call (reset after a snapshot), and
  /// forgets it; nullopt if nothing changed or there is no map yet.
  std::optional<nlohmann::json> Changes(double t);

  /// The whole map as one reset payload (a new subscriber, a seek); nullopt if no map yet.
  std::optional<nlohmann::json> Full(double t) const;

  std::int64_t occupied_total() const { return occupied_total_; }
  const msgs::MapReceiver& receiver() const { return receiver_; }

 private:
  int BlockOf(int ix, int iy, int iz) const;
  nlohmann::json BlockJson(int block) const;
  nlohmann::json Payload(double t, bool reset, nlohmann::json blocks) const;
  void ResetBlocks();
  void CountBlock(int block);

  msgs::MapReceiver receiver_;
  Eigen::Vector3i blocks_per_axis_ = Eigen::Vector3i::Zero();
  std::vector<int> block_occupied_;     // occupied voxels per block
  std::vector<std::uint8_t> is_dirty_;  // per block
  std::vector<int> dirty_blocks_;
  bool reset_pending_ = false;
  std::int64_t occupied_total_ = 0;
};

}  // namespace topay::viz
