#include "procs/planner/planner_world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/common/stopwatch.h"
#include "core/planning/planner_fields.h"

namespace topay::planner {
namespace {

// The class of a voxel state as the fields see it under `unknown`: free, blocked, or (only
// under kOccupiedInBaseBands, where unknown differs from both) unknown.
int FieldClass(VoxelState s, UnknownVoxelPolicy unknown) {
  if (s != VoxelState::kUnknown) return s == VoxelState::kOccupied ? 1 : 0;
  switch (unknown) {
    case UnknownVoxelPolicy::kFree: return 0;
    case UnknownVoxelPolicy::kOccupied: return 1;
    case UnknownVoxelPolicy::kOccupiedInBaseBands: return 2;
  }
  return 2;
}

bool InGrid(const GridGeometry3& g, const VoxelChange& c) {
  return (c.voxel.array() >= 0).all() && (c.voxel.array() < g.dims.array()).all() &&
         static_cast<std::uint8_t>(c.state) <= static_cast<std::uint8_t>(VoxelState::kUnknown);
}

std::string Describe(const VoxelChange& c) {
  return "voxel (" + std::to_string(c.voxel.x()) + ", " + std::to_string(c.voxel.y()) + ", " +
         std::to_string(c.voxel.z()) + ") state " + std::to_string(static_cast<int>(c.state));
}

}  // namespace

Eigen::AlignedBox3d GridBounds(const GridGeometry3& geometry) {
  return {geometry.origin_W_m,
          geometry.origin_W_m + geometry.resolution_m * geometry.dims.cast<double>()};
}

PlannerWorld::PlannerWorld(const Kinematics& kinematics, UnknownVoxelPolicy unknown, double slice_m)
    : kinematics_(kinematics), unknown_(unknown), slice_m_(slice_m) {
  if (!(std::isfinite(slice_m) && slice_m > 0.0)) {
    throw std::invalid_argument("planner map: slice_m must be finite and > 0");
  }
}

void PlannerWorld::Queue(MapWork work, Clock::time_point now) {
  ++works_;
  queued_seq_ = work.map_seq;
  if (work.reset) {
    reset_ = std::move(work);
    pending_.clear();
    slice_since_.clear();
    invalid_.clear();
    return;
  }
  if (reset_) {  // on top of a grid not built yet: change its states
    const GridGeometry3& g = reset_->geometry;
    for (const VoxelChange& c : work.changes) {
      if (!InGrid(g, c)) {
        invalid_.push_back(c);
      } else {
        reset_->states[g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z())] = static_cast<std::uint8_t>(c.state);
      }
    }
    reset_->map_seq = work.map_seq;
    return;
  }
  if (fields_ == nullptr) return;  // no grid yet: a delta without its snapshot changes nothing
  for (const VoxelChange& c : work.changes) QueueChange(c, now);
}

void PlannerWorld::QueueChange(const VoxelChange& c, Clock::time_point now) {
  const GridGeometry3& g = fields_->geometry();
  if (!InGrid(g, c)) {
    invalid_.push_back(c);
    return;
  }
  const std::int64_t index = g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z());
  if (FieldClass(fields_->state(c.voxel.x(), c.voxel.y(), c.voxel.z()), unknown_) == FieldClass(c.state, unknown_)) {
    pending_.erase(index);  // back to what the fields have (or nothing they can see)
    return;
  }
  const std::int64_t slice = SliceOf(c.voxel);
  pending_[index] = Pending{c, slice};
  slice_since_.try_emplace(slice, now);
}

std::int64_t PlannerWorld::SliceOf(const Eigen::Vector3i& voxel) const {
  const GridGeometry3& g = fields_->geometry();
  const int per_slice = std::max(1, static_cast<int>(std::lround(slice_m_ / g.resolution_m)));
  const std::int64_t columns = (g.dims.x() + per_slice - 1) / per_slice;
  return std::int64_t{voxel.y() / per_slice} * columns + voxel.x() / per_slice;
}

std::optional<PlannerWorld::Clock::time_point> PlannerWorld::OldestPending() const {
  if (reset_ || !invalid_.empty()) return Clock::time_point::min();
  std::optional<Clock::time_point> oldest;
  for (const auto& [slice, since] : slice_since_) {
    if (!oldest || since < *oldest) oldest = since;
  }
  return oldest;
}

void PlannerWorld::Reset(const MapWork& work) {
  const GridGeometry3& g = work.geometry;
  // Bounds half a voxel short of the grid's far corner, so that FromBounds's ceil gives the
  // grid's own voxel count whatever the rounding of origin + dims x resolution.
  const Eigen::AlignedBox3d bounds(
      g.origin_W_m, g.origin_W_m + g.resolution_m * (g.dims.cast<double>().array() - 0.5).matrix());
  VoxelMapFieldsOptions options = VoxelMapFieldsOptionsFrom(PlannerFieldOptions(kinematics_), bounds);
  options.resolution_m = g.resolution_m;
  options.unknown = unknown_;
  options.initial_state = VoxelState::kUnknown;
  auto fields = std::make_unique<VoxelMapFields>(options);
  if (!SameGeometry(fields->geometry(), g)) {
    throw std::invalid_argument("planner map: the fields' grid does not match the map's");
  }
  fields->ResetStates(work.states);
  fields_ = std::move(fields);
}

