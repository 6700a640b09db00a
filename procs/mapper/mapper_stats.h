#pragma once
// The mapper's per-scan figures (filter stages, insertion, encoding, scan in to MAP_UPDATE out)
// and per-message bytes, for the heartbeat's status line and the report printed at exit.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/map/occupancy_map.h"
#include "procs/mapper/scan_mapper.h"

namespace topay::mapper {

/// Appends `value` to a per-scan sample, keeping at most the newest 2 x kMaxSamples values:
/// the mapper runs for days, and its figures are over the last hour or two, not all time
/// (36,000 samples = 1 h of scans at 10 Hz; the oldest half is dropped at once, amortised
/// O(1)).
inline constexpr std::size_t kMaxSamples = 36'000;
void AddSample(std::vector<double>* sample, double value);

struct MapperStats {
  std::int64_t clouds = 0;           ///< POINT_CLOUD messages received (decoded).
  std::int64_t clouds_rejected = 0;  ///< ... rejected by CheckCloud (malformed, NaN pose, huge).
  std::int64_t points_non_finite = 0;  ///< NaN/inf points dropped by the filter.
  std::int64_t scans_without_state = 0;  ///< Scans mapped without the self filter (no state).
  std::int64_t states_rejected = 0;  ///< ROBOT_STATE messages malformed or refused (continuity gate).
  std::int64_t updates = 0, snapshots = 0;  ///< MAP_UPDATEs published, of which full.
  std::int64_t journal_errors = 0;  ///< Updates the map journal could not write.
  std::string last_error;            ///< The last rejection's reason.
  // Per scan (AddSample: the last 1-2 hours), ms.
  std::vector<double> range_ms, ground_ms, self_ms, voxel_ms, outlier_ms, filter_ms;
  std::vector<double> insert_ms, encode_ms, scan_to_update_ms;
  std::vector<double> delta_bytes, snapshot_bytes, snapshot_encode_ms;
  std::vector<double> changes;  ///< Voxel changes per scan.

  void AddScan(const ScanMapperSummary& summary);
  /// One line for the heartbeat: counts of the map's states and the last scan's times.
  std::string StatusLine(const VoxelStateCounts& counts) const;
  /// The report printed at exit: median and p95 of every figure (over the samples kept),
  /// counts (all time).
  std::string Report() const;
};

}  // namespace topay::mapper
