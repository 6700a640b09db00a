// Benchmark of the dense occupancy map's scan insertion (core/map/occupancy_map.h, issue 17
// item 2): one simulated LiDAR scan (sim/lidar, Mid-360 defaults: 20,000 rays, 2 cm noise;
// floor (z < 0.05 m) and self hits dropped, as the mapper's filters do) of a seeded Tables room (20 x 20 x 1.6 m) inserted into the
// 400 x 400 x 32 map at 0.05 m (clearing up to 10 m), one thread, from 64 seeded poses
// across the room, visited twice (the first visit sees unknown space, the second a built
// map). First argument: 0 = every return; 1 = returns first deduplicated by voxel (one point
// per 0.05 m voxel, a stand-in for the mapper's PCL voxel-grid filter; its time is reported
// apart as dedupe_ms and not included in the insertion time). Second argument: 0 = the room
// as generated (no ceiling: only ~8,000 of the 20,000 rays return); 1 = with a ceiling at
// 2.5 m (testing::ScanRoom's with_ceiling: nearly every ray returns, the full scan's load;
// the ceiling returns lie above the 1.6 m map volume, so they clear and give no hit).
// Counters: median and p95 (nearest rank) of the insertion's wall and CPU time, points and
// changes per scan.
// Run (Release build):
//   build/bin/occupancy_map_bench
// Figures: reported with issue 17 item 2 (not yet in docs/benchmarks.md).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/stopwatch.h"
#include "core/map/occupancy_map.h"
#include "tests/core/map/scanned_room.h"

namespace topay {
namespace {

// Nearest-rank quantile q of the values (sorted in place).
double Quantile(std::vector<double>* values, double q) {
  std::sort(values->begin(), values->end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * values->size()));
  return (*values)[std::clamp<std::size_t>(rank, 1, values->size()) - 1];
}

void SetMedianAndP95(benchmark::State& state, const std::string& name, std::vector<double> v,
                     double scale) {
  if (v.empty()) return;
  state.counters["median_" + name] = scale * Quantile(&v, 0.5);
  state.counters["p95_" + name] = scale * Quantile(&v, 0.95);
}

// Keeps the first return in each voxel of `geometry` (returns outside it are kept); `stamp`
// holds one entry per voxel, `generation` tells this call's marks from earlier calls'.
void DedupeByVoxel(const GridGeometry3& geometry, const std::vector<Eigen::Vector3f>& points,
                   std::uint32_t generation, std::vector<std::uint32_t>* stamp,
                   std::vector<Eigen::Vector3f>* kept) {
  kept->clear();
  for (const Eigen::Vector3f& p : points) {
    const Eigen::Vector3d p_W = p.cast<double>();
    if (!geometry.Contains(p_W)) {
      kept->push_back(p);
      continue;
    }
    const Eigen::Vector3i v = geometry.CellOf(p_W);
    std::uint32_t& s = (*stamp)[geometry.Index(v.x(), v.y(), v.z())];
    if (s == generation) continue;
    s = generation;
    kept->push_back(p);
  }
}

void BM_InsertScan(benchmark::State& state) {
  const bool dedupe = state.range(0) != 0;
  const bool with_ceiling = state.range(1) != 0;
  static const testing::ScannedRoom rooms[2] = {
      testing::ScanRoom(SceneKind::kTables, 1, 64, 0.02, false),
      testing::ScanRoom(SceneKind::kTables, 1, 64, 0.02, true)};
  const testing::ScannedRoom& room = rooms[with_ceiling ? 1 : 0];
  OccupancyMapOptions options;
  options.bounds_W_m = room.scene.bounds_W_m;
  OccupancyMap map(options);
  std::vector<std::uint32_t> stamp(map.geometry().NumCells(), 0);
  std::vector<Eigen::Vector3f> kept;
  std::vector<VoxelChange> changes;
  std::vector<double> wall_s, cpu_s, dedupe_s, points, changes_first, changes_second, steps;
  std::size_t i = 0;
  for (auto _ : state) {
    const testing::WorldScan& scan = room.scans[i % room.scans.size()];
    const Stopwatch dedupe_watch;
    if (dedupe) DedupeByVoxel(map.geometry(), scan.p_WP, static_cast<std::uint32_t>(i + 1), &stamp, &kept);
    dedupe_s.push_back(dedupe_watch.ElapsedS());
    const std::vector<Eigen::Vector3f>& p_WP = dedupe ? kept : scan.p_WP;
    changes.clear();
    const CpuStopwatch cpu;  // the process's CPU time: the benchmark runs one thread
    const ScanInsertSummary s = map.InsertScan(scan.p_WS, p_WP, &changes);
    cpu_s.push_back(cpu.ElapsedS());
    wall_s.push_back(s.total_s);
    points.push_back(s.num_points);
    steps.push_back(static_cast<double>(s.num_ray_steps));
    (i < room.scans.size() ? changes_first : changes_second).push_back(s.num_changes);
    ++i;
  }
  SetMedianAndP95(state, "ms", wall_s, 1e3);
  SetMedianAndP95(state, "cpu_ms", cpu_s, 1e3);
  if (dedupe) SetMedianAndP95(state, "dedupe_ms", dedupe_s, 1e3);
  SetMedianAndP95(state, "points", points, 1.0);
  SetMedianAndP95(state, "ray_steps", steps, 1.0);
  SetMedianAndP95(state, "changes_first_visit", changes_first, 1.0);
  SetMedianAndP95(state, "changes_second_visit", changes_second, 1.0);
  const VoxelStateCounts counts = map.CountStates();
  state.counters["occupied"] = static_cast<double>(counts.occupied);
  state.counters["free"] = static_cast<double>(counts.free);
}
BENCHMARK(BM_InsertScan)
    ->Args({0, 0})
    ->Args({1, 0})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Iterations(128)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
