// Benchmarks of the planner on scenes of many boxes (issue 13: "the planning time limit does
// not hold on large scenes"): N floor boxes (N = 1,000, 10,000, 100,000) in the 20 x 20 m room,
// (1) the planner's map build (BuildSceneDistanceFields at PlannerFieldOptions: 3D field at
// 0.05 m, exact 2D base field at 0.01 m in two bands), and (2) the whole plan from the scene
// (PlanInScene: exact start and target check, map build and plan, all under the 3 s limit).
// Run (Release build):
//   build/bin/scene_scaling_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// Scene files for topay-plan (floor_boxes_<N>.json in DIR), then exit:
//   build/bin/scene_scaling_bench --write-scenes DIR
// Commands and figures: docs/benchmarks.md ("Large scenes").

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <vector>
#include <iostream>
#include <string>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "core/geometry/scene.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planner/plan_in_scene.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "sim/scenes/scene_json.h"

namespace topay {
namespace {

// The start's and the target's base positions, in a corridor kept free of boxes
// (y in [-1.5, 2.0] m, the whole room's length), so that a plan can succeed and runs every
// stage: front end, optimization, validation against all the boxes.
const Eigen::Vector2d kStartBase(-3.0, 0.0);
const Eigen::Vector2d kGoalBase(3.0, 0.5);
constexpr double kCorridorLowY = -1.5;
constexpr double kCorridorHighY = 2.0;

OrientedBox Box(const Eigen::Vector3d& center, const Eigen::Vector3d& size, double yaw) {
  OrientedBox b;
  b.center_W_m = center;
  b.size_m = size;
  b.yaw_rad = yaw;
  return b;
}

// Four walls 1 m tall and `count` floor boxes: footprint U[0.03, 0.08]^2 m, height
// U[0.05, 0.3] m, random yaw, uniform over [-9.5, 9.5]^2 m outside the corridor.
Scene FloorBoxes(int count) {
  Scene scene;
  scene.kind = "floor boxes";
  scene.seed = static_cast<std::uint64_t>(count);
  scene.boxes.push_back(Box({0, -9.9, 0.5}, {20, 0.2, 1}, 0));
  scene.boxes.push_back(Box({0, 9.9, 0.5}, {20, 0.2, 1}, 0));
  scene.boxes.push_back(Box({-9.9, 0, 0.5}, {0.2, 20, 1}, 0));
  scene.boxes.push_back(Box({9.9, 0, 0.5}, {0.2, 20, 1}, 0));
  Rng rng(scene.seed);
  while (static_cast<int>(scene.boxes.size()) < count + 4) {
    const Eigen::Vector2d p(rng.Uniform(-9.5, 9.5), rng.Uniform(-9.5, 9.5));
    if (p.y() > kCorridorLowY && p.y() < kCorridorHighY) continue;
    const double height = rng.Uniform(0.05, 0.3);
    scene.boxes.push_back(Box({p.x(), p.y(), 0.5 * height},
                              {rng.Uniform(0.03, 0.08), rng.Uniform(0.03, 0.08), height},
                              rng.Uniform(-3.2, 3.2)));
  }
  return scene;
}

const Kinematics& TopayKinematics() {
  static const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                                 TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  static const Kinematics kinematics(model);
  return kinematics;
}

// The map build as it was before issue 13 ("before" in docs/benchmarks.md): the same 3D
// field, but each exact base field by the old loop, every box lowering every cell within
// cap_m of its footprint's bounds (cost: boxes x cells within the cap, not the boxes near
// each cell). Kept here, verbatim in its arithmetic, to measure the old cost on this machine.
void OldLowerToFootprint(const GridGeometry2& g, const OrientedBox& box, double cap_m,
                         std::vector<float>* values) {
  const double c = std::cos(box.yaw_rad), s = std::sin(box.yaw_rad);
  const double hx = 0.5 * box.size_m.x(), hy = 0.5 * box.size_m.y();
  const double ex = std::abs(c) * hx + std::abs(s) * hy + cap_m;
  const double ey = std::abs(s) * hx + std::abs(c) * hy + cap_m;
  const double cx = box.center_W_m.x(), cy = box.center_W_m.y();
  const double inv_res = 1.0 / g.resolution_m;
  const int ix0 = std::max(0, static_cast<int>(std::ceil((cx - ex - g.origin_W_m.x()) * inv_res - 0.5)));
  const int ix1 = std::min(g.dims.x() - 1,
                           static_cast<int>(std::floor((cx + ex - g.origin_W_m.x()) * inv_res - 0.5)));
  const int iy0 = std::max(0, static_cast<int>(std::ceil((cy - ey - g.origin_W_m.y()) * inv_res - 0.5)));
  const int iy1 = std::min(g.dims.y() - 1,
                           static_cast<int>(std::floor((cy + ey - g.origin_W_m.y()) * inv_res - 0.5)));
  float* data = values->data();
  for (int iy = iy0; iy <= iy1; ++iy) {
    const double dy = g.origin_W_m.y() + (iy + 0.5) * g.resolution_m - cy;
    float* row = data + g.Index(0, iy);
    for (int ix = ix0; ix <= ix1; ++ix) {
      const double dx = g.origin_W_m.x() + (ix + 0.5) * g.resolution_m - cx;
      const double qx = std::abs(c * dx + s * dy) - hx;
      const double qy = std::abs(-s * dx + c * dy) - hy;
      const double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
      const double distance = std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0);
      row[ix] = std::min(row[ix], static_cast<float>(distance));
    }
  }
}

SignedDistanceField2 OldFootprintField(const GridGeometry2& g, const Scene& scene,
                                       const HeightBand& band, double cap_m) {
  std::vector<float> values(g.NumCells(), static_cast<float>(cap_m));
  for (const OrientedBox& box : scene.boxes) {
    const double half = 0.5 * box.size_m.z();
    if (box.center_W_m.z() - half < band.z_max_m && box.center_W_m.z() + half > band.z_min_m) {
      OldLowerToFootprint(g, box, cap_m, &values);
    }
  }
  return SignedDistanceField2::FromCellValues(g, std::move(values), cap_m,
                                              g.resolution_m / std::sqrt(2.0));
}

void BM_MapBuildBefore(benchmark::State& state) {
  const Scene scene = FloorBoxes(static_cast<int>(state.range(0)));
  const SceneDistanceFieldsOptions o = PlannerFieldOptions(TopayKinematics());
  const GridGeometry3 g3 = GridGeometry3::FromBounds(scene.bounds_W_m, o.resolution_m);
  const GridGeometry2 g2 = GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(scene.bounds_W_m.min().head<2>(), scene.bounds_W_m.max().head<2>()),
      o.base_resolution_m);
  for (auto _ : state) {
    OccupancyGrid3 occupancy(g3);
    for (const OrientedBox& box : scene.boxes) occupancy.AddBox(box);
    SignedDistanceField3 field_3d = SignedDistanceField3::Build(occupancy, o.field);
    SignedDistanceField2 field_2d = OldFootprintField(g2, scene, o.base_band, o.base_exact_cap_m);
    if (o.base_upper_band) {
      field_2d.LowerTo(OldFootprintField(g2, scene, *o.base_upper_band, o.base_exact_cap_m),
                       o.base_upper_band_offset_m);
    }
    benchmark::DoNotOptimize(field_3d.values().data());
    benchmark::DoNotOptimize(field_2d.values().data());
  }
}

