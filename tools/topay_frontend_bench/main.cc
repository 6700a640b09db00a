// topay-frontend-bench: runs the planner's front end (core/planning/front_end.h) on N generated
// benchmark tasks and prints a Markdown table of its stage timings and success rates.
// Task i uses GenerateBenchmarkCase(scene, range, DeriveSeed(seed, i)) (scene and task from
// that seed); the distance fields (PlannerFieldOptions by default) are built before the
// clock starts. Every returned path is checked independently against the exact scene
// (core/planning/path_verification.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/common/heap_retention.h"
#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/base_band.h"
#include "core/planning/front_end.h"
#include "core/planning/path_verification.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "sim/scenes/base_reachability.h"
#include "sim/scenes/task_generator.h"

namespace {

struct BenchOptions {
  std::string scene = "cuboids";
  std::string range = "medium";
  int tasks = 20;
  std::uint64_t seed = 1;
  int threads = 0;
  bool jps_only = false;
  double omega_max_radps = 1.25;  // the paper's simulation benchmark (facts sheet)
  std::string robot_urdf;
  std::string robot_yaml;
  std::string planner_config;  // planner YAML: its front_end section sets the options
  bool verbose = false;
  // Front-end knobs: unset = the planner YAML's value.
  std::optional<double> rrt_budget_s;
  std::optional<double> window_s;
  bool first_solution = false;
  bool chassis_band_only = false;
  // Field settings; < 0: PlannerFieldOptions' (3D 0.05 m, 2D 0.02 m, rigid-body band).
  double base_resolution_m = -1.0;
  double resolution_m = -1.0;
  double band_margin_m = -1.0;
  std::optional<double> clearance_m;
  std::optional<double> fallback_clearance_m;
};

// Samples of one metric.
struct Samples {
  std::vector<double> values;
  void Add(double v) { values.push_back(v); }
  double Quantile(double q) const {
    if (values.empty()) return std::nan("");
    std::vector<double> v = values;
    std::sort(v.begin(), v.end());
    // Nearest-rank quantile: the smallest value with at least q of the samples <= it.
    const std::size_t rank = static_cast<std::size_t>(std::ceil(q * v.size()));
    return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
  }
  double Mean() const {
    if (values.empty()) return std::nan("");
    double sum = 0.0;
    for (double v : values) sum += v;
    return sum / values.size();
  }
};

struct Tally {
  int tasks = 0;
  int tasks_ok = 0;
  int unreachable = 0;     // certified unsolvable (sim/scenes/base_reachability.h)
  int unreachable_ok = 0;  // ... yet given a path: must stay 0
  int paths = 0;
  int paths_failing_exact_check = 0;
  int jobs_finished = 0;  // ran to their own end (not cancelled by the window or budget)
  int jobs_succeeded = 0;
  int jobs_cancelled = 0;
  Samples topology_ms, classes, base_paths, rrt_first_ms, total_ms, goal_ms;
  Samples prm_ms, dfs_ms, shortcut_ms, pruning_ms, jps_ms, acquisition_ms;
  int fallback_searches = 0;
  int reachable_goal_searches = 0;
  std::map<std::string, int> statuses;
  std::vector<std::string> exact_failures;
};

std::string ConfigDir() {
  const char* from_env = std::getenv("TOPAY_CONFIG_DIR");
  return from_env != nullptr && *from_env != '\0' ? from_env : TOPAY_CONFIG_DIR;
}

void RunTask(const BenchOptions& o, const topay::FrontEndOptions& configured,
             topay::SceneKind kind, topay::DistanceRange range, int i,
             const topay::Kinematics& kinematics, Tally* tally) {
  using namespace topay;
  const BenchmarkCase bench_case =
      GenerateBenchmarkCase(kind, range, DeriveSeed(o.seed, static_cast<std::uint64_t>(i)),
                            kinematics);
  SceneDistanceFieldsOptions field_options = PlannerFieldOptions(kinematics);
  if (o.resolution_m >= 0.0) field_options.resolution_m = o.resolution_m;
  if (o.base_resolution_m >= 0.0) field_options.base_resolution_m = o.base_resolution_m;
  if (o.band_margin_m >= 0.0) {  // one band, as before the two-band field
    field_options.base_band = FrontEndBaseBand(kinematics, o.band_margin_m);
    field_options.base_upper_band.reset();
  }
  if (o.chassis_band_only) {
    field_options.base_band = HeightBand{};
    field_options.base_upper_band.reset();
  }
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(bench_case.scene.scene, field_options);
  FrontEndOptions options = configured;
  options.num_threads = o.threads;
  options.seed = DeriveSeed(o.seed, 1'000'000 + static_cast<std::uint64_t>(i));
  if (o.jps_only) options.topology.mode = BasePathMode::kJpsOnly;
  if (o.rrt_budget_s) options.rrt.time_budget_s = *o.rrt_budget_s;
  if (o.clearance_m) options.topology.clearance_m = *o.clearance_m;
  if (o.fallback_clearance_m) options.fallback_base_clearance_m = *o.fallback_clearance_m;
  if (o.first_solution) options.rrt.stop_at_first_solution = true;
  if (o.window_s) options.improvement_window_s = *o.window_s;
  BaseLimits limits = kinematics.model().base_limits;
  limits.omega_max_radps = o.omega_max_radps;
  options.base_limits = limits;
  const FrontEnd front_end(kinematics, fields.base_field_2d, fields.field_3d, options);
  const PlanningTask& task = bench_case.task;

  const FrontEndResult result = front_end.Plan(task.start, task.X_WE_goal, task.goal);

  ++tally->tasks;
  ++tally->statuses[std::string(ToString(result.status))];
  tally->total_ms.Add(result.stats.total_ms);
  tally->goal_ms.Add(result.stats.goal_ms);
  if (result.stats.num_goal_attempts > 0) {
    tally->topology_ms.Add(result.stats.topology_ms);
    tally->classes.Add(result.stats.num_classes_kept);
    tally->base_paths.Add(result.stats.num_base_paths);
    tally->prm_ms.Add(result.topology.prm_ms);
    tally->dfs_ms.Add(result.topology.dfs_ms);
    tally->shortcut_ms.Add(result.topology.shortcut_ms);
    tally->pruning_ms.Add(result.topology.pruning_ms);
    tally->jps_ms.Add(result.topology.jps_ms);
    tally->acquisition_ms.Add(result.stats.acquisition_ms);
    tally->fallback_searches += result.stats.used_fallback_base_clearance ? 1 : 0;
    tally->reachable_goal_searches += result.stats.used_reachable_goal_search ? 1 : 0;
  }
  for (const ArmJobReport& job : result.jobs) {
    if (job.status == ArmRrtStarStatus::kCancelled || job.stats.cancelled || !job.started) {
      ++tally->jobs_cancelled;
    }
    if (job.status == ArmRrtStarStatus::kSuccess) {
      ++tally->jobs_succeeded;
      tally->rrt_first_ms.Add(1e3 * job.stats.time_to_first_solution_s);
    }
    if (job.status != ArmRrtStarStatus::kCancelled && job.started) ++tally->jobs_finished;
  }
  const SceneClearanceChecker checker(kinematics, bench_case.scene.scene);
  bool all_exact = true;
  for (const FrontEndPath& path : result.paths) {
    ++tally->paths;
    const PathVerification check = VerifyWholeBodyPath(path.path, task.start, task.X_WE_goal,
                                                        checker, kinematics, &path.base_sequence);
    if (!check.ok) {
      all_exact = false;
      ++tally->paths_failing_exact_check;
      tally->exact_failures.push_back("task " + std::to_string(i) + ": " + check.message);
    }
  }
  if (result.success() && all_exact) ++tally->tasks_ok;
  const bool unreachable =
      CertifyTargetUnreachable(bench_case.scene.scene, kinematics,
                               {task.start.x_m, task.start.y_m}, task.X_WE_goal)
          .certified_unreachable;
  tally->unreachable += unreachable ? 1 : 0;
  tally->unreachable_ok += unreachable && result.success() ? 1 : 0;
  if (o.verbose) {
    std::cerr << "task " << i << ": " << ToString(result.status) << " " << std::fixed
              << std::setprecision(1) << result.stats.total_ms << " ms, " << result.paths.size()
              << " paths, classes " << result.stats.num_classes_kept << ", base band to "
              << field_options.base_band.z_max_m << " m: " << fields.summary.num_boxes_in_base_band
              << " boxes"
              << (result.success() ? "" : " -- " + result.failure_reason) << "\n";
    for (const ArmJobReport& job : result.jobs) {
      std::cerr << "  job goal " << job.goal_attempt << " path " << job.base_path_index << ": "
                << ToString(job.status) << ", " << job.stats.iterations << " iterations, nodes "
                << job.stats.nodes_start_tree << " + " << job.stats.nodes_goal_tree << ", "
                << job.wall_ms << " ms\n";
    }
  }
}

std::string Fmt(double v, int digits = 1) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(digits) << v;
  return out.str();
}

