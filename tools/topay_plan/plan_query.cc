#include "tools/topay_plan/plan_query.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "tools/topay_plan/target_pose.h"
#include "tools/common/usage_error.h"
#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_generator.h"
#include "sim/scenes/task_json.h"

namespace topay::plan {
namespace {

std::string Text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void RequireIn(double value, double lo, double hi, const std::string& option,
               const std::string& unit) {
  if (!(value >= lo && value <= hi)) {
    throw UsageError(option + ": " + Text(value) + unit + " is outside [" + Text(lo) + ", " +
                     Text(hi) + "]" + unit);
  }
}

void RequireFinite(const std::vector<double>& values, const std::string& option) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) {
      throw UsageError(option + ": value " + std::to_string(i + 1) + " (" + Text(values[i]) +
                       ") is not a finite number");
    }
  }
}

void CheckTaskSource(const PlanToolOptions& o) {
  const bool command_line =
      !o.start.empty() || !o.target_rpy.empty() || !o.target_quaternion.empty();
  const int sources =
      (o.range.empty() ? 0 : 1) + (o.task_file.empty() ? 0 : 1) + (command_line ? 1 : 0);
  if (sources != 1) {
    throw UsageError(
        "give exactly one task: --range RANGE, --task-file FILE, or --start and --target (or "
        "--target-quat)");
  }
  if (!command_line) return;
  if (o.start.empty()) throw UsageError("--target/--target-quat: also give --start");
  if (o.target_rpy.empty() == o.target_quaternion.empty()) {
    throw UsageError(
        "--start: give exactly one of --target X Y Z ROLL PITCH YAW and "
        "--target-quat X Y Z QW QX QY QZ");
  }
  if (!o.target_rpy.empty() && o.target_rpy.size() != 6) {
    throw UsageError("--target: expected 6 numbers (x y z roll pitch yaw), got " +
                     std::to_string(o.target_rpy.size()));
  }
  if (!o.target_quaternion.empty() && o.target_quaternion.size() != 7) {
    throw UsageError("--target-quat: expected 7 numbers (x y z qw qx qy qz), got " +
                     std::to_string(o.target_quaternion.size()));
  }
  RequireFinite(o.start, "--start");
  RequireFinite(o.target_rpy, "--target");
  RequireFinite(o.target_quaternion, "--target-quat");
  if (o.use_goal_hint) {
    throw UsageError("--use-goal-hint: a command-line task has no goal state to use as hint");
  }
}

void CheckOutputFolder(const std::string& path, const std::string& option) {
  if (path.empty()) return;
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code error;
  if (!parent.empty() && !std::filesystem::is_directory(parent, error)) {
    throw std::runtime_error(option + ": cannot write '" + path + "': folder '" + parent.string() +
                             "' does not exist");
  }
}

WholeBodyState StartFromCommandLine(const std::vector<double>& v, int num_joints) {
  if (static_cast<int>(v.size()) != 3 + num_joints) {
    throw UsageError("--start: expected " + std::to_string(3 + num_joints) +
                     " numbers (x y yaw and " + std::to_string(num_joints) +
                     " joint angles), got " + std::to_string(v.size()));
  }
  return WholeBodyState::FromVector(Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()));
}

Eigen::Isometry3d TargetFromCommandLine(const PlanToolOptions& o) {
  if (!o.target_rpy.empty()) {
    const std::vector<double>& v = o.target_rpy;
    return PoseFromXyzRpy({v[0], v[1], v[2]}, v[3], v[4], v[5]);
  }
  const std::vector<double>& v = o.target_quaternion;
  try {
    return PoseFromXyzQuaternion({v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]});
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--target-quat: ") + e.what());
  }
}

DistanceRange RangeOf(const std::string& name) {
  const std::optional<DistanceRange> range = ParseDistanceRange(name);
  if (!range) {
    throw UsageError("--range: unknown range '" + name + "' (small, medium or large)");
  }
  return *range;
}

SceneKind KindOf(const std::string& name) {
  const std::optional<SceneKind> kind = ParseSceneKind(name);
  if (!kind) throw UsageError("--scene: unknown kind '" + name + "' (cuboids or tables)");
  return *kind;
}

void TakeTask(const PlanningTask& task, const std::string& source, PlanQuery* query) {
  query->start = task.start;
  query->X_WE_goal = task.X_WE_goal;
  query->goal_state = task.goal;
  query->task_source = source;
  query->task_range = std::string(DistanceRangeName(task.range));
  query->task_seed = task.seed;
}

}  // namespace

void CheckPlanToolOptions(const PlanToolOptions& o) {
  if (o.scene_kind.empty() == o.scene_file.empty()) {
    throw UsageError("give exactly one of --scene KIND and --scene-file FILE");
  }
  if (!o.scene_kind.empty()) KindOf(o.scene_kind);
  if (!o.range.empty()) RangeOf(o.range);
  CheckTaskSource(o);
  if (!o.base_limits.empty() && !ParseBaseLimitChoice(o.base_limits)) {
    throw UsageError("--base-limits: unknown choice '" + o.base_limits +
                     "' (benchmark, robot or config)");
  }
  const PlannerOverrides& p = o.overrides;
  if (p.num_threads) RequireIn(*p.num_threads, 0, 256, "--threads", "");
  if (p.time_limit_s) RequireIn(*p.time_limit_s, 0.01, 600.0, "--time-limit", " s");
  if (p.optimizer_time_limit_s) {
    RequireIn(*p.optimizer_time_limit_s, 0.01, 600.0, "--optimizer-time-limit", " s");
  }
  if (p.acquisition_budget_s) {
    RequireIn(*p.acquisition_budget_s, 0.01, 600.0, "--acquisition-budget", " s");
  }
  RequireIn(o.px_per_m, 1.0, 400.0, "--px-per-m", "");
  RequireIn(o.footprint_interval_s, 0.05, 100.0, "--footprint-interval", " s");
  RequireIn(o.sample_period_s, 0.001, 1.0, "--sample-period", " s");
}

void CheckOutputFolders(const PlanToolOptions& o) {
  CheckOutputFolder(o.trajectory_json_out, "--json");
  CheckOutputFolder(o.path_png_out, "--png");
  CheckOutputFolder(o.time_png_out, "--time-png");
}

PlanQuery ResolvePlanQuery(const PlanToolOptions& o, const Kinematics& kinematics) {
  PlanQuery query;
  std::optional<PlanningTask> task;
  if (!o.scene_kind.empty()) {
    const SceneKind kind = KindOf(o.scene_kind);
    if (!o.range.empty()) {
      BenchmarkCase generated = GenerateBenchmarkCase(kind, RangeOf(o.range), o.seed, kinematics);
      query.scene = std::move(generated.scene.scene);
      task = std::move(generated.task);
    } else {
      query.scene = GenerateBenchmarkScene(kind, o.seed).scene;
    }
    query.scene_source = "generated from --seed " + std::to_string(o.seed);
  } else {
    query.scene = ReadSceneJson(o.scene_file);
    query.scene_source = o.scene_file;
    if (!o.range.empty()) {
      task = GenerateTask(query.scene, RangeOf(o.range), o.seed, kinematics);
    }
  }
  if (task) {
    TakeTask(*task, "generated", &query);
  } else if (!o.task_file.empty()) {
    TakeTask(ReadTaskJson(o.task_file, kinematics.num_joints()), "task file " + o.task_file,
             &query);
  } else {
    query.start = StartFromCommandLine(o.start, kinematics.num_joints());
    query.X_WE_goal = TargetFromCommandLine(o);
    query.task_source = "command line";
  }
  return query;
}

}  // namespace topay::plan
