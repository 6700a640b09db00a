#pragma once
// What the planning thread plans on: the planner's distance fields built from the live map
// (VoxelMapFields, updated in batches) and the map's blocked voxels as exact boxes (the
// planner's own validator checks against them: its Scene). Owned by one thread.

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
  double ms = 0.0;        ///< wall time of the whole flush
};

class PlannerWorld {
 public:
  /// `kinematics` outlives this object (it sizes the fields: PlannerFieldOptions).
  PlannerWorld(const Kinematics& kinematics, UnknownVoxelPolicy unknown);

  /// Queues map work for the next Flush.
  void Queue(MapWork work);
  bool pending() const { return !queue_.empty(); }

  /// Applies the queued work to the fields in order. A reset builds new fields over the map's
  /// grid (the planner's field options at the map's resolution). Throws std::invalid_argument
  /// for work that does not fit the grid (the queue is dropped; the fields keep what was applied).
  MapFlushSummary Flush();

  bool has_map() const { return fields_ != nullptr; }
  /// The fields (has_map() only).
  const VoxelMapFields& fields() const { return *fields_; }
  /// The blocked voxels as boxes over the map's volume, rebuilt after a Flush that changed
  /// anything (has_map() only).
  const Scene& scene();
  std::int64_t map_seq() const { return map_seq_; }
  std::int64_t map_utime() const { return map_utime_; }

 private:
  void Reset(const MapWork& work);

  const Kinematics& kinematics_;
  UnknownVoxelPolicy unknown_;
  std::vector<MapWork> queue_;
  std::unique_ptr<VoxelMapFields> fields_;
  Scene scene_;
  bool scene_stale_ = true;
  std::int64_t map_seq_ = 0;
  std::int64_t map_utime_ = 0;
};

/// The volume a grid covers (origin to origin + dims x resolution).
Eigen::AlignedBox3d GridBounds(const GridGeometry3& geometry);

}  // namespace topay::planner
