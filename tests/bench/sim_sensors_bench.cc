// Benchmarks of the simulator's per-step sensors (issue 16): one full LiDAR scan
// (sim/lidar/LidarScanner: 20,000 rays, Mid-360 defaults, 2 cm range noise) and one collision
// monitor check (sim/monitor/CollisionMonitor: the whole collision model against every box
// near the robot, self pairs and chassis), in a seeded Tables benchmark room (~540 boxes), one
// thread. The robot visits 64 seeded poses where its base is clear of the boxes (arm stowed
// for the scans; random joint states within the limits for the monitor). Each iteration's
// time is recorded; the counters give the median and p95 over the iterations.
// Run (Release build):
//   build/bin/sim_sensors_bench --benchmark_min_time=5
// Commands and figures: docs/benchmarks.md ("Simulator (issue 16): LiDAR scan and collision
// monitor").

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <time.h>

#include <benchmark/benchmark.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/common/stopwatch.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "sim/lidar/lidar_scanner.h"
#include "sim/monitor/collision_monitor.h"
#include "sim/scenes/benchmark_scene.h"

namespace topay {
namespace {

RobotModel LoadModel() {
  const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
  return LoadRobotModel(dir + "topay_mm.urdf", dir + "topay_mm.yaml");
}

// 64 poses with the base at least 5 cm from every box, seeded; the arm at `q` or, if
// `random_q`, uniform within the joint limits.
std::vector<WholeBodyState> ClearPoses(const Kinematics& kinematics, const Scene& scene,
                                       bool random_q, std::uint64_t seed) {
  const RobotModel& model = kinematics.model();
  const SceneClearanceChecker checker(kinematics, scene);
  Rng rng(seed);
  std::vector<WholeBodyState> poses;
  while (poses.size() < 64) {
    WholeBodyState state;
    state.x_m = rng.Uniform(-9, 9);
    state.y_m = rng.Uniform(-9, 9);
    state.yaw_rad = rng.Uniform(-3.14159, 3.14159);
    state.q_rad = model.stow_q_rad;
    if (random_q) {
      for (int i = 0; i < model.num_joints(); ++i) {
        state.q_rad(i) = rng.Uniform(model.joint_limits.q_min_rad(i), model.joint_limits.q_max_rad(i));
      }
    }
    if (checker.BaseClearance({state.x_m, state.y_m}, 1.0) > 0.05) poses.push_back(state);
  }
  return poses;
}

// This thread's CPU time (s): what one core spends, whatever else runs on the machine.
double ThreadCpuS() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// Median and 95th percentile (nearest rank) of the recorded times.
void ReportPercentiles(benchmark::State& state, std::vector<double> times, const std::string& unit,
                       double scale) {
  std::sort(times.begin(), times.end());
  const auto at = [&](double q) {
    const std::size_t rank = static_cast<std::size_t>(std::ceil(q * times.size()));
    return times[std::clamp<std::size_t>(rank, 1, times.size()) - 1] * scale;
  };
  state.counters["median_" + unit] = at(0.5);
  state.counters["p95_" + unit] = at(0.95);
  state.counters["max_" + unit] = times.back() * scale;
}

void BM_LidarScan(benchmark::State& state) {
  const RobotModel model = LoadModel();
  const Kinematics kinematics(model);
  const Scene scene =
      GenerateBenchmarkScene(SceneKind::kTables, static_cast<std::uint64_t>(state.range(0))).scene;
  const std::vector<WholeBodyState> poses = ClearPoses(kinematics, scene, false, 1);
  sim::LidarOptions options;
  if (state.range(1) > 0) options.grid_cell_m = 1e-3 * static_cast<double>(state.range(1));
  sim::LidarScanner scanner(options, kinematics, 7);
  scanner.SetWorld(scene.boxes);
  std::vector<double> times_s, cpu_s;
  double points = 0.0, self_hits = 0.0;
  std::size_t i = 0;
  for (auto _ : state) {
    const Stopwatch watch;
    const double cpu0 = ThreadCpuS();
    const sim::LidarScan scan = scanner.Scan(poses[i % poses.size()], 0.1 * i);
    cpu_s.push_back(ThreadCpuS() - cpu0);
    times_s.push_back(watch.ElapsedS());
    ++i;
    points += scan.p_SP.size();
    self_hits += scan.self_hits;
    benchmark::DoNotOptimize(scan.p_SP.data());
  }
  ReportPercentiles(state, times_s, "ms", 1e3);
  ReportPercentiles(state, cpu_s, "cpu_ms", 1e3);
  state.counters["boxes"] = static_cast<double>(scene.boxes.size());
  state.counters["rays"] = scanner.points_per_scan();
  state.counters["points"] = points / times_s.size();
  state.counters["self_hits"] = self_hits / times_s.size();
  state.counters["box_tests_per_ray"] =
      static_cast<double>(scanner.grid().box_tests()) /
      (static_cast<double>(times_s.size()) * scanner.points_per_scan());
}
// Args: the scene seed, the grid cell (mm; 0: the default, LidarOptions::grid_cell_m).
BENCHMARK(BM_LidarScan)
    ->Args({1, 0})
    ->Args({2, 0})
    ->Args({3, 0})
    ->Args({1, 250})
    ->Args({1, 1000})
    ->Args({1, 2000})
    ->Unit(benchmark::kMillisecond);

void BM_CollisionMonitorCheck(benchmark::State& state) {
  const RobotModel model = LoadModel();
  const Kinematics kinematics(model);
  const Scene scene =
      GenerateBenchmarkScene(SceneKind::kTables, static_cast<std::uint64_t>(state.range(0))).scene;
  const std::vector<WholeBodyState> poses = ClearPoses(kinematics, scene, true, 2);
  sim::CollisionMonitor monitor(kinematics);
  monitor.SetWorld(scene.boxes);
  std::vector<double> times_s, cpu_s;
  std::size_t i = 0;
  for (auto _ : state) {
    const Stopwatch watch;
    const double cpu0 = ThreadCpuS();
    const auto& started = monitor.Check(poses[i % poses.size()], 0.002 * i);
    cpu_s.push_back(ThreadCpuS() - cpu0);
    times_s.push_back(watch.ElapsedS());
    ++i;
    benchmark::DoNotOptimize(started.data());
  }
  ReportPercentiles(state, times_s, "us", 1e6);
  ReportPercentiles(state, cpu_s, "cpu_us", 1e6);
  state.counters["boxes"] = static_cast<double>(scene.boxes.size());
  state.counters["contact_steps_share"] =
      static_cast<double>(monitor.counts().steps_in_contact) / monitor.counts().steps;
}
BENCHMARK(BM_CollisionMonitorCheck)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
