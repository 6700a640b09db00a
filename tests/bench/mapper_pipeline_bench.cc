// The mapper's whole per-scan pipeline, stage by stage (issue 17's figures): the simulated LiDAR
// (sim/lidar, config/sim/lidar.yaml: 20,000 rays per scan, 2 cm noise) on a robot driving at
// 1 m/s (0.1 m per 10 Hz scan) across a seeded Tables room, arm stowed; each scan through
// topay-mapper's own code: the cloud check, the PCL scan filter (each stage), the dense map's
// insertion, the MAP_UPDATE delta's encoding (zlib) — together "scan in -> MAP_UPDATE out" —
// and beside it the planner's incremental field update from the changes
// (VoxelMapFields::ApplyChanges, planner side), the OctoMap insertion of the same filtered cloud
// (every 10th scan: the mirror's rate) and a full snapshot's encoding.
// Two worlds: the room as generated (no ceiling: ~half the rays return) and with a ceiling
// slab at 2.5 m (every ray that is not blocked returns: the full 20,000-point load).
// One thread, wall clock (steady) per stage; median, p95 and mean over the scans.
// Run (Release build, benchmarks on):
//   build/bin/mapper_pipeline_bench [scans=150] [seed=1] [clearing_m=the config's]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/common/sample_statistics.h"
#include "core/io/robot_loader.h"
#include "core/map/voxel_map_fields.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "procs/msgs/cloud_input.h"
#include "procs/mapper/mapper_options.h"
#include "procs/mapper/octomap_mirror.h"
#include "procs/mapper/scan_mapper.h"
#include "procs/msgs/map_codec.h"
#include "sim/lidar/lidar_options.h"
#include "sim/lidar/lidar_scanner.h"
#include "sim/scenes/benchmark_scene.h"

