#pragma once
// The planner's distance fields built from the live map (VoxelMapFields), kept up to date from
// the map work the LCM thread hands over. Owned by one thread (PlanWorker's worker).
//
// Queued work is folded at once into the pending changes, one per voxel (its newest state),
// keeping only those the fields can see (a voxel whose class under the unknown policy differs
// from the fields'). The pending changes are applied to the fields in three ways:
//  - FlushWithin(regions): the changes in some xy regions only (a plan's start and the
//    collisions it must avoid), incrementally: fresh fields where a plan needs them, in tens of
//    milliseconds, while the rest of the map waits;
//  - FlushOldestSlice(): the changes of one square slice of the map (the one holding the
//    oldest pending change), incrementally: background work in short steps, so that a plan
//    never waits long for it;
//  - Flush(): everything (a new grid is always built whole).
// After any of them the fields are the exact fields of their own voxel states (states()):
// part of the newest map, so a plan validated on states() is consistent with its fields.

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "core/geometry/scene.h"
#include "core/map/voxel_map_fields.h"
#include "core/robot/kinematics.h"
#include "procs/planner/map_intake.h"

namespace topay::planner {

/// What one flush did.
struct MapFlushSummary {
  int works = 0;          ///< MapWork items folded in since the last flush
  bool reset = false;     ///< a new grid was built
  std::int64_t field_changes = 0;  ///< changes the fields can see that were applied
  std::int64_t left_pending = 0;   ///< ... that are still pending after it
  bool rebuilt = false;   ///< the fields were rebuilt whole (more than kRebuildAboveChanges)
  VoxelMapUpdateSummary update;  ///< the incremental update (when not rebuilt)
  double ms = 0.0;        ///< wall time of the whole flush
};

class PlannerWorld {
 public:
  using Clock = std::chrono::steady_clock;

  /// `kinematics` outlives this object (it sizes the fields: PlannerFieldOptions). Background
  /// slices are `slice_m` wide (xy squares of the map).
  PlannerWorld(const Kinematics& kinematics, UnknownVoxelPolicy unknown, double slice_m = 5.0);

  /// Folds `work` into the pending changes (a reset replaces everything pending). Changes
  /// outside the grid or with a bad state are kept to be reported by the next flush.
  void Queue(MapWork work, Clock::time_point now = Clock::now());
  /// Work is pending (a new grid, changes, or bad changes to report).
  bool pending() const { return reset_.has_value() || !pending_.empty() || !invalid_.empty(); }
  std::int64_t pending_changes() const { return static_cast<std::int64_t>(pending_.size()); }
  /// When the oldest pending slice got its first change (nullopt: nothing pending).
  std::optional<Clock::time_point> OldestPending() const;

  /// More pending changes than this in one Flush rebuild the fields whole (about 0.4 s for
  /// a 20 x 20 m map, docs/benchmarks.md) instead of window by window.
  static constexpr std::int64_t kRebuildAboveChanges = 5'000;

  /// Applies everything pending. Throws std::invalid_argument for work that does not fit the
  /// grid (naming it; everything pending is dropped, the fields keep what they had).
  MapFlushSummary Flush();
  /// Applies the pending changes whose voxel centres lie in one of `regions_xy_W_m` (a new grid
  /// or bad changes: everything, as Flush).
  MapFlushSummary FlushWithin(std::span<const Eigen::AlignedBox2d> regions_xy_W_m);
  /// Applies the pending changes of the slice that holds the oldest one.
  MapFlushSummary FlushOldestSlice();

  bool has_map() const { return fields_ != nullptr; }
  /// The fields (has_map() only) and the voxel states they are exact for.
  const VoxelMapFields& fields() const { return *fields_; }
  std::span<const std::uint8_t> states() const { return fields_->states(); }
  /// The newest map update whose changes are all in the fields.
  std::int64_t map_seq() const { return pending_.empty() && !reset_ ? queued_seq_ : applied_seq_; }
  std::int64_t queued_seq() const { return queued_seq_; }

 private:
  struct Pending {
    VoxelChange change;
    std::int64_t slice = 0;
  };
  void Reset(const MapWork& work);
  void QueueChange(const VoxelChange& c, Clock::time_point now);
  std::int64_t SliceOf(const Eigen::Vector3i& voxel) const;
  // Applies `changes` (all valid, in the grid) and drops them from the pending ones; many
  // changes spread over the map rebuild the fields whole if `allow_rebuild` (a region's or a
  // slice's windows stay within it: always incremental).
  MapFlushSummary Apply(std::vector<VoxelChange> changes, bool allow_rebuild);
  void ForgetEmptySlices();

  const Kinematics& kinematics_;
  UnknownVoxelPolicy unknown_;
  double slice_m_;
  std::unique_ptr<VoxelMapFields> fields_;
  std::optional<MapWork> reset_;                        // a new grid to build
  std::unordered_map<std::int64_t, Pending> pending_;    // by voxel index
  std::unordered_map<std::int64_t, Clock::time_point> slice_since_;  // first pending change
  std::vector<VoxelChange> invalid_;
  int works_ = 0;
  std::int64_t queued_seq_ = 0;   // the newest map update queued
  std::int64_t applied_seq_ = 0;  // the newest map update fully applied
};

/// The volume a grid covers (origin to origin + dims x resolution).
Eigen::AlignedBox3d GridBounds(const GridGeometry3& geometry);

}  // namespace topay::planner
