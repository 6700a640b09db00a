#include "tools/topay_bench/bench_cli.h"

#include "tools/common/tool_cli.h"
#include "tools/common/usage_error.h"

namespace topay::bench {
namespace {

void AddTaskFlags(CLI::App* app, BenchOptions* o) {
  app->add_option("--scene", o->scene, "Scene kind: cuboids | tables")->capture_default_str();
  app->add_option("--range", o->range, "Task range: small | medium | large")->capture_default_str();
  app->add_flag("--tight", o->tight,
                "Tight tasks: no keep-out zones; start and goal exactly collision free with "
                "their closest body within 5 cm of a box (Tables: half the goals with the end "
                "effector on or under a table top); the cell is '<scene> <range> tight'");
  app->add_option("--tasks", o->num_tasks, "Number of tasks N")->capture_default_str();
  app->add_option("--seed", o->seed, "Base seed S (task i: DeriveSeed(S, i))")
      ->capture_default_str()
      ->check(tools::NonNegativeInteger());
}

void AddMethodFlags(CLI::App* app, BenchCommandLine* line) {
  BenchOptions* o = &line->options;
  auto* one = app->add_option("--method", line->method,
                              "One method: topay | jps-only | sequential | flatness (default "
                              "topay)");
  auto* many = app->add_option("--compare", line->compare,
                               "Several methods on identical tasks, e.g. topay,flatness");
  one->excludes(many);
  // Unset flags leave the planner YAML's values (tools/topay_plan/planner_overrides.h).
  app->add_option("--threads", o->num_threads,
                  "Planner workers (0: all cores; 1: deterministic; default: the YAML's "
                  "planner.num_threads)");
  app->add_option("--time-limit-ms", o->time_limit_ms,
                  "Per-task planning time limit (ms; default: the YAML's planner.time_limit_s)");
  app->add_option("--base-limits", o->base_limits,
                  "Base limits: benchmark (paper's simulation) | robot (robot config) | config "
                  "(the planner YAML's); default: the YAML's if it sets them, else benchmark");
  app->add_flag("--use-hint,!--no-hint", o->use_hint,
                "Pass the task's generating goal state as the planner's hint (default on)");
}

void AddFileFlags(const std::string& config_dir, CLI::App* app, BenchOptions* o) {
  o->planner_config = config_dir + "/planner/topay.yaml";
  o->robot_urdf = config_dir + "/robot/topay_mm.urdf";
  o->robot_yaml = config_dir + "/robot/topay_mm.yaml";
  app->add_option("--config", o->planner_config, "Planner options YAML")->capture_default_str();
  app->add_option("--robot", o->robot_urdf, "Robot URDF")->capture_default_str();
  app->add_option("--robot-config", o->robot_yaml, "Robot YAML")->capture_default_str();
  app->add_option("--out", o->out_dir, "Output folder (created)")->required();
  o->mapper_config = config_dir + "/mapper/mapper.yaml";
  o->lidar_config = config_dir + "/sim/lidar.yaml";
  app->add_option("--sensed-map", o->sensed_map,
                  "Also plan on each task's scene as the simulated LiDAR maps it from a tour: "
                  "line (start to goal) | tour (line + a grid over the room); methods <m>@sensed");
  app->add_option("--sensed-unknown", o->sensed_unknown,
                  "Never-seen voxels of sensed maps: free | occupied")->capture_default_str();
  app->add_option("--sensed-margin-m", o->sensed_margin_m,
                  "The planner's extra obstacle margin on sensed maps (m)")->capture_default_str();
  app->add_option("--mapper-config", o->mapper_config, "Mapper YAML (scan filter, map), for sensed maps")
      ->capture_default_str();
  app->add_option("--lidar-config", o->lidar_config, "LiDAR YAML (the simulator's), for sensed maps")
      ->capture_default_str();
  app->add_flag("--dump-trajectories", o->dump_trajectories,
                "Also write each task's scene, task and trajectory JSON");
}

}  // namespace

void AddBenchFlags(const std::string& config_dir, CLI::App* app, BenchCommandLine* line) {
  AddTaskFlags(app, &line->options);
  AddMethodFlags(app, line);
  AddFileFlags(config_dir, app, &line->options);
}

void FinishBenchCommandLine(BenchCommandLine* line) {
  if (line->method.find(',') != std::string::npos) {
    throw plan::UsageError("--method: one method only; use --compare " + line->method +
                           " for several");
  }
  if (!line->method.empty()) line->options.methods = ParseMethodList(line->method, "--method");
  if (!line->compare.empty()) line->options.methods = ParseMethodList(line->compare, "--compare");
}

}  // namespace topay::bench
