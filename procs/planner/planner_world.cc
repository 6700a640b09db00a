#include "procs/planner/planner_world.h"

#include <stdexcept>
#include <unordered_map>

#include "core/common/stopwatch.h"
#include "core/map/voxel_boxes.h"
#include "core/planning/planner_fields.h"

namespace topay::planner {

Eigen::AlignedBox3d GridBounds(const GridGeometry3& geometry) {
  return {geometry.origin_W_m,
          geometry.origin_W_m + geometry.resolution_m * geometry.dims.cast<double>()};
}

PlannerWorld::PlannerWorld(const Kinematics& kinematics, UnknownVoxelPolicy unknown)
    : kinematics_(kinematics), unknown_(unknown) {}

void PlannerWorld::Queue(MapWork work) { queue_.push_back(std::move(work)); }

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
  std::vector<MapWork> queue;
  queue.swap(queue_);
  // From the last reset on, everything is changes on top of it.
  std::size_t first = 0;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    if (queue[k].reset) first = k;
  }
  if (first < queue.size() && queue[first].reset) {
    Reset(queue[first]);
    summary.reset = true;
    ++first;
  }
  std::int64_t num_changes = 0;
  for (std::size_t k = first; k < queue.size(); ++k) num_changes += static_cast<std::int64_t>(queue[k].changes.size());
  if (fields_ != nullptr && num_changes > 0) ApplyChanges(queue, first, num_changes, &summary);
  summary.changes = num_changes;
  summary.works = static_cast<int>(queue.size());
  if (!queue.empty()) {
    map_seq_ = queue.back().map_seq;
    map_utime_ = queue.back().map_utime;
  }
  summary.ms = watch.ElapsedMs();
  return summary;
}

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

}  // namespace

void PlannerWorld::ApplyChanges(const std::vector<MapWork>& queue, std::size_t first,
                                std::int64_t num_changes, MapFlushSummary* summary) {
  // Only the changes the fields can see (most of a scan's changes are unknown -> free,
  // nothing to the fields under the default policy): each voxel's last state in the batch,
  // kept if its class differs from the fields' (bad changes are kept: ApplyChanges names them).
  const GridGeometry3& g = fields_->geometry();
  std::unordered_map<std::int64_t, VoxelChange> last;
  last.reserve(static_cast<std::size_t>(num_changes));
  std::vector<VoxelChange> seen;
  for (std::size_t k = first; k < queue.size(); ++k) {
    for (const VoxelChange& c : queue[k].changes) {
      const bool inside = (c.voxel.array() >= 0).all() && (c.voxel.array() < g.dims.array()).all();
      if (!inside || static_cast<std::uint8_t>(c.state) > static_cast<std::uint8_t>(VoxelState::kUnknown)) {
        seen.push_back(c);
      } else {
        last[g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z())] = c;
      }
    }
  }
  for (const auto& [index, c] : last) {
    if (FieldClass(fields_->state(c.voxel.x(), c.voxel.y(), c.voxel.z()), unknown_) != FieldClass(c.state, unknown_)) {
      seen.push_back(c);
    }
  }
  summary->field_changes = static_cast<std::int64_t>(seen.size());
  if (summary->field_changes <= kRebuildAboveChanges) {
    summary->update = fields_->ApplyChanges(seen);
    return;
  }
  summary->rebuilt = true;
  // Many changes (a first scan, a long batch): their windows cover much of the map, and
  // recomputing window after window costs far more than one full rebuild (docs/benchmarks.md).
  std::vector<std::uint8_t> states(fields_->states().begin(), fields_->states().end());
  for (const VoxelChange& c : seen) {
    const bool inside = (c.voxel.array() >= 0).all() && (c.voxel.array() < g.dims.array()).all();
    if (!inside) throw std::invalid_argument("planner map: a change outside the grid");
    states[g.Index(c.voxel.x(), c.voxel.y(), c.voxel.z())] = static_cast<std::uint8_t>(c.state);
  }
  fields_->ResetStates(states);
}

}  // namespace topay::planner