MapFlushSummary PlannerWorld::Flush() {
  const Stopwatch watch;
  MapFlushSummary summary;
  summary.works = works_;
  works_ = 0;
  if (!invalid_.empty()) {
    const std::string what = Describe(invalid_.front());
    const std::size_t n = invalid_.size();
    invalid_.clear();
    pending_.clear();
    slice_since_.clear();
    reset_.reset();
    throw std::invalid_argument("planner map: " + std::to_string(n) + " change(s) outside the grid or with a bad "
                                "state, the first " + what);
  }
  if (reset_) {
    const MapWork work = std::move(*reset_);
    reset_.reset();
    Reset(work);
    applied_seq_ = work.map_seq;
    summary.reset = true;
  }
  std::vector<VoxelChange> all;
  all.reserve(pending_.size());
  for (const auto& [index, p] : pending_) all.push_back(p.change);
  const MapFlushSummary applied = Apply(std::move(all), /*allow_rebuild=*/true);
  summary.field_changes = applied.field_changes;
  summary.rebuilt = applied.rebuilt;
  summary.update = applied.update;
  summary.ms = watch.ElapsedMs();
  return summary;
}

MapFlushSummary PlannerWorld::FlushWithin(std::span<const Eigen::AlignedBox2d> regions_xy_W_m) {
  if (reset_ || !invalid_.empty() || fields_ == nullptr) return Flush();
  const Stopwatch watch;
  const GridGeometry3& g = fields_->geometry();
  std::vector<VoxelChange> inside;
  for (const auto& [index, p] : pending_) {
    const Eigen::Vector2d c = (g.origin_W_m + g.resolution_m * (p.change.voxel.cast<double>().array() + 0.5).matrix()).head<2>();
    if (std::any_of(regions_xy_W_m.begin(), regions_xy_W_m.end(), [&](const Eigen::AlignedBox2d& r) { return r.contains(c); })) {
      inside.push_back(p.change);
    }
  }
  MapFlushSummary summary = Apply(std::move(inside), /*allow_rebuild=*/false);
  summary.works = works_;
  works_ = 0;
  summary.ms = watch.ElapsedMs();
  return summary;
}

MapFlushSummary PlannerWorld::FlushOldestSlice() {
  if (reset_ || !invalid_.empty() || fields_ == nullptr) return Flush();
  const Stopwatch watch;
  std::optional<std::int64_t> oldest;
  Clock::time_point since = Clock::time_point::max();
  for (const auto& [slice, t] : slice_since_) {
    if (t < since) since = t, oldest = slice;
  }
  std::vector<VoxelChange> in_slice;
  if (oldest) {
    for (const auto& [index, p] : pending_) {
      if (p.slice == *oldest) in_slice.push_back(p.change);
    }
    slice_since_.erase(*oldest);
  }
  MapFlushSummary summary = Apply(std::move(in_slice), /*allow_rebuild=*/false);
  summary.works = works_;
  works_ = 0;
  summary.ms = watch.ElapsedMs();
  return summary;
}

MapFlushSummary PlannerWorld::Apply(std::vector<VoxelChange> changes, bool allow_rebuild) {
  MapFlushSummary summary;
  if (fields_ == nullptr) return summary;
  const GridGeometry3& g = fields_->geometry();
  for (const VoxelChange& c : changes) pending_.erase(g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z()));
  ForgetEmptySlices();
  summary.field_changes = static_cast<std::int64_t>(changes.size());
  summary.left_pending = static_cast<std::int64_t>(pending_.size());
  if (pending_.empty()) applied_seq_ = queued_seq_;
  if (changes.empty()) return summary;
  if (!allow_rebuild || summary.field_changes <= kRebuildAboveChanges) {
    summary.update = fields_->ApplyChanges(changes);
    return summary;
  }
  // Many changes (a first scan, a long batch): their windows cover much of the map, and
  // recomputing window after window costs far more than one full rebuild (docs/benchmarks.md).
  summary.rebuilt = true;
  std::vector<std::uint8_t> states(fields_->states().begin(), fields_->states().end());
  for (const VoxelChange& c : changes) states[g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z())] = static_cast<std::uint8_t>(c.state);
  fields_->ResetStates(states);
  return summary;
}

void PlannerWorld::ForgetEmptySlices() {
  if (pending_.empty()) {
    slice_since_.clear();
    return;
  }
  std::unordered_map<std::int64_t, bool> used;
  for (const auto& [index, p] : pending_) used[p.slice] = true;
  std::erase_if(slice_since_, [&](const auto& entry) { return !used.contains(entry.first); });
}

}  // namespace topay::planner
