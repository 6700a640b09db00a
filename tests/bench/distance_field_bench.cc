// Benchmarks of core/map: building the signed distance fields of a whole 20 x 20 x 1.6 m room
// (~160 random boxes) at 0.1 and 0.05 m, and DistanceAndGradient queries at random points.
// Figures to meet (one core): build <= 30 ms at 0.1 m, <= 200 ms at 0.05 m; query <= 50 ns.
// Run (Release build):
//   build-map-rel/bin/distance_field_bench --benchmark_repetitions=20
//       --benchmark_report_aggregates_only=true   (one line)
// Each benchmark reports mean, median, stddev, cv and p95 over the repetitions.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "core/geometry/scene.h"
#include "core/map/occupancy_grid3.h"
#include "core/map/scene_distance_fields.h"
#include "core/map/signed_distance_field3.h"

namespace topay {
namespace {

// A small local stand-in for the benchmark "cuboids" room (the real generator lives in
// sim/scenes): four walls 1 m tall, 80 grounded boxes (footprint U[0.2, 0.8]^2 m, height
// U[0.4, 1.5] m) and 80 floating cubes (side U[0.3, 0.6] m, bottom U[0.4, 0.8] m), random yaw.
Scene BenchRoom(std::uint64_t seed) {
  Scene scene;
  scene.kind = "cuboids";
  scene.seed = seed;
  auto box = [](Eigen::Vector3d center, Eigen::Vector3d size, double yaw) {
    OrientedBox b;
    b.center_W_m = center;
    b.size_m = size;
    b.yaw_rad = yaw;
    return b;
  };
  scene.boxes.push_back(box({0, -9.9, 0.5}, {20, 0.2, 1}, 0));
  scene.boxes.push_back(box({0, 9.9, 0.5}, {20, 0.2, 1}, 0));
  scene.boxes.push_back(box({-9.9, 0, 0.5}, {0.2, 20, 1}, 0));
  scene.boxes.push_back(box({9.9, 0, 0.5}, {0.2, 20, 1}, 0));
  Rng rng(seed);
  for (int i = 0; i < 160; ++i) {
    const double yaw = rng.Uniform(-std::numbers::pi, std::numbers::pi);
    const double x = rng.Uniform(-9.5, 9.5);
    const double y = rng.Uniform(-9.5, 9.5);
    if (i % 2 == 0) {
      const Eigen::Vector3d size(rng.Uniform(0.2, 0.8), rng.Uniform(0.2, 0.8),
                                 rng.Uniform(0.4, 1.5));
      scene.boxes.push_back(box({x, y, 0.5 * size.z()}, size, yaw));
    } else {
      const double side = rng.Uniform(0.3, 0.6);
      const double bottom = rng.Uniform(0.4, 0.8);
      scene.boxes.push_back(box({x, y, bottom + 0.5 * side}, Eigen::Vector3d::Constant(side), yaw));
    }
  }
  return scene;
}

OccupancyGrid3 Rasterize(const Scene& scene, double resolution_m) {
  OccupancyGrid3 grid(GridGeometry3::FromBounds(scene.bounds_W_m, resolution_m));
  for (const OrientedBox& b : scene.boxes) grid.AddBox(b);
  return grid;
}

double Percentile95(const std::vector<double>& values) {
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  // Nearest-rank p95.
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * sorted.size()));
  return sorted[std::max<std::size_t>(rank, 1) - 1];
}

double ResolutionOf(const benchmark::State& state) { return state.range(0) / 1000.0; }

// The 3D field alone (two exact EDTs + signing), rebuilt in place with a warm workspace: what
// a mapper pays per update once running.
void BM_Sdf3Rebuild(benchmark::State& state) {
  const OccupancyGrid3 grid = Rasterize(BenchRoom(1), ResolutionOf(state));
  EdtWorkspace workspace;
  SignedDistanceField3 field = SignedDistanceField3::Build(grid, {}, &workspace);
  for (auto _ : state) {
    field.Rebuild(grid, {}, &workspace);
    benchmark::DoNotOptimize(field.values().data());
  }
  state.counters["cells"] = static_cast<double>(grid.geometry().NumCells());
}

