#pragma once
// topay-bench's sensed maps (--sensed-map): a task's scene is mapped by the simulated LiDAR
// from a tour of poses (sensing_tour.h) through the mapper's own pipeline (PCL scan filter,
// dense occupancy map: procs/mapper/scan_mapper.h), and the planner's fields are built from
// the map's voxels (VoxelMapFields). The planner then plans on those fields and validates
// against the map's occupied voxels as boxes (its own check, as on the robot); the benchmark
// validates the result again against the exact scene.

#include <cstdint>
#include <memory>

#include "core/geometry/scene.h"
#include "core/map/occupancy_map.h"
#include "core/map/scene_distance_fields.h"
#include "core/map/voxel_map_fields.h"
#include "core/robot/kinematics.h"
#include "procs/mapper/scan_filter_options.h"
#include "sim/lidar/lidar_options.h"
#include "sim/scenes/planning_task.h"
#include "tools/topay_bench/sensed_map_figures.h"
#include "tools/topay_bench/sensing_tour.h"

namespace topay::bench {

/// How a task's scene is sensed and mapped.
struct SensedMapSettings {
  SensingTourOptions tour;
  sim::LidarOptions lidar;           ///< config/sim/lidar.yaml's (the simulator's sensor)
  mapper::ScanFilterOptions filter;  ///< config/mapper/mapper.yaml's
  OccupancyMapOptions map;           ///< config/mapper/mapper.yaml's (bounds: the scene's)
  /// How never-seen voxels count, for the fields and the planner's voxel boxes alike:
  /// kFree (default; the planner plans through unseen space, as the graph's planner replanning
  /// on every scan does) or kOccupied.
  UnknownVoxelPolicy unknown = UnknownVoxelPolicy::kFree;
  /// Added to the planner's own validator obstacle margin (m) on a sensed map, for the map's
  /// uncertainty. 0 by default: measured at 0, 2 and 5 cm on Tables medium, 2 cm changed
  /// nothing (the exact-scene rejections come from box parts never seen, not from voxel
  /// quantisation) and 5 cm made the planner's own validator reject nearly every plan (the
  /// fields do not carry the margin) (docs/benchmarks.md). The exact scene's check keeps the
  /// benchmark's own margin.
  double map_margin_m = 0.0;
};

struct SensedMap {
  std::unique_ptr<VoxelMapFields> fields;
  Scene scene;  ///< The blocked voxels as boxes, with the exact scene's bounds.
  SensedMapFigures figures;
};

/// Scans `exact` from the tour of `task` (LiDAR seeded with `seed`), maps the scans and builds
/// the fields (`field_options`: the planner's, e.g. PlannerFieldOptions) and the voxel boxes.
/// Throws ConfigError / std::invalid_argument for inconsistent settings.
SensedMap BuildSensedMap(const Scene& exact, const PlanningTask& task, const Kinematics& kinematics,
                         const SensedMapSettings& settings,
                         const SceneDistanceFieldsOptions& field_options, std::uint64_t seed);

}  // namespace topay::bench
