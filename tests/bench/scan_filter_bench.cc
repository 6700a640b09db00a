// Benchmarks of the mapper's scan filter (issue 17: procs/mapper/scan_filter.h) and of the
// OctoMap mirror's insertion of its output (procs/mapper/octomap_mirror.h), per simulated
// 20,000-ray scan (sim/lidar/LidarScanner: Mid-360 defaults, 2 cm range noise, the floor
// on; ~11,000 returns, the rays into the open sky give none) of a seeded Tables room, from 64 seeded poses with the whole robot at least 5 cm from
// every box and the arm at random joint states within the limits, one thread. The scans are
// made before timing; each iteration filters one (poses in turn) and records each stage's
// time (the summary's steady-clock times). Counters: median and p95 per stage (ms), and the
// mean point counts after each stage.
//   BM_ScanFilter/<outlier>: 0 none (the default), 1 radius, 2 statistical.
//   BM_OctomapInsert: the default filter's output inserted into one OctomapMirror at 0.05 m
//     (free-space ray casting, max range 20 m), the mirror kept across scans as in the mapper.
// Run (Release build):
//   build/bin/scan_filter_bench

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "procs/mapper/octomap_mirror.h"
#include "procs/mapper/scan_filter.h"
#include "sim/lidar/lidar_scanner.h"
#include "sim/scenes/benchmark_scene.h"

namespace topay {
namespace {

using mapper::ScanFilterSummary;

constexpr int kNumPoses = 64;

RobotModel LoadModel() {
  const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/config/robot/";
  return LoadRobotModel(dir + "topay_mm.urdf", dir + "topay_mm.yaml");
}

// kNumPoses seeded states in [-9, 9]^2 m, the whole body > 5 cm from every box.
std::vector<WholeBodyState> ClearStates(const Kinematics& kinematics, const Scene& scene) {
  const RobotModel& model = kinematics.model();
  const SceneClearanceChecker checker(kinematics, scene);
  Rng rng(17);
  std::vector<WholeBodyState> states;
  while (states.size() < kNumPoses) {
    WholeBodyState state;
    state.x_m = rng.Uniform(-9, 9);
    state.y_m = rng.Uniform(-9, 9);
    state.yaw_rad = rng.Uniform(-3.14159, 3.14159);
    state.q_rad.resize(model.num_joints());
    for (int i = 0; i < model.num_joints(); ++i) {
      const JointLimits& limits = model.joint_limits;
      state.q_rad(i) = rng.Uniform(limits.q_min_rad(i), limits.q_max_rad(i));
    }
    if (checker.BaseClearance({state.x_m, state.y_m}, 1.0) > 0.05 &&
        checker.Compute(state).obstacle_m() > 0.05) {
      states.push_back(state);
    }
  }
  return states;
}

// The scans, their states, and the robot they were taken of (built once).
struct ScanSet {
  RobotModel model = LoadModel();
  Kinematics kinematics{model};
  std::vector<WholeBodyState> states;
  std::vector<msgs::CheckedCloud> clouds;

  ScanSet() {
    const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 1).scene;
    states = ClearStates(kinematics, scene);
    sim::LidarOptions options;
    options.ground_plane = true;
    sim::LidarScanner scanner(options, kinematics, 5);
    scanner.SetWorld(scene.boxes);
    for (const WholeBodyState& state : states) {
      const sim::LidarScan scan = scanner.Scan(state, 0.1 * clouds.size());
      clouds.push_back({static_cast<std::int64_t>(scan.t_s * 1e6), scan.X_WS, scan.p_SP});
    }
  }
};

const ScanSet& Scans() {
  static const ScanSet* scans = new ScanSet();
  return *scans;
}

// Median and 95th percentile (nearest rank) of `values` as counters "<name>_median_ms", ...
void ReportPercentiles(benchmark::State& state, const std::string& name,
                       std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const auto at = [&](double q) {
    const std::size_t rank = static_cast<std::size_t>(std::ceil(q * values.size()));
    return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
  };
  state.counters[name + "_median_ms"] = at(0.5);
  state.counters[name + "_p95_ms"] = at(0.95);
}

void BM_ScanFilter(benchmark::State& state) {
  const ScanSet& scans = Scans();
  mapper::ScanFilterOptions options;
  options.outlier_method = static_cast<mapper::OutlierMethod>(state.range(0));
  mapper::ScanFilter filter(options, scans.kinematics);
  std::vector<Eigen::Vector3f> p_WP;
  std::vector<ScanFilterSummary> summaries;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % scans.clouds.size();
    summaries.push_back(filter.Filter(scans.clouds[k], scans.states[k], &p_WP));
    benchmark::DoNotOptimize(p_WP.data());
  }
  const auto report = [&](const char* name, double ScanFilterSummary::*field) {
    std::vector<double> values;
    for (const ScanFilterSummary& s : summaries) values.push_back(s.*field);
    ReportPercentiles(state, name, values);
  };
  report("range", &ScanFilterSummary::range_ms);
  report("ground", &ScanFilterSummary::ground_ms);
  report("self", &ScanFilterSummary::self_ms);
  report("voxel", &ScanFilterSummary::voxel_ms);
  report("outlier", &ScanFilterSummary::outlier_ms);
  report("total", &ScanFilterSummary::total_ms);
  const auto mean = [&](int ScanFilterSummary::*field) {
    double sum = 0.0;
    for (const ScanFilterSummary& s : summaries) sum += s.*field;
    return sum / summaries.size();
  };
  state.counters["n_in"] = mean(&ScanFilterSummary::num_input);
  state.counters["n_range"] = mean(&ScanFilterSummary::num_after_range);
  state.counters["n_ground"] = mean(&ScanFilterSummary::num_after_ground);
  state.counters["n_self"] = mean(&ScanFilterSummary::num_after_self);
  state.counters["n_voxel"] = mean(&ScanFilterSummary::num_after_voxel);
  state.counters["n_out"] = mean(&ScanFilterSummary::num_output);
}
BENCHMARK(BM_ScanFilter)->Arg(0)->Arg(1)->Arg(2)->Iterations(2 * kNumPoses)
    ->Unit(benchmark::kMillisecond);

void BM_OctomapInsert(benchmark::State& state) {
  const ScanSet& scans = Scans();
  mapper::ScanFilter filter(mapper::ScanFilterOptions{}, scans.kinematics);
  std::vector<std::vector<Eigen::Vector3f>> filtered(scans.clouds.size());
  for (std::size_t k = 0; k < scans.clouds.size(); ++k) {
    filter.Filter(scans.clouds[k], scans.states[k], &filtered[k]);
  }
  mapper::OctomapMirror mirror;
  std::vector<double> times;
  double points = 0.0;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % scans.clouds.size();
    const mapper::OctomapInsertSummary s =
        mirror.Insert(scans.clouds[k].X_WS.translation(), filtered[k]);
    times.push_back(s.ms);
    points += s.num_points;
  }
  ReportPercentiles(state, "insert", times);
  state.counters["n_points"] = points / times.size();
  state.counters["leaves"] = static_cast<double>(mirror.tree().getNumLeafNodes());
}
BENCHMARK(BM_OctomapInsert)->Iterations(kNumPoses)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