// Everything from the scene: rasterise 3D and 2D, build both fields, cold (allocating).
void BM_SceneDistanceFields(benchmark::State& state) {
  const Scene scene = BenchRoom(1);
  SceneDistanceFieldsOptions options;
  options.resolution_m = ResolutionOf(state);
  for (auto _ : state) {
    SceneDistanceFields fields = BuildSceneDistanceFields(scene, options);
    benchmark::DoNotOptimize(fields.field_3d.values().data());
  }
}

// One DistanceAndGradient per iteration at uniformly random points of the room (so most
// queries miss the caches at 0.05 m, where the field is 20 MB).
void BM_DistanceAndGradient(benchmark::State& state) {
  const Scene scene = BenchRoom(1);
  const SignedDistanceField3 field =
      SignedDistanceField3::Build(Rasterize(scene, ResolutionOf(state)));
  Rng rng(2);
  std::vector<Eigen::Vector3d> points(1 << 16);
  for (Eigen::Vector3d& p : points) {
    p = {rng.Uniform(-10, 10), rng.Uniform(-10, 10), rng.Uniform(0, 1.6)};
  }
  std::size_t i = 0;
  Eigen::Vector3d gradient;
  for (auto _ : state) {
    const double d = field.DistanceAndGradient(points[i], &gradient);
    benchmark::DoNotOptimize(d);
    benchmark::DoNotOptimize(gradient);
    i = (i + 1) & (points.size() - 1);
  }
}

// The same query along a smooth path (1 cm steps on a random walk of headings), as a trajectory
// optimizer sampling a trajectory asks: neighbouring queries share cache lines.
void BM_DistanceAndGradientAlongPath(benchmark::State& state) {
  const Scene scene = BenchRoom(1);
  const SignedDistanceField3 field =
      SignedDistanceField3::Build(Rasterize(scene, ResolutionOf(state)));
  Rng rng(3);
  std::vector<Eigen::Vector3d> points(1 << 16);
  Eigen::Vector3d p(0, 0, 0.8);
  double heading = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    heading += rng.Uniform(-0.05, 0.05);
    p += 0.01 * Eigen::Vector3d(std::cos(heading), std::sin(heading), 0.0);
    p = p.cwiseMax(Eigen::Vector3d(-9.5, -9.5, 0.0)).cwiseMin(Eigen::Vector3d(9.5, 9.5, 1.6));
    points[k] = {p.x(), p.y(), 0.8 + 0.5 * std::sin(0.002 * static_cast<double>(k))};
  }
  std::size_t i = 0;
  Eigen::Vector3d gradient;
  for (auto _ : state) {
    const double d = field.DistanceAndGradient(points[i], &gradient);
    benchmark::DoNotOptimize(d);
    benchmark::DoNotOptimize(gradient);
    i = (i + 1) & (points.size() - 1);
  }
}

BENCHMARK(BM_Sdf3Rebuild)
    ->Arg(100)->Arg(50)->ArgName("res_mm")
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("p95", Percentile95);
BENCHMARK(BM_SceneDistanceFields)
    ->Arg(100)->Arg(50)->ArgName("res_mm")
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("p95", Percentile95);
BENCHMARK(BM_DistanceAndGradient)
    ->Arg(100)->Arg(50)->ArgName("res_mm")
    ->Unit(benchmark::kNanosecond)
    ->ComputeStatistics("p95", Percentile95);
BENCHMARK(BM_DistanceAndGradientAlongPath)
    ->Arg(100)->Arg(50)->ArgName("res_mm")
    ->Unit(benchmark::kNanosecond)
    ->ComputeStatistics("p95", Percentile95);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
