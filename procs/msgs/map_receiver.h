#pragma once
// The receiving end of MAP_UPDATE: the receiver's copy of the mapper's voxel grid, kept equal
// to the sender's by snapshots and the deltas between them; a receiver that joined late or
// missed a delta ignores deltas until the next snapshot.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/map/grid_geometry.h"
#include "core/map/voxel_map_fields.h"
#include "procs/msgs/map_codec.h"
#include "topay/map_update_t.hpp"

namespace topay::msgs {

/// What MapReceiver::Accept did with a message.
enum class MapUpdateOutcome {
  /// A full map replaced the grid (geometry and every state): rebuild what derives from it
  /// (e.g. VoxelMapFields from states()).
  kSnapshotApplied,
  /// A delta to the grid's map_seq was applied: `changes` lists what it set (for
  /// VoxelMapFields::ApplyChanges).
  kDeltaApplied,
  /// A valid delta that does not follow the grid (no snapshot yet, map_seq other than
  /// last + 1, or another geometry): ignored; the grid waits for the next snapshot.
  kWaitingForSnapshot,
  /// A malformed message (`error` names the field and the place): ignored, grid unchanged.
  kRejected,
};

/// The outcome of one message.
struct MapAcceptResult {
  MapUpdateOutcome outcome = MapUpdateOutcome::kRejected;
  /// kDeltaApplied: the changes in the order applied (compressed deltas: each voxel once, by
  /// index). Empty otherwise.
  std::vector<VoxelChange> changes;
  /// kRejected: the decoder's error ("map_update_t.<field>: ..."); kWaitingForSnapshot: why.
  std::string reason;
};

/// How many messages ended in each outcome since construction.
struct MapReceiverCounts {
  std::int64_t snapshots = 0;
  std::int64_t deltas = 0;
  std::int64_t waiting = 0;
  std::int64_t rejected = 0;
};

/// The receiver's copy of the map. Not thread safe.
class MapReceiver {
 public:
  /// `options` bound what a message may make it allocate (MapCodecOptions::max_voxels).
  explicit MapReceiver(const MapCodecOptions& options = {});

  /// Decodes `msg` (every field checked) and applies it if it continues the grid. A full map
  /// always applies (whatever its map_seq: the sender may have restarted); a delta applies
  /// only on top of a snapshot of the same geometry with map_seq = last + 1, and after a
  /// missed delta no delta applies until the next full map.
  MapAcceptResult Accept(const map_update_t& msg);

  /// True once a snapshot has been applied.
  bool has_map() const { return has_map_; }
  /// False after a delta was missed (or before the first snapshot): deltas are ignored.
  bool in_sync() const { return in_sync_; }
  /// The grid of the last snapshot (meaningless before has_map()).
  const GridGeometry3& geometry() const { return geometry_; }
  /// One VoxelState per voxel, linear order (GridGeometry3::Index); empty before has_map().
  std::span<const std::uint8_t> states() const { return states_; }
  VoxelState state(int ix, int iy, int iz) const {
    return static_cast<VoxelState>(states_[geometry_.Index(ix, iy, iz)]);
  }
  /// map_seq and utime of the last update applied.
  std::int64_t map_seq() const { return map_seq_; }
  std::int64_t utime() const { return utime_; }
  const MapReceiverCounts& counts() const { return counts_; }

 private:
  MapAcceptResult AcceptFull(const map_update_t& msg);
  MapAcceptResult AcceptDelta(const map_update_t& msg);
  // Why a valid delta cannot apply to the grid (nullopt: it can).
  std::optional<std::string> WhyNotNext(const DecodedMapDelta& delta) const;
  MapAcceptResult Rejected(std::string error);
  MapAcceptResult Waiting(std::string reason);

  MapCodecOptions options_;
  bool has_map_ = false;
  bool in_sync_ = false;
  GridGeometry3 geometry_;
  std::vector<std::uint8_t> states_;
  std::int64_t map_seq_ = 0;
  std::int64_t utime_ = 0;
  MapReceiverCounts counts_;
};

}  // namespace topay::msgs