namespace topay {
namespace {

using Clock = std::chrono::steady_clock;
double MsSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct Series {
  std::vector<double> range, ground, self, voxel, filter, insert, encode, total, fields, octomap, snapshot;
  std::vector<double> fields_3d, fields_2d, changes_3d;
  std::vector<double> points_in, points_out, changes, delta_bytes, snapshot_bytes;
};

void Print(const char* what, const std::vector<double>& v, const char* unit) {
  std::printf("| %-34s | %8.2f | %8.2f | %8.2f | %s |\n", what, Median(v), NearestRankQuantile(v, 0.95), Mean(v), unit);
}

point_cloud_t ToMessage(const sim::LidarScan& scan, std::int64_t utime) {
  point_cloud_t m{};
  m.utime = utime;
  m.sensor_frame = "lidar";
  const Eigen::Quaterniond q(scan.X_WS.rotation());
  const double quat[4] = {q.w(), q.x(), q.y(), q.z()};
  for (int a = 0; a < 3; ++a) m.p_WS[a] = scan.X_WS.translation()(a);
  for (int a = 0; a < 4; ++a) m.quat_WS[a] = quat[a];
  m.num_coords = 3 * static_cast<int>(scan.p_SP.size());
  m.p_SP.reserve(m.num_coords);
  for (const Eigen::Vector3f& p : scan.p_SP) m.p_SP.insert(m.p_SP.end(), {p.x(), p.y(), p.z()});
  return m;
}

void Run(bool with_ceiling, int num_scans, std::uint64_t seed, double clearing_m) {
  const std::string config = std::string(TOPAY_SOURCE_DIR) + "/config/";
  const RobotModel model = LoadRobotModel(config + "robot/topay_mm.urdf", config + "robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  mapper::MapperOptions options = mapper::LoadMapperOptions(config + "mapper/mapper.yaml");
  if (clearing_m > 0.0) options.map.max_free_ray_length_m = clearing_m;
  const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, seed).scene;
  std::vector<OrientedBox> world = scene.boxes;
  if (with_ceiling) {
    OrientedBox ceiling;
    ceiling.center_W_m = Eigen::Vector3d(0.0, 0.0, 2.55);
    ceiling.size_m = Eigen::Vector3d(30.0, 30.0, 0.1);
    world.push_back(ceiling);
  }
  sim::LidarScanner lidar(sim::LoadLidarOptionsFile(config + "sim/lidar.yaml"), kinematics, seed);
  lidar.SetWorld(world);
  mapper::ScanMapper mapper(options.filter, options.map, kinematics);
  mapper::OctomapMirror octomap(mapper::MirrorOptionsOf(options));
  VoxelMapFields fields(VoxelMapFieldsOptionsFrom(PlannerFieldOptions(kinematics), options.map.bounds_W_m));
  msgs::CheckedCloud cloud;
  std::vector<VoxelChange> changes;
  Series s;
  WholeBodyState state;
  state.q_rad = model.stow_q_rad.size() == model.num_joints() ? model.stow_q_rad
                                                              : Eigen::VectorXd::Zero(model.num_joints());
  for (int k = 0; k < num_scans; ++k) {
    // A drive along y = 0.5 from x = -8 at 1 m/s (the scene keeps its start area clear).
    state.x_m = -8.0 + 0.1 * k;
    state.y_m = 0.5;
    const sim::LidarScan scan = lidar.Scan(state, 0.1 * k);
    const point_cloud_t msg = ToMessage(scan, 1'000'000 + 100'000 * k);
    const auto start = Clock::now();
    if (msgs::CheckCloud(msg, options.filter.input, &cloud)) std::abort();
    changes.clear();
    const mapper::ScanMapperSummary summary = mapper.Integrate(cloud, state, &changes);
    const auto encode_start = Clock::now();
    const map_update_t delta = msgs::EncodeMapDelta(mapper.map().geometry(), changes, msg.utime, k + 2, options.publish.codec);
    s.encode.push_back(MsSince(encode_start));
    s.total.push_back(MsSince(start));
    s.range.push_back(summary.filter.range_ms);
    s.ground.push_back(summary.filter.ground_ms);
    s.self.push_back(summary.filter.self_ms);
    s.voxel.push_back(summary.filter.voxel_ms);
    s.filter.push_back(summary.filter.total_ms);
    s.insert.push_back(summary.insert.total_s * 1e3);
    s.points_in.push_back(summary.filter.num_input);
    s.points_out.push_back(summary.filter.num_output);
    s.changes.push_back(static_cast<double>(changes.size()));
    s.delta_bytes.push_back(delta.getEncodedSize());
    const auto fields_start = Clock::now();
    const VoxelMapUpdateSummary field_update = fields.ApplyChanges(changes);
    s.fields.push_back(MsSince(fields_start));
    s.fields_3d.push_back(field_update.field_3d_s * 1e3);
    s.fields_2d.push_back(field_update.field_2d_s * 1e3);
    s.changes_3d.push_back(field_update.num_voxels_changed_3d);
    if (k % 10 == 0) {
      s.octomap.push_back(octomap.Insert(cloud.X_WS.translation(), mapper.last_points()).ms);
      const auto snapshot_start = Clock::now();
      const map_update_t full = msgs::EncodeFullMap(mapper.map().geometry(), mapper.map().states(), msg.utime, 1, options.publish.codec);
      s.snapshot.push_back(MsSince(snapshot_start));
      s.snapshot_bytes.push_back(full.getEncodedSize());
    }
  }
  std::printf("\n### Tables seed %llu, %s, %d scans (0.1 m apart), clearing up to %.1f m\n\n",
              static_cast<unsigned long long>(seed), with_ceiling ? "with a ceiling at 2.5 m" : "as generated (no ceiling)",
              num_scans, options.map.max_free_ray_length_m);
  std::printf("| stage | median | p95 | mean | unit |\n|---|---:|---:|---:|---|\n");
  Print("points in the scan", s.points_in, "points");
  Print("points after the filter", s.points_out, "points");
  Print("filter: range + to W", s.range, "ms");
  Print("filter: ground", s.ground, "ms");
  Print("filter: self (robot body)", s.self, "ms");
  Print("filter: voxel grid (PCL)", s.voxel, "ms");
  Print("filter: total", s.filter, "ms");
  Print("map insertion (ray casting)", s.insert, "ms");
  Print("delta encoding (zlib)", s.encode, "ms");
  Print("**scan in -> MAP_UPDATE out**", s.total, "ms");
  Print("voxel changes per scan", s.changes, "voxels");
  Print("delta bytes (LCM message)", s.delta_bytes, "B");
  Print("planner fields update (beside)", s.fields, "ms");
  Print("  of which the 3D field", s.fields_3d, "ms");
  Print("  of which the 2D base field", s.fields_2d, "ms");
  Print("  occupancy flips (3D)", s.changes_3d, "voxels");
  Print("OctoMap insertion (beside, 1 in 10)", s.octomap, "ms");
  Print("full snapshot encoding (1 in 10)", s.snapshot, "ms");
  Print("full snapshot bytes (1 in 10)", s.snapshot_bytes, "B");
}

}  // namespace
}  // namespace topay

int main(int argc, char** argv) {
  const int scans = argc > 1 ? std::atoi(argv[1]) : 150;
  const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const double clearing_m = argc > 3 ? std::atof(argv[3]) : 0.0;  // 0: the config's
  topay::Run(false, scans, seed, clearing_m);
  topay::Run(true, scans, seed, clearing_m);
  return 0;
}
