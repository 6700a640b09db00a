// The back end's trajectory optimization (issue 4, items 3-4). Commands and results:
// docs/benchmarks.md. Release build with benchmarks:
//   cmake -S . -B build-optim-rel -G Ninja -DCMAKE_BUILD_TYPE=Release
//   cmake --build build-optim-rel --target trajectory_objective_bench
//   build-optim-rel/bin/trajectory_objective_bench --benchmark_repetitions=20
//       --benchmark_report_aggregates_only=true --benchmark_filter=Evaluate   (one line)
//   TOPAY_OPTIM_BENCH_TASKS=100 build-optim-rel/bin/trajectory_objective_bench
//       --benchmark_filter=FrontEndPaths                                     (one line)
// The robot is read from config/robot/ of the source tree this file is in (or of
// $TOPAY_SOURCE_DIR if set).
//  - BM_ObjectiveEvaluate: one evaluation of the stage-2 objective (every term) with its
//    gradient, M = 10 pieces, K = 12, at the warm start of a front-end path in a Cuboids room
//    (penalties active as they are at the start of an optimization), and without gradient;
//  - BM_OptimizerOnFrontEndPaths: for generated tasks (GenerateBenchmarkCase, seeds
//    DeriveSeed(1, i)), the front end's shortest path, then TrajectoryOptimizer on it alone:
//    its success, the independent validator's verdict (core/validate, exact boxes, 10 ms),
//    L-BFGS iterations and time per optimization (one thread). Per-task lines on stderr.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/optimization/trajectory_objective.h"
#include "core/optimization/trajectory_optimizer.h"
#include "core/optimization/warm_start.h"
#include "core/planning/front_end.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/arc_yaw_sampling.h"
#include "core/validate/trajectory_validator.h"
#include "sim/scenes/task_generator.h"