void PrintTable(const BenchOptions& o, const Tally& t) {
  const double share = t.tasks > 0 ? 100.0 * t.tasks_ok / t.tasks : 0.0;
  const int reachable = t.tasks - t.unreachable;
  const double reachable_share =
      reachable > 0 ? 100.0 * (t.tasks_ok - t.unreachable_ok) / reachable : std::nan("");
  const double per_path =
      t.jobs_finished > 0 ? 100.0 * t.jobs_succeeded / t.jobs_finished : std::nan("");
  std::cout << "| scene | range | tasks | topo search ms (median / p95) | classes (mean) | "
               "base paths incl. JPS (mean) | RRT* first solution ms (median / p95) | "
               "RRT* success per path | front end ms (median / p95) | tasks with a path | "
               "reachable tasks with a path |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|\n"
            << "| " << o.scene << (o.jps_only ? " (JPS only)" : "") << " | " << o.range << " | "
            << t.tasks << " | " << Fmt(t.topology_ms.Quantile(0.5)) << " / "
            << Fmt(t.topology_ms.Quantile(0.95)) << " | " << Fmt(t.classes.Mean(), 2) << " | "
            << Fmt(t.base_paths.Mean(), 2) << " | " << Fmt(t.rrt_first_ms.Quantile(0.5)) << " / "
            << Fmt(t.rrt_first_ms.Quantile(0.95)) << " | " << Fmt(per_path) << " % ("
            << t.jobs_succeeded << "/" << t.jobs_finished << ") | "
            << Fmt(t.total_ms.Quantile(0.5)) << " / " << Fmt(t.total_ms.Quantile(0.95)) << " | "
            << Fmt(share) << " % (" << t.tasks_ok << "/" << t.tasks << ") | "
            << Fmt(reachable_share) << " % (" << t.tasks_ok - t.unreachable_ok << "/"
            << t.tasks - t.unreachable << ") |\n\n";
  std::cout << "Reachable: tasks not certified unsolvable by the rigid lower body's connectivity "
               "to the target's reach disc (sim/scenes/base_reachability.h); certified: "
            << t.unreachable << ", of which given a path (must be 0): " << t.unreachable_ok
            << ".\n";
  std::cout << "Goal stage ms (median / p95): " << Fmt(t.goal_ms.Quantile(0.5)) << " / "
            << Fmt(t.goal_ms.Quantile(0.95)) << ". Jobs cancelled by the improvement window or "
            << "budget (not counted in the per-path rate): " << t.jobs_cancelled
            << ". Paths: " << t.paths << ", failing the exact check: "
            << t.paths_failing_exact_check << ". Status counts:";
  for (const auto& [status, count] : t.statuses) std::cout << " " << status << " " << count;
  std::cout << ".\n";
  std::cout << "Stage medians (ms), last search of each task: PRM " << Fmt(t.prm_ms.Quantile(0.5))
            << ", DFS " << Fmt(t.dfs_ms.Quantile(0.5)) << ", shortcut "
            << Fmt(t.shortcut_ms.Quantile(0.5)) << ", UVD " << Fmt(t.pruning_ms.Quantile(0.5))
            << ", JPS " << Fmt(t.jps_ms.Quantile(0.5)) << "; arm stage "
            << Fmt(t.acquisition_ms.Quantile(0.5)) << " (p95 " << Fmt(t.acquisition_ms.Quantile(0.95))
            << "). Tasks needing the fallback base search: " << t.fallback_searches
            << ", the reachable-goal search: " << t.reachable_goal_searches << ".\n";
  for (const std::string& failure : t.exact_failures) std::cout << "  exact check: " << failure << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  topay::RetainFreedHeapMemory();  // plans reuse their grids' memory (heap_retention.h)
  CLI::App app{"Benchmark the TopAY front end on generated tasks (Markdown table on stdout)."};
  BenchOptions o;
  app.add_option("--scene", o.scene, "cuboids | tables")->capture_default_str();
  app.add_option("--range", o.range, "small | medium | large")->capture_default_str();
  app.add_option("--tasks", o.tasks, "Number of tasks")->capture_default_str()->check(
      CLI::PositiveNumber);
  app.add_option("--seed", o.seed, "Base seed S: task i uses DeriveSeed(S, i)")
      ->capture_default_str();
  app.add_option("--threads", o.threads, "Front-end threads (0: all cores)")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  app.add_flag("--jps-only", o.jps_only, "The JPS-only ablation (no topological PRM paths)");
  app.add_option("--omega-max", o.omega_max_radps,
                 "Base yaw rate limit (rad/s) for the layer times (paper benchmark: 1.25)")
      ->capture_default_str();
  const std::string config = ConfigDir();
  o.robot_urdf = config + "/robot/topay_mm.urdf";
  o.robot_yaml = config + "/robot/topay_mm.yaml";
  app.add_option("--robot", o.robot_urdf, "Robot URDF")->capture_default_str();
  app.add_option("--robot-config", o.robot_yaml, "Robot YAML")->capture_default_str();
  o.planner_config = config + "/planner/topay.yaml";
  app.add_option("--config", o.planner_config,
                 "Planner YAML (its front_end section); the flags below override it")
      ->capture_default_str();
  app.add_option("--rrt-budget", o.rrt_budget_s, "t_smax of each arm RRT* job (s; default: the YAML's)")
      ->capture_default_str();
  app.add_option("--window", o.window_s, "Improvement window after the first success (s; default: the YAML's)")
      ->capture_default_str();
  app.add_flag("--first-solution", o.first_solution,
               "Arm RRT* stops at its first solution (the reference code), instead of the "
               "paper's anytime improvement");
  app.add_flag("--chassis-band", o.chassis_band_only,
               "Base field from obstacles below the chassis top only (the reference harness)");
  app.add_option("--base-resolution", o.base_resolution_m,
                 "Cell size (m) of the 2D base field (< 0: the planner's 0.02; 0: same as 3D)")
      ->capture_default_str();
  app.add_option("--resolution", o.resolution_m, "Cell size (m) of the 3D field (< 0: the planner's 0.05)")
      ->capture_default_str();
  app.add_option("--band-margin", o.band_margin_m,
                 "One base band up to the rigid lower body's top plus this margin (m), instead of "
                 "the planner's two bands (< 0: two bands)")
      ->capture_default_str();
  app.add_option("--clearance", o.clearance_m, "Preferred base clearance (m) of the path search")
      ->capture_default_str();
  app.add_option("--fallback-clearance", o.fallback_clearance_m,
                 "Base clearance (m) of the second search when the first finds nothing")
      ->capture_default_str();
  app.add_flag("-v,--verbose", o.verbose, "One line per task on stderr");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "topay-frontend-bench: " << e.what() << "\n(run with --help for usage)\n";
    return 2;
  }
  const auto kind = topay::ParseSceneKind(o.scene);
  const auto range = topay::ParseDistanceRange(o.range);
  if (!kind || !range) {
    std::cerr << "topay-frontend-bench: --scene must be cuboids|tables and --range "
                 "small|medium|large\n";
    return 2;
  }
  try {
    const topay::RobotModel model = topay::LoadRobotModel(o.robot_urdf, o.robot_yaml);
    const topay::Kinematics kinematics(model);
    const topay::FrontEndOptions configured = topay::LoadPlannerOptions(o.planner_config).front_end;
    Tally tally;
    for (int i = 0; i < o.tasks; ++i) RunTask(o, configured, *kind, *range, i, kinematics, &tally);
    PrintTable(o, tally);
  } catch (const std::exception& e) {
    std::cerr << "topay-frontend-bench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
