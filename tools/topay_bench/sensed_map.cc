#include "tools/topay_bench/sensed_map.h"

#include <chrono>

#include "core/map/voxel_boxes.h"
#include "procs/mapper/scan_mapper.h"
#include "sim/lidar/lidar_scanner.h"

namespace topay::bench {
namespace {

using Clock = std::chrono::steady_clock;

double MsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

SensedMap BuildSensedMap(const Scene& exact, const PlanningTask& task, const Kinematics& kinematics,
                         const SensedMapSettings& settings,
                         const SceneDistanceFieldsOptions& field_options, std::uint64_t seed) {
  if (settings.unknown == UnknownVoxelPolicy::kOccupiedInBaseBands) {
    throw std::invalid_argument("sensed maps: the unknown policy must be free or occupied");
  }
  OccupancyMapOptions map_options = settings.map;
  map_options.bounds_W_m = exact.bounds_W_m;
  mapper::ScanMapper mapper(settings.filter, map_options, kinematics);
  sim::LidarScanner lidar(settings.lidar, kinematics, seed);
  lidar.SetWorld(exact.boxes);

  SensedMap out;
  SensedMapFigures& f = out.figures;
  std::vector<VoxelChange> changes;
  msgs::CheckedCloud cloud;
  const double period_s = 1.0 / settings.lidar.scan_rate_hz;
  for (const WholeBodyState& state : SensingTourStates(exact, task, settings.tour)) {
    const auto scan_start = Clock::now();
    const sim::LidarScan scan = lidar.Scan(state, f.scans * period_s);
    f.lidar_ms += MsSince(scan_start);
    cloud.utime = static_cast<std::int64_t>(scan.t_s * 1e6);
    cloud.X_WS = scan.X_WS;
    cloud.p_SP = scan.p_SP;
    const auto map_start = Clock::now();
    const mapper::ScanMapperSummary summary = mapper.Integrate(cloud, state, &changes);
    f.mapping_ms += MsSince(map_start);
    f.points += summary.filter.num_input;
    f.points_mapped += summary.filter.num_output;
    f.self_points += scan.self_hits;
    ++f.scans;
  }
  f.voxels = mapper.map().CountStates();

  const auto fields_start = Clock::now();
  VoxelMapFieldsOptions fields_options = VoxelMapFieldsOptionsFrom(field_options, exact.bounds_W_m);
  fields_options.resolution_m = map_options.resolution_m;
  fields_options.unknown = settings.unknown;
  out.fields = std::make_unique<VoxelMapFields>(fields_options);
  out.fields->ApplyChanges(changes);
  f.fields_ms = MsSince(fields_start);

  const auto boxes_start = Clock::now();
  out.scene.boxes = BlockedVoxelBoxes(mapper.map().geometry(), mapper.map().states(), settings.unknown);
  out.scene.bounds_W_m = exact.bounds_W_m;
  out.scene.kind = "sensed " + exact.kind;
  out.scene.seed = exact.seed;
  f.voxel_boxes = static_cast<int>(out.scene.boxes.size());
  f.boxes_ms = MsSince(boxes_start);
  return out;
}

}  // namespace topay::bench
