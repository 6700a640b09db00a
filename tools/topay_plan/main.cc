// topay-plan: one planning query on a scene (generated or from a JSON file) and a task
// (generated, from a JSON file, or a start state and an end-effector target given here).
// Prints a summary, writes the trajectory JSON and PNG plots. Logic: tools/topay_plan/plan_tool.h.
// Exit codes: 0 a validated trajectory, 1 an error (file, output), 2 a usage error, 3 the
// planner found no validated trajectory (the reason is printed).
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "core/common/heap_retention.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_plan/plan_tool.h"
#include "tools/common/usage_error.h"

namespace {

void AddInputOptions(CLI::App* app, topay::plan::PlanToolOptions* o) {
  auto* kind = app->add_option("--scene", o->scene_kind, "Generate a scene: cuboids | tables");
  auto* file = app->add_option("--scene-file", o->scene_file, "Load a scene JSON instead");
  kind->excludes(file);
  app->add_option("--seed", o->seed, "Seed of the generated scene and task")
      ->capture_default_str()
      ->check(topay::tools::NonNegativeInteger());
  auto* range = app->add_option("--range", o->range, "Generate a task: small | medium | large");
  auto* task = app->add_option("--task-file", o->task_file, "Load a task JSON instead");
  range->excludes(task);
  app->add_option("--start", o->start, "Start state: X Y YAW Q1..QN (m, rad)")
      ->expected(1, 64)
      ->allow_extra_args(false);
  auto* rpy = app->add_option("--target", o->target_rpy,
                              "End-effector target: X Y Z ROLL PITCH YAW (m, rad; fixed axes, "
                              "R = Rz(yaw) Ry(pitch) Rx(roll))")
                  ->expected(1, 16)
                  ->allow_extra_args(false);
  auto* quat = app->add_option("--target-quat", o->target_quaternion,
                               "End-effector target: X Y Z QW QX QY QZ (m; unit quaternion)")
                   ->expected(1, 16)
                   ->allow_extra_args(false);
  rpy->excludes(quat);
  app->add_flag("--use-goal-hint", o->use_goal_hint,
                "Give a generated or loaded task's goal state to the planner as a hint");
}

void AddPlanAndOutputOptions(CLI::App* app, topay::plan::PlanToolOptions* o,
                             bool* sequential_flag) {
  app->add_option("--json", o->trajectory_json_out, "Write the trajectory JSON here");
  app->add_option("--png", o->path_png_out, "Write the top-down path PNG here");
  app->add_option("--time-png", o->time_png_out, "Write the time plots PNG here");
  // Planner settings: unset flags leave the planner YAML's values (precedence: defaults, YAML,
  // flags; tools/topay_plan/planner_overrides.h).
  app->add_option("--threads", o->overrides.num_threads,
                  "Front-end and optimization workers (0: all cores; default: the YAML's "
                  "planner.num_threads and front_end.num_threads)");
  app->add_option("--time-limit", o->overrides.time_limit_s,
                  "Bound on the whole plan (s; default: the YAML's planner.time_limit_s)");
  app->add_flag("--sequential", *sequential_flag,
                "Optimize candidates one after another (default: the YAML's planner.sequential)");
  app->add_option("--optimizer-time-limit", o->overrides.optimizer_time_limit_s,
                  "Bound on one candidate's optimization (s; default: the YAML's "
                  "optimizer.time_limit_s)");
  app->add_option("--acquisition-budget", o->overrides.acquisition_budget_s,
                  "Bound on the front end's arm search (s; default: the YAML's "
                  "front_end.acquisition_budget_s)");
  app->add_option("--base-limits", o->base_limits,
                  "Base limits: benchmark (paper's simulation, omega_max 1.25) | robot (robot "
                  "config) | config (the planner YAML's planner.base_limits); default: the "
                  "YAML's if it sets them, else benchmark");
  app->add_option("--px-per-m", o->px_per_m, "Top-down PNG scale")->capture_default_str();
  app->add_option("--footprint-interval", o->footprint_interval_s,
                  "Time between drawn footprints (s)")
      ->capture_default_str();
  app->add_option("--sample-period", o->sample_period_s, "JSON and plot sample period (s)")
      ->capture_default_str();
  const std::string config = topay::tools::ConfigDir(TOPAY_CONFIG_DIR);
  o->robot_urdf = config + "/robot/topay_mm.urdf";
  o->robot_yaml = config + "/robot/topay_mm.yaml";
  app->add_option("--robot", o->robot_urdf, "Robot URDF")->capture_default_str();
  app->add_option("--robot-config", o->robot_yaml, "Robot YAML")->capture_default_str();
  o->planner_config = config + "/planner/topay.yaml";
  app->add_option("--config", o->planner_config,
                  "Planner YAML (the flags above override it; \"\" for the built-in defaults)")
      ->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  topay::RetainFreedHeapMemory();  // plans reuse their grids' memory (heap_retention.h)
  namespace plan = topay::plan;
  CLI::App app{"Plan one TopAY whole-body query and write its summary, trajectory and plots."};
  plan::PlanToolOptions options;
  AddInputOptions(&app, &options);
  bool sequential = false;
  AddPlanAndOutputOptions(&app, &options, &sequential);
  app.footer(topay::tools::ExitCodesFooter(true));
  if (const auto code = topay::tools::ParseCommandLine(app, argc, argv, "topay-plan")) {
    return *code;
  }
  if (sequential) options.overrides.sequential = true;
  try {
    const plan::PlanToolSummary summary = plan::RunPlanTool(options);
    std::cout << summary.Report();
    return summary.ExitCode();
  } catch (const plan::UsageError& e) {
    std::cerr << "topay-plan: " << e.what() << "\n(run with --help for usage)\n";
    return plan::kExitUsage;
  } catch (const std::exception& e) {
    std::cerr << "topay-plan: error: " << e.what() << "\n";
    return plan::kExitError;
  }
}

