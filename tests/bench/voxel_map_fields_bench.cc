// Benchmarks of the planner's fields from a sensed map (core/map/voxel_map_fields.h, issue 17
// item 3): the full build over the 20 x 20 x 1.6 m room at 0.05 m voxels (2D base field at
// 0.01 m, both caps 1 m, two bands), and the incremental update for a scan's typical change
// set around a robot pose: a box appearing (then going away again), and scattered voxels.
// Each update is timed on its own (wall clock and thread CPU time); the counters give the
// median and p95 (nearest rank) over the iterations, for the whole update and the 3D and 2D
// field parts. Run (Release build):
//   build-bench/bin/voxel_map_fields_bench --benchmark_min_time=3
// Figures: docs/benchmarks.md, "Sensed-map fields (issue 17, part)".

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numbers>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "core/map/occupancy_grid3.h"
#include "core/map/signed_distance_window.h"
#include "core/map/voxel_map_fields.h"
#include "sim/scenes/benchmark_scene.h"
#include "tests/bench/bench_clock.h"

namespace topay {
namespace {

using bench_clock::ThreadCpuSeconds;
using bench_clock::WallSeconds;

void ReportPercentiles(benchmark::State& state, std::vector<double> times, const std::string& name,
                       double scale) {
  if (times.empty()) return;
  std::sort(times.begin(), times.end());
  const auto at = [&](double q) {
    const std::size_t rank = static_cast<std::size_t>(std::ceil(q * times.size()));
    return times[std::clamp<std::size_t>(rank, 1, times.size()) - 1] * scale;
  };
  state.counters["median_" + name] = at(0.5);
  state.counters["p95_" + name] = at(0.95);
}

// The planner's settings for the base field (PlannerFieldOptions: 0.01 m, cap 1 m, two bands;
// the upper band and offset as on the TopAY arm, to within a few cm) over the benchmark room.
VoxelMapFieldsOptions BenchOptions(const Scene& scene) {
  VoxelMapFieldsOptions options;
  options.bounds_W_m = scene.bounds_W_m;
  options.resolution_m = 0.05;
  options.field_3d_cap_m = 1.0;
  options.base_resolution_m = 0.01;
  options.base_cap_m = 1.0;
  options.base_band = HeightBand{0.0, 0.155};
  options.base_upper_band = HeightBand{0.0, 0.70};
  options.base_upper_band_offset_m = 0.2;
  return options;
}

OccupancyGrid3 Voxels(const Scene& scene, const GridGeometry3& geometry) {
  OccupancyGrid3 grid(geometry);
  for (const OrientedBox& box : scene.boxes) grid.AddBox(box);
  return grid;
}

// The changes that set the voxels `box` covers (AddBox) to `state`.
std::vector<VoxelChange> BoxChanges(const GridGeometry3& g, const OrientedBox& box,
                                    VoxelState state) {
  OccupancyGrid3 grid(g);
  grid.AddBox(box);
  std::vector<VoxelChange> changes;
  for (int iz = 0; iz < g.dims.z(); ++iz)
    for (int iy = 0; iy < g.dims.y(); ++iy)
      for (int ix = 0; ix < g.dims.x(); ++ix)
        if (grid.IsOccupied(ix, iy, iz)) changes.push_back({{ix, iy, iz}, state});
  return changes;
}

// Full build: every voxel set from the Tables room, then both fields over the whole grid.
void BM_FullBuild(benchmark::State& state) {
  const Scene scene = GenerateTablesScene(1).scene;
  VoxelMapFields map(BenchOptions(scene));
  const OccupancyGrid3 voxels = Voxels(scene, map.geometry());
  std::vector<double> wall, cpu;
  for (auto _ : state) {
    const double w = WallSeconds(), c = ThreadCpuSeconds();
    map.ResetFrom(voxels);
    cpu.push_back(ThreadCpuSeconds() - c);
    wall.push_back(WallSeconds() - w);
  }
  ReportPercentiles(state, wall, "ms", 1e3);
  ReportPercentiles(state, cpu, "cpu_ms", 1e3);
  state.counters["voxels"] = static_cast<double>(map.geometry().NumCells());
  state.counters["cells_2d"] = static_cast<double>(map.base_geometry().NumCells());
}
BENCHMARK(BM_FullBuild)->Unit(benchmark::kMillisecond)->Iterations(8);

// The 3D field alone over the whole grid (the full build's 3D part).
void BM_FullBuild3d(benchmark::State& state) {
  const Scene scene = GenerateTablesScene(1).scene;
  const GridGeometry3 g = GridGeometry3::FromBounds(scene.bounds_W_m, 0.05);
  const OccupancyGrid3 voxels = Voxels(scene, g);
  std::vector<float> values(g.NumCells());
  SignedDistanceWindowWorkspace ws;
  std::vector<double> cpu;
  for (auto _ : state) {
    const double c = ThreadCpuSeconds();
    RecomputeSignedDistanceWindow(voxels.cells().data(), g.dims, 3, 0.05, 1.0, {},
                                  CellBox{Eigen::Vector3i::Zero(), g.dims}, &ws, values.data());
    cpu.push_back(ThreadCpuSeconds() - c);
  }
  ReportPercentiles(state, cpu, "cpu_ms", 1e3);
}
BENCHMARK(BM_FullBuild3d)->Unit(benchmark::kMillisecond)->Iterations(8);

// A box of the given size (cm: x, y, z; floor standing, random yaw; fourth argument: the 3D
// field's cap in cm) appears 0.8-2 m from a
// seeded robot pose in the Tables room, and goes away at the next iteration: each iteration is
// one ApplyChanges of the box's voxels.
void BM_BoxAppears(benchmark::State& state) {
  const Scene scene = GenerateTablesScene(1).scene;
  VoxelMapFieldsOptions options = BenchOptions(scene);
  options.field_3d_cap_m = state.range(3) / 100.0;
  VoxelMapFields map(options);
  map.ResetFrom(Voxels(scene, map.geometry()));
  const Eigen::Vector3d size(state.range(0) / 100.0, state.range(1) / 100.0,
                             state.range(2) / 100.0);
  Rng rng(5);
  std::vector<double> wall, cpu, field_3d, field_2d;
  double voxels = 0.0, cells_3d = 0.0, cells_2d = 0.0;
  std::vector<VoxelChange> placed;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<VoxelChange> changes;
    if (placed.empty()) {
      const double robot_x = rng.Uniform(-8.0, 8.0), robot_y = rng.Uniform(-8.0, 8.0);
      const double range = rng.Uniform(0.8, 2.0),
                   bearing = rng.Uniform(-std::numbers::pi, std::numbers::pi);
      OrientedBox box;
      box.center_W_m = Eigen::Vector3d(robot_x + range * std::cos(bearing),
                                       robot_y + range * std::sin(bearing), 0.5 * size.z());
      box.size_m = size;
      box.yaw_rad = rng.Uniform(-std::numbers::pi, std::numbers::pi);
      placed = BoxChanges(map.geometry(), box, VoxelState::kOccupied);
      changes = placed;
    } else {
      changes = placed;
      for (VoxelChange& change : changes) change.state = VoxelState::kFree;
      placed.clear();
    }
    state.ResumeTiming();
    const double w = WallSeconds(), c = ThreadCpuSeconds();
    const VoxelMapUpdateSummary summary = map.ApplyChanges(changes);
    cpu.push_back(ThreadCpuSeconds() - c);
    wall.push_back(WallSeconds() - w);
    field_3d.push_back(summary.field_3d_s);
    field_2d.push_back(summary.field_2d_s);
    voxels += summary.num_voxels_changed;
    cells_3d += static_cast<double>(summary.num_cells_3d);
    cells_2d += static_cast<double>(summary.num_cells_2d);
  }
  ReportPercentiles(state, wall, "ms", 1e3);
  ReportPercentiles(state, cpu, "cpu_ms", 1e3);
  ReportPercentiles(state, field_3d, "3d_ms", 1e3);
  ReportPercentiles(state, field_2d, "2d_ms", 1e3);
  const double n = static_cast<double>(wall.size());
  state.counters["voxels_changed"] = voxels / n;
  state.counters["cells_3d"] = cells_3d / n;
  state.counters["cells_2d"] = cells_2d / n;
}
BENCHMARK(BM_BoxAppears)
    ->Args({30, 30, 60, 100})   // ~600 voxels: a small box or a bag
    ->Args({50, 50, 100, 100})  // ~2,400 voxels: a box, a person's legs and trunk
    ->Args({100, 60, 80, 100})  // ~4,300 voxels: a cart or a small table
    ->Args({30, 30, 60, 50})    // the same with the 3D field capped at 0.5 m
    ->Args({50, 50, 100, 50})
    ->Args({100, 60, 80, 50})
    ->Unit(benchmark::kMillisecond);

// Scattered changes (a scan's noise): `count` voxels within 4 m of a seeded robot pose flip
// to occupied, then back to free at the next iteration.
void BM_ScatteredVoxels(benchmark::State& state) {
  const Scene scene = GenerateTablesScene(1).scene;
  VoxelMapFields map(BenchOptions(scene));
  map.ResetFrom(Voxels(scene, map.geometry()));
  const GridGeometry3& g = map.geometry();
  const int count = static_cast<int>(state.range(0));
  Rng rng(9);
  std::vector<double> wall, cpu;
  std::vector<VoxelChange> placed;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<VoxelChange> changes;
    if (placed.empty()) {
      const Eigen::Vector2d robot(rng.Uniform(-6.0, 6.0), rng.Uniform(-6.0, 6.0));
      for (int i = 0; i < count; ++i) {
        const Eigen::Vector3d p(robot.x() + rng.Uniform(-4.0, 4.0),
                                robot.y() + rng.Uniform(-4.0, 4.0), rng.Uniform(0.0, 1.6));
        const Eigen::Vector3i v =
            g.CellOf(p).cwiseMax(0).cwiseMin(g.dims - Eigen::Vector3i::Ones());
        if (map.state(v.x(), v.y(), v.z()) == VoxelState::kOccupied) continue;
        placed.push_back({v, VoxelState::kOccupied});
      }
      changes = placed;
    } else {
      changes = placed;
      for (VoxelChange& change : changes) change.state = VoxelState::kFree;
      placed.clear();
    }
    state.ResumeTiming();
    const double w = WallSeconds(), c = ThreadCpuSeconds();
    map.ApplyChanges(changes);
    cpu.push_back(ThreadCpuSeconds() - c);
    wall.push_back(WallSeconds() - w);
  }
  ReportPercentiles(state, wall, "ms", 1e3);
  ReportPercentiles(state, cpu, "cpu_ms", 1e3);
}
BENCHMARK(BM_ScatteredVoxels)->Arg(20)->Arg(300)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
