#include "tools/topay_frontend_bench/front_end_bench_run.h"

#include <iomanip>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/base_band.h"
#include "core/planning/front_end.h"
#include "core/planning/path_verification.h"
#include "core/planning/planner_fields.h"
#include "core/planning/base_reachability.h"
#include "sim/scenes/task_generator.h"

namespace topay::frontend_bench {
namespace {

// The authors' simulation benchmark's yaw-rate limit (rad/s).
constexpr double kBenchmarkOmegaMaxRadps = 1.25;

SceneDistanceFieldsOptions FieldOptions(const FrontEndBenchOptions& o,
                                        const Kinematics& kinematics) {
  SceneDistanceFieldsOptions options = PlannerFieldOptions(kinematics);
  if (o.resolution_m) options.resolution_m = *o.resolution_m;
  if (o.base_resolution_m) options.base_resolution_m = *o.base_resolution_m;
  if (o.band_margin_m) {  // one band, as before the two-band field
    options.base_band = FrontEndBaseBand(kinematics, *o.band_margin_m);
    options.base_upper_band.reset();
  }
  if (o.chassis_band_only) {
    options.base_band = HeightBand{};
    options.base_upper_band.reset();
  }
  return options;
}

std::vector<std::string> ExactFailures(const FrontEndResult& result, const PlanningTask& task,
                                       const Scene& scene, const Kinematics& kinematics) {
  const SceneClearanceChecker checker(kinematics, scene);
  std::vector<std::string> failures;
  for (const FrontEndPath& path : result.paths) {
    const PathVerification check = VerifyWholeBodyPath(path.path, task.start, task.X_WE_goal,
                                                        checker, kinematics, &path.base_sequence);
    if (!check.ok) failures.push_back(check.message);
  }
  return failures;
}

void LogTask(int index, const FrontEndResult& result, const SceneDistanceFields& fields,
             double band_top_m, std::ostream& log) {
  log << "task " << index << ": " << ToString(result.status) << " " << std::fixed
      << std::setprecision(1) << result.stats.total_ms << " ms, " << result.paths.size()
      << " paths, classes " << result.stats.num_classes_kept << ", base band to " << band_top_m
      << " m: " << fields.summary.num_boxes_in_base_band << " boxes"
      << (result.success() ? "" : " -- " + result.failure_reason) << "\n";
  for (const ArmJobReport& job : result.jobs) {
    log << "  job goal " << job.goal_attempt << " path " << job.base_path_index << ": "
        << ToString(job.status) << ", " << job.stats.iterations << " iterations, nodes "
        << job.stats.nodes_start_tree << " + " << job.stats.nodes_goal_tree << ", " << job.wall_ms
        << " ms\n";
  }
}

}  // namespace

FrontEndOptions TaskFrontEndOptions(const FrontEndBenchOptions& o,
                                    const FrontEndOptions& configured, int index,
                                    const Kinematics& kinematics) {
  FrontEndOptions options = configured;
  if (o.threads) options.num_threads = *o.threads;
  options.seed = DeriveSeed(o.seed, 1'000'000 + static_cast<std::uint64_t>(index));
  if (o.jps_only) options.topology.mode = BasePathMode::kJpsOnly;
  if (o.rrt_budget_s) options.rrt.time_budget_s = *o.rrt_budget_s;
  if (o.clearance_m) options.topology.clearance_m = *o.clearance_m;
  if (o.fallback_clearance_m) options.fallback_base_clearance_m = *o.fallback_clearance_m;
  if (o.first_solution) options.rrt.stop_at_first_solution = true;
  if (o.window_s) options.improvement_window_s = *o.window_s;
  BaseLimits limits = options.base_limits.value_or(kinematics.model().base_limits);
  if (o.omega_max_radps) {
    limits.omega_max_radps = *o.omega_max_radps;
  } else if (!options.base_limits) {
    limits.omega_max_radps = kBenchmarkOmegaMaxRadps;
  }
  options.base_limits = limits;
  return options;
}

void RunFrontEndTask(const FrontEndBenchOptions& o, const FrontEndOptions& configured,
                     SceneKind kind, DistanceRange range, int index,
                     const Kinematics& kinematics, FrontEndTally* tally, std::ostream& log) {
  const BenchmarkCase bench_case = GenerateBenchmarkCase(
      kind, range, DeriveSeed(o.seed, static_cast<std::uint64_t>(index)), kinematics);
  const Scene& scene = bench_case.scene.scene;
  const SceneDistanceFieldsOptions field_options = FieldOptions(o, kinematics);
  const SceneDistanceFields fields = BuildSceneDistanceFields(scene, field_options);
  const FrontEnd front_end(kinematics, fields.base_field_2d, fields.field_3d,
                           TaskFrontEndOptions(o, configured, index, kinematics));
  const PlanningTask& task = bench_case.task;
  const FrontEndResult result = front_end.Plan(task.start, task.X_WE_goal, task.goal);

  FrontEndTaskOutcome outcome;
  outcome.index = index;
  outcome.exact_failures = ExactFailures(result, task, scene, kinematics);
  outcome.certified_unreachable =
      CertifyTargetUnreachable(scene, kinematics, {task.start.x_m, task.start.y_m}, task.X_WE_goal)
          .certified_unreachable;
  AddToTally(result, outcome, tally);
  if (o.verbose) LogTask(index, result, fields, field_options.base_band.z_max_m, log);
}

}  // namespace topay::frontend_bench