void BM_MapBuild(benchmark::State& state) {
  const Scene scene = FloorBoxes(static_cast<int>(state.range(0)));
  const SceneDistanceFieldsOptions options = PlannerFieldOptions(TopayKinematics());
  for (auto _ : state) {
    SceneDistanceFields fields = BuildSceneDistanceFields(scene, options);
    benchmark::DoNotOptimize(fields.base_field_2d.values().data());
  }
  state.counters["boxes"] = static_cast<double>(scene.boxes.size());
}

// The README's start state and topay-plan's target (3, 0.5, 0.8) m, pitch 1.57 rad.
void BM_PlanInScene(benchmark::State& state) {
  const Scene scene = FloorBoxes(static_cast<int>(state.range(0)));
  const Kinematics& kinematics = TopayKinematics();
  WholeBodyState start;
  start.x_m = kStartBase.x();
  start.y_m = kStartBase.y();
  start.q_rad.resize(kinematics.num_joints());
  start.q_rad << 0, 0.5, 0, 1.2, 0, 0.6, 0;
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  X_WE.translation() << kGoalBase.x(), kGoalBase.y(), 0.8;
  X_WE.linear() = Eigen::AngleAxisd(1.57, Eigen::Vector3d::UnitY()).toRotationMatrix();
  WholeBodyPlannerOptions options;  // time_limit_s 3 s, the robot's base limits
  int successes = 0, time_limits = 0, runs = 0;
  double worst_total_ms = 0.0;
  double cpu_s = 0.0;
  for (auto _ : state) {
    const std::clock_t cpu0 = std::clock();  // the process's CPU time: every thread
    const ScenePlan plan = PlanInScene(kinematics, scene, options, start, X_WE);
    cpu_s += static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
    ++runs;
    successes += plan.result.success();
    time_limits += plan.result.status == PlanStatus::kTimeLimit;
    worst_total_ms = std::max(worst_total_ms, plan.result.timings.total_ms);
    state.counters["map_ms"] = plan.result.timings.map_ms;
  }
  state.counters["success"] = static_cast<double>(successes) / runs;
  state.counters["time_limit"] = static_cast<double>(time_limits) / runs;
  state.counters["worst_total_ms"] = worst_total_ms;
  state.counters["process_cpu_ms"] = 1e3 * cpu_s / runs;
}

BENCHMARK(BM_MapBuildBefore)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_MapBuild)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_PlanInScene)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)
    ->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace topay

int main(int argc, char** argv) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--write-scenes") == 0) {
      for (int count : {1000, 10000, 100000}) {
        const std::string path =
            std::string(argv[i + 1]) + "/floor_boxes_" + std::to_string(count) + ".json";
        topay::WriteSceneJson(path, topay::FloorBoxes(count));
        std::cout << path << "\n";
      }
      return 0;
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
