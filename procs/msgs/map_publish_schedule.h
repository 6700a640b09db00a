#pragma once
// When the mapper publishes MAP_UPDATE as a full snapshot and when as a delta, and the
// map_seq each update carries.

#include <cstdint>

namespace topay::msgs {

struct MapPublishScheduleOptions {
  /// A full snapshot at least this often, seconds (finite, > 0). 5 s (default): a subscriber
  /// that joins late or misses a delta has the map again within 5 s, while snapshots, the
  /// costlier messages (a mapped 400 x 400 x 32 room: about 64 kB and 5 to 10 ms to encode,
  /// against about 5 kB and under 1 ms for a scan's delta of 5,000 changes,
  /// tests/bench/map_codec_bench.cc), stay 2 % of the updates at 10 Hz.
  double snapshot_period_s = 5.0;
  /// map_seq of the first update; each update increments it by 1.
  std::int64_t first_map_seq = 1;
};

/// One update's kind and sequence number.
struct MapPublishStep {
  bool is_full = true;       ///< A full snapshot (else a delta to map_seq - 1).
  std::int64_t map_seq = 0;
};

/// Decides snapshot or delta for each update. Not thread safe.
class MapPublishSchedule {
 public:
  /// Throws std::invalid_argument for a period that is not finite and > 0.
  explicit MapPublishSchedule(const MapPublishScheduleOptions& options = {});

  /// The update published at now_s (a monotonic clock, s; not finite throws
  /// std::invalid_argument): a snapshot on the first call, after RequestSnapshot(), once
  /// now_s is snapshot_period_s or more past the last snapshot, or when now_s lies before it
  /// (the clock jumped back); a delta otherwise.
  MapPublishStep Next(double now_s);

  /// Makes the next update a snapshot (e.g. after the grid was reset or moved).
  void RequestSnapshot() { snapshot_requested_ = true; }

 private:
  bool SnapshotDue(double now_s) const;

  MapPublishScheduleOptions options_;
  std::int64_t next_seq_;
  bool snapshot_requested_ = true;
  double last_snapshot_s_ = 0.0;
};

}  // namespace topay::msgs
