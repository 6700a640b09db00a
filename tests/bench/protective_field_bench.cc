// Benchmarks of the tracker's protective field (core/control/protective_field.h,
// procs/tracker/field_scan_intake.h), one thread, on simulated 20,000-ray scans (sim/lidar:
// Mid-360 defaults, 2 cm range noise, the robot's own body in view) of a seeded Tables room from
// 32 seeded poses with the base at least 0.3 m from every box and the arm stowed. The scans are
// made and encoded as POINT_CLOUD messages before timing.
//   BM_FieldScanIntake: one message in turn -> the checked cloud, its points in W, the robot's
//     own body removed, and ProtectiveField::SetScan (the tracker's work per scan, 10 Hz).
//     Counters: median / p95 ms, mean points kept.
//   BM_FieldCheck/<speed cm/s>: one check of the base path ahead on a straight reference at that
//     speed against the scan kept at the pose (the tracker's work per cycle, 50 Hz), path built
//     by BasePathAhead included. Counters: median / p95 ms, mean path poses.
// Run (Release build):
//   build/bin/protective_field_bench

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/common/sample_statistics.h"
#include "core/control/protective_field.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "procs/sim/sim_messages.h"
#include "procs/tracker/field_scan_intake.h"
#include "sim/lidar/lidar_scanner.h"
#include "sim/scenes/benchmark_scene.h"

namespace topay {
namespace {

constexpr int kNumPoses = 32;
constexpr std::int64_t kT0 = 1'700'000'000'000'000;

struct Scans {
  RobotModel model = LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                                    std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml");
  Kinematics kinematics{model};
  std::vector<WholeBodyState> states;
  std::vector<point_cloud_t> messages;

  Scans() {
    const Scene scene = GenerateBenchmarkScene(SceneKind::kTables, 1).scene;
    const SceneClearanceChecker checker(kinematics, scene);
    Rng rng(23);
    while (static_cast<int>(states.size()) < kNumPoses) {
      WholeBodyState state;
      state.x_m = rng.Uniform(-9, 9);
      state.y_m = rng.Uniform(-9, 9);
      state.yaw_rad = rng.Uniform(-3.14159, 3.14159);
      state.q_rad = model.stow_q_rad.size() > 0 ? model.stow_q_rad : Eigen::VectorXd::Zero(model.num_joints());
      if (checker.BaseClearance({state.x_m, state.y_m}, 1.0) > 0.3) states.push_back(state);
    }
    sim::LidarScanner scanner(sim::LidarOptions{}, kinematics, 9);
    scanner.SetWorld(scene.boxes);
    for (std::size_t k = 0; k < states.size(); ++k) {
      const sim::LidarScan scan = scanner.Scan(states[k], 0.0);
      messages.push_back(simproc::ToPointCloud({scan.t_s, scan.X_WS, scan.p_SP},
                                               kT0 + static_cast<std::int64_t>(k) * 100'000, "lidar"));
    }
  }
};

const Scans& TheScans() {
  static const Scans* scans = new Scans();
  return *scans;
}

void ReportPercentiles(benchmark::State& state, const std::vector<double>& ms) {
  state.counters["median_ms"] = NearestRankQuantile(ms, 0.5);
  state.counters["p95_ms"] = NearestRankQuantile(ms, 0.95);
}

double MsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void BM_FieldScanIntake(benchmark::State& state) {
  const Scans& scans = TheScans();
  tracker::FieldScanIntake intake(scans.model, ProtectiveFieldOptions{}.self_margin_m);
  ProtectiveField field(ProtectiveFieldOptions{}, scans.model.base_cylinder, scans.model.base_limits);
  std::vector<Eigen::Vector3f> p_WP;
  std::vector<double> ms;
  double kept = 0.0;
  std::size_t i = 0;
  point_cloud_t msg;
  for (auto _ : state) {
    // Untimed: the scan stamped 0.1 s after the one before, the robot's state at that time added.
    state.PauseTiming();
    const std::size_t k = i % scans.messages.size();
    msg = scans.messages[k];
    msg.utime = kT0 + static_cast<std::int64_t>(i++) * 100'000;
    intake.AddState(msg.utime, scans.states[k]);
    state.ResumeTiming();
    const auto t0 = std::chrono::steady_clock::now();
    if (intake.Take(msg, &p_WP)) state.SkipWithError("scan not taken");
    field.SetScan(p_WP, 0.0, Eigen::Vector2d(scans.states[k].x_m, scans.states[k].y_m));
    ms.push_back(MsSince(t0));
    kept += field.num_kept();
  }
  ReportPercentiles(state, ms);
  state.counters["points_kept"] = kept / static_cast<double>(ms.size());
}
BENCHMARK(BM_FieldScanIntake)->Unit(benchmark::kMillisecond);

void BM_FieldCheck(benchmark::State& state) {
  const Scans& scans = TheScans();
  const double speed_mps = 0.01 * static_cast<double>(state.range(0));
  tracker::FieldScanIntake intake(scans.model, ProtectiveFieldOptions{}.self_margin_m);
  std::vector<ProtectiveField> fields;  // one per pose, its scan kept
  std::vector<Eigen::Vector3f> p_WP;
  for (std::size_t k = 0; k < scans.states.size(); ++k) {  // the history keeps 2 s: one pose at a time
    intake.AddState(scans.messages[k].utime, scans.states[k]);
    if (intake.Take(scans.messages[k], &p_WP)) state.SkipWithError("scan not taken");
    fields.emplace_back(ProtectiveFieldOptions{}, scans.model.base_cylinder, scans.model.base_limits);
    fields.back().SetScan(p_WP, 0.0, Eigen::Vector2d(scans.states[k].x_m, scans.states[k].y_m));
  }
  const BaseLimits& limits = scans.model.base_limits;
  const ProtectiveFieldOptions options;
  std::vector<Eigen::Vector2d> path;
  TrajectorySample sample;
  std::vector<double> ms;
  double poses = 0.0;
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = i++ % scans.states.size();
    const WholeBodyState& s = scans.states[k];
    TrackerReference reference;  // straight ahead at the speed
    reference.duration_s = 10.0;
    reference.sampler = [&s, speed_mps](double t_s, TrajectorySample* out) {
      out->state.x_m = s.x_m + speed_mps * t_s * std::cos(s.yaw_rad);
      out->state.y_m = s.y_m + speed_mps * t_s * std::sin(s.yaw_rad);
    };
    const auto t0 = std::chrono::steady_clock::now();
    BasePathAhead(reference, 0.0, fields[k].LengthM(speed_mps), options.step_m / limits.v_max_mps,
                  options.reaction_s + limits.v_max_mps / limits.a_max_mps2 + 1.0, &path, &sample);
    benchmark::DoNotOptimize(fields[k].Check(path, 0.0));
    ms.push_back(MsSince(t0));
    poses += static_cast<double>(path.size());
  }
  ReportPercentiles(state, ms);
  state.counters["path_poses"] = poses / static_cast<double>(ms.size());
}
BENCHMARK(BM_FieldCheck)->Arg(0)->Arg(50)->Arg(100)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