namespace topay {
namespace {

BaseLimits BenchmarkLimits(const RobotModel& model) {
  BaseLimits limits = model.base_limits;
  limits.omega_max_radps = 1.25;  // the paper's simulation benchmark (the authors' code)
  return limits;
}

std::string SourceDir() {
  if (const char* env = std::getenv("TOPAY_SOURCE_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  const std::string file = __FILE__;  // <root>/tests/bench/trajectory_objective_bench.cc
  return file.substr(0, file.rfind("/tests/bench/"));
}

const RobotModel& Model() {
  static const RobotModel model = LoadRobotModel(SourceDir() + "/config/robot/topay_mm.urdf",
                                                 SourceDir() + "/config/robot/topay_mm.yaml");
  return model;
}

double Percentile(std::vector<double> values, double p) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t rank = static_cast<std::size_t>(std::ceil(p * values.size()));
  return values[std::max<std::size_t>(rank, 1) - 1];
}

/// One generated task with its fields and the front end's result.
struct PlannedCase {
  BenchmarkCase bench_case;
  SceneDistanceFields fields;
  FrontEndResult front_end;
};

PlannedCase PlanCase(const Kinematics& kinematics, SceneKind kind, DistanceRange range,
                     std::uint64_t seed) {
  BenchmarkCase bench_case = GenerateBenchmarkCase(kind, range, seed, kinematics);
  SceneDistanceFields fields =
      BuildSceneDistanceFields(bench_case.scene.scene, PlannerFieldOptions(kinematics));
  FrontEndOptions options;
  options.base_limits = BenchmarkLimits(kinematics.model());
  options.seed = DeriveSeed(seed, 7);
  const FrontEnd front_end(kinematics, fields.base_field_2d, fields.field_3d, options);
  FrontEndResult result =
      front_end.Plan(bench_case.task.start, bench_case.task.X_WE_goal, bench_case.task.goal);
  return {std::move(bench_case), std::move(fields), std::move(result)};
}

// The objective with gradient, M = 10, K = 12, at the warm start of a front-end path.
void BM_ObjectiveEvaluate(benchmark::State& state) {
  const bool with_gradient = state.range(0) != 0;
  const Kinematics kinematics(Model());
  // The first seed whose task has a front-end path.
  std::optional<PlannedCase> planned;
  for (std::uint64_t i = 0; i < 20 && !planned; ++i) {
    PlannedCase c = PlanCase(kinematics, SceneKind::kCuboids, DistanceRange::kMedium,
                             DeriveSeed(1, i));
    if (c.front_end.success()) planned.emplace(std::move(c));
  }
  if (!planned) {
    state.SkipWithError("no front-end path in 20 tasks");
    return;
  }
  const PlanningTask& task = planned->bench_case.task;
  const BaseLimits limits = BenchmarkLimits(kinematics.model());
  WarmStartOptions warm_options;
  warm_options.min_pieces = warm_options.max_pieces = 10;  // M = 10
  const TrajectoryObjectiveOptions objective_options;    // K = 12, stage 2's weights
  const WarmStart warm =
      MakeWarmStart(planned->front_end.paths.front().path, task.start, limits,
                    kinematics.model().joint_limits, objective_options.panels_per_piece,
                    warm_options);
  TrajectoryObjective objective(kinematics, planned->fields.base_field_2d,
                                planned->fields.field_3d, limits, task.start, task.X_WE_goal,
                                warm.num_pieces, objective_options);
  const Eigen::VectorXd x = objective.Pack(warm.durations_s, warm.waypoints, warm.end);
  Eigen::VectorXd gradient(objective.num_parameters());
  double cost = 0.0;
  for (auto _ : state) {
    objective.Evaluate(x.data(), &cost, with_gradient ? gradient.data() : nullptr);
    benchmark::DoNotOptimize(cost);
    benchmark::DoNotOptimize(gradient.data());
  }
  state.counters["pieces"] = objective.num_pieces();
  state.counters["parameters"] = objective.num_parameters();
}
BENCHMARK(BM_ObjectiveEvaluate)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

double EnvDouble(const char* name, double fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::atof(value) : fallback;
}

// Optimizer options, with knobs for experiments from the environment:
// TOPAY_OPTIM_TIME_LIMIT (s), TOPAY_OPTIM_STAGE1_ITERATIONS, TOPAY_OPTIM_RHO0,
// TOPAY_OPTIM_DELTA (relative decrease), TOPAY_OPTIM_MEMORY, TOPAY_OPTIM_EIGEN_SCALING (0/1).
TrajectoryOptimizerOptions BenchOptimizerOptions() {
  TrajectoryOptimizerOptions o;
  o.time_limit_s = EnvDouble("TOPAY_OPTIM_TIME_LIMIT", o.time_limit_s);
  o.stage1_max_iterations =
      static_cast<int>(EnvDouble("TOPAY_OPTIM_STAGE1_ITERATIONS", o.stage1_max_iterations));
  o.alm.rho_initial = EnvDouble("TOPAY_OPTIM_RHO0", o.alm.rho_initial);
  o.lbfgs.relative_decrease_delta = EnvDouble("TOPAY_OPTIM_DELTA", o.lbfgs.relative_decrease_delta);
  o.lbfgs.memory = static_cast<int>(EnvDouble("TOPAY_OPTIM_MEMORY", o.lbfgs.memory));
  o.lbfgs.approximate_eigenvalue_scaling =
      EnvDouble("TOPAY_OPTIM_EIGEN_SCALING", o.lbfgs.approximate_eigenvalue_scaling) != 0.0;
  return o;
}

// The optimizer alone on front-end paths (see the file comment).
void BM_OptimizerOnFrontEndPaths(benchmark::State& state) {
  const SceneKind kind = state.range(0) == 0 ? SceneKind::kCuboids : SceneKind::kTables;
  const DistanceRange range = static_cast<DistanceRange>(state.range(1));
  const char* env = std::getenv("TOPAY_OPTIM_BENCH_TASKS");
  const int num_tasks = env ? std::max(1, std::atoi(env)) : 20;
  const Kinematics kinematics(Model());
  const BaseLimits limits = BenchmarkLimits(kinematics.model());
  int with_path = 0, optimizer_success = 0, validated = 0, validated_of_success = 0;
  std::vector<double> times_ms, iterations, durations_s;
  for (auto _ : state) {
    for (int i = 0; i < num_tasks; ++i) {
      const PlannedCase c = PlanCase(kinematics, kind, range, DeriveSeed(1, i));
      if (!c.front_end.success()) continue;
      ++with_path;
      const PlanningTask& task = c.bench_case.task;
      const TrajectoryOptimizer optimizer(kinematics, c.fields.base_field_2d, c.fields.field_3d,
                                          BenchOptimizerOptions());
      TrajectoryProblem problem;
      problem.start = task.start;
      problem.X_WE_goal = task.X_WE_goal;
      problem.base_limits = limits;
      const BackEndSummary summary =
          optimizer.Optimize(problem, c.front_end.paths.front().path);
      times_ms.push_back(1e3 * summary.total_s);
      iterations.push_back(summary.inner_iterations());
      bool valid = false;
      std::string verdict = "-";
      if (summary.num_pieces > 0) {
        const ArcYawTrajectory trajectory = summary.MakeTrajectory();
        const TrajectoryValidator validator(kinematics, c.bench_case.scene.scene, limits);
        const ValidationReport report =
            validator.Validate(SampleArcYaw(trajectory), task.start, task.X_WE_goal);
        valid = report.ok;
        verdict = report.ok ? "valid" : report.first_failure.message;
      }
      if (summary.success()) {
        ++optimizer_success;
        durations_s.push_back(summary.duration_s);
        validated_of_success += valid;
      }
      validated += valid;
      std::fprintf(stderr,
                   "task %2d: %-13s %7.1f ms %5d it (%d+%d, %d outer) %5d ev M %2d T %5.1f s | "
                   "%s | %s\n",
                   i, std::string(ToString(summary.status)).c_str(), 1e3 * summary.total_s,
                   summary.inner_iterations(), summary.stage1_iterations,
                   summary.stage2_iterations, summary.outer_iterations,
                   summary.objective_evaluations, summary.num_pieces,
                   summary.duration_s, summary.reason.c_str(), verdict.c_str());
    }
  }
  state.counters["tasks"] = num_tasks;
  state.counters["with_path"] = with_path;
  state.counters["opt_success_pct"] = with_path ? 100.0 * optimizer_success / with_path : 0.0;
  state.counters["validated_pct"] = with_path ? 100.0 * validated / with_path : 0.0;
  state.counters["valid_of_success_pct"] =
      optimizer_success ? 100.0 * validated_of_success / optimizer_success : 0.0;
  state.counters["time_ms_median"] = Percentile(times_ms, 0.5);
  state.counters["time_ms_p95"] = Percentile(times_ms, 0.95);
  state.counters["iterations_median"] = Percentile(iterations, 0.5);
  state.counters["iterations_p95"] = Percentile(iterations, 0.95);
  state.counters["traj_duration_s_mean"] =
      durations_s.empty() ? 0.0
                          : [&] {
                              double sum = 0.0;
                              for (double d : durations_s) sum += d;
                              return sum / durations_s.size();
                            }();
}
BENCHMARK(BM_OptimizerOnFrontEndPaths)
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace topay

BENCHMARK_MAIN();
