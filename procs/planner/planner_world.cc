#include "procs/planner/planner_world.h"

#include <stdexcept>

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
  std::vector<VoxelChange> known;
  for (int iz = 0; iz < g.dims.z(); ++iz) {
    for (int iy = 0; iy < g.dims.y(); ++iy) {
      for (int ix = 0; ix < g.dims.x(); ++ix) {
        const auto s = static_cast<VoxelState>(work.states[g.Index(ix, iy, iz)]);
        if (s != VoxelState::kUnknown) known.push_back({{ix, iy, iz}, s});
      }
    }
  }
  fields->ApplyChanges(known);
  fields_ = std::move(fields);
}

MapFlushSummary PlannerWorld::Flush() {
  const Stopwatch watch;
  MapFlushSummary summary;
  std::vector<MapWork> queue;
  queue.swap(queue_);
  for (const MapWork& work : queue) {
    if (work.reset) {
      Reset(work);
      summary.reset = true;
    } else if (fields_ != nullptr) {
      fields_->ApplyChanges(work.changes);
      summary.changes += static_cast<std::int64_t>(work.changes.size());
    }  // changes before any grid: nothing to apply them to (the intake sends a reset first)
    map_seq_ = work.map_seq;
    map_utime_ = work.map_utime;
    ++summary.works;
  }
  if (summary.works > 0) scene_stale_ = true;
  summary.ms = watch.ElapsedMs();
  return summary;
}

const Scene& PlannerWorld::scene() {
  if (scene_stale_ && fields_ != nullptr) {
    scene_.boxes = BlockedVoxelBoxes(fields_->geometry(), fields_->states(), unknown_);
    scene_.bounds_W_m = GridBounds(fields_->geometry());
    scene_.kind = "map";
    scene_stale_ = false;
  }
  return scene_;
}

}  // namespace topay::planner
