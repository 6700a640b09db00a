#pragma once
// The planner's distance fields built from the live map (VoxelMapFields), updated in batches
// of map work. Owned by one thread (PlanWorker's field thread).

#include <cstdint>
#include <memory>
#include <vector>

#include "core/geometry/scene.h"
#include "core/map/voxel_map_fields.h"
#include "core/robot/kinematics.h"
#include "procs/planner/map_intake.h"

namespace topay::planner {

/// What one Flush did.
struct MapFlushSummary {
  int works = 0;          ///< MapWork items applied (resets and change lists)
  bool reset = false;     ///< a new grid was built
  std::int64_t changes = 0;  ///< voxel changes applied
  std::int64_t field_changes = 0;  ///< ... of them, changes the fields can see (their class changed)
  bool rebuilt = false;   ///< the fields were rebuilt whole (more than kRebuildAboveChanges)
  VoxelMapUpdateSummary update;  ///< the incremental update (when not rebuilt)
  double ms = 0.0;        ///< wall time of the whole flush
};

class PlannerWorld {
 public:
  /// `kinematics` outlives this object (it sizes the fields: PlannerFieldOptions).
  PlannerWorld(const Kinematics& kinematics, UnknownVoxelPolicy unknown);

  /// Queues map work for the next Flush.
  void Queue(MapWork work);
  bool pending() const { return !queue_.empty(); }

  /// More voxel changes the fields can see (their class under the unknown policy changes)
  /// than this in one flush rebuild the fields whole (about 0.4 s for a
  /// 20 x 20 m map, docs/benchmarks.md) instead of window by window: the first scan of a
  /// room changes ~200 k voxels, whose windows cover most of the map, and took 10 s
  /// incrementally; a second of driving changes thousands, spread over the view.
  static constexpr std::int64_t kRebuildAboveChanges = 5'000;

  /// Applies the queued work to the fields in order (work before the last reset is skipped:
  /// the reset replaces it). A reset builds new fields over the map's grid (the planner's field
  /// options at the map's resolution). Throws std::invalid_argument
  /// for work that does not fit the grid (the queue is dropped; the fields keep what was applied).
  MapFlushSummary Flush();

  bool has_map() const { return fields_ != nullptr; }
  /// The fields (has_map() only).
  const VoxelMapFields& fields() const { return *fields_; }
  std::int64_t map_seq() const { return map_seq_; }
  std::int64_t map_utime() const { return map_utime_; }

 private:
  void Reset(const MapWork& work);
  void ApplyChanges(const std::vector<MapWork>& queue, std::size_t first, std::int64_t num_changes,
                    MapFlushSummary* summary);

  const Kinematics& kinematics_;
  UnknownVoxelPolicy unknown_;
  std::vector<MapWork> queue_;
  std::unique_ptr<VoxelMapFields> fields_;
  std::int64_t map_seq_ = 0;
  std::int64_t map_utime_ = 0;
};

/// The volume a grid covers (origin to origin + dims x resolution).
Eigen::AlignedBox3d GridBounds(const GridGeometry3& geometry);

}  // namespace topay::planner
