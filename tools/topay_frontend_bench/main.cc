// topay-frontend-bench: runs the planner's front end (core/planning/front_end.h) on N generated
// benchmark tasks and prints a Markdown table of its stage timings and success rates.
// Task i uses GenerateBenchmarkCase(scene, range, DeriveSeed(seed, i)); the distance fields
// are built before the front end's clock starts; every returned path is re-checked against
// the exact scene. Logic: front_end_bench_run.h, front_end_tally.h, front_end_report.h.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "core/common/heap_retention.h"
#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_frontend_bench/front_end_bench_run.h"
#include "tools/topay_frontend_bench/front_end_report.h"

namespace {

using topay::frontend_bench::FrontEndBenchOptions;

void AddTaskOptions(CLI::App* app, FrontEndBenchOptions* o) {
  app->add_option("--scene", o->scene, "cuboids | tables")
      ->capture_default_str()
      ->check(CLI::IsMember({"cuboids", "tables"}));
  app->add_option("--range", o->range, "small | medium | large")
      ->capture_default_str()
      ->check(CLI::IsMember({"small", "medium", "large"}));
  app->add_option("--tasks", o->tasks, "Number of tasks")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app->add_option("--seed", o->seed, "Base seed S: task i uses DeriveSeed(S, i)")
      ->capture_default_str()
      ->check(topay::tools::NonNegativeInteger());
  app->add_option("--threads", o->threads,
                  "Front-end threads (0: all cores; default: the YAML's front_end.num_threads)")
      ->check(CLI::NonNegativeNumber);
  app->add_flag("--jps-only", o->jps_only, "The JPS-only ablation (no topological PRM paths)");
  app->add_option("--omega-max", o->omega_max_radps,
                  "Base yaw rate limit (rad/s) for the layer times (default: the YAML's "
                  "planner.base_limits if set, else the simulation benchmark's 1.25)")
      ->check(CLI::PositiveNumber);
  const std::string config = topay::tools::ConfigDir(TOPAY_CONFIG_DIR);
  o->robot_urdf = config + "/robot/topay_mm.urdf";
  o->robot_yaml = config + "/robot/topay_mm.yaml";
  o->planner_config = config + "/planner/topay.yaml";
  app->add_option("--robot", o->robot_urdf, "Robot URDF")->capture_default_str();
  app->add_option("--robot-config", o->robot_yaml, "Robot YAML")->capture_default_str();
  app->add_option("--config", o->planner_config,
                  "Planner YAML (its front_end section); --threads, --jps-only, --omega-max "
                  "and the flags below override it")
      ->capture_default_str();
  app->add_flag("-v,--verbose", o->verbose, "One line per task on stderr");
}

void AddFrontEndOverrides(CLI::App* app, FrontEndBenchOptions* o) {
  app->add_option("--rrt-budget", o->rrt_budget_s,
                  "t_smax of each arm RRT* job (s; default: the YAML's)")
      ->check(CLI::NonNegativeNumber);
  app->add_option("--window", o->window_s,
                  "Improvement window after the first success (s; default: the YAML's)")
      ->check(CLI::NonNegativeNumber);
  app->add_flag("--first-solution", o->first_solution,
                "Arm RRT* stops at its first solution (the reference code), instead of the "
                "paper's anytime improvement");
  app->add_flag("--chassis-band", o->chassis_band_only,
                "Base field from obstacles below the chassis top only (the reference harness)");
  app->add_option("--base-resolution", o->base_resolution_m,
                  "Cell size (m) of the 2D base field (default: the planner's; 0: same as 3D)")
      ->check(CLI::NonNegativeNumber);
  app->add_option("--resolution", o->resolution_m,
                  "Cell size (m) of the 3D field (default: the planner's)")
      ->check(CLI::PositiveNumber);
  app->add_option("--band-margin", o->band_margin_m,
                  "One base band up to the rigid lower body's top plus this margin (m), "
                  "instead of the planner's two bands")
      ->check(CLI::NonNegativeNumber);
  app->add_option("--clearance", o->clearance_m,
                  "Preferred base clearance (m) of the path search (default: the YAML's)")
      ->check(CLI::NonNegativeNumber);
  app->add_option("--fallback-clearance", o->fallback_clearance_m,
                  "Base clearance (m) of the second search when the first finds nothing "
                  "(default: the YAML's)")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace

int main(int argc, char** argv) {
  topay::RetainFreedHeapMemory();  // plans reuse their grids' memory (heap_retention.h)
  CLI::App app{"Benchmark the TopAY front end on generated tasks (Markdown table on stdout)."};
  app.footer(topay::tools::ExitCodesFooter(false));
  FrontEndBenchOptions o;
  AddTaskOptions(&app, &o);
  AddFrontEndOverrides(&app, &o);
  if (const auto code = topay::tools::ParseCommandLine(app, argc, argv, "topay-frontend-bench")) {
    return *code;
  }
  const auto kind = topay::ParseSceneKind(o.scene);
  const auto range = topay::ParseDistanceRange(o.range);
  try {
    const topay::RobotModel model = topay::LoadRobotModel(o.robot_urdf, o.robot_yaml);
    const topay::Kinematics kinematics(model);
    const topay::WholeBodyPlannerOptions loaded = topay::LoadPlannerOptions(o.planner_config);
    topay::FrontEndOptions configured = loaded.front_end;
    if (loaded.base_limits) configured.base_limits = loaded.base_limits;  // as the planner does
    topay::frontend_bench::FrontEndTally tally;
    for (int i = 0; i < o.tasks; ++i) {
      topay::frontend_bench::RunFrontEndTask(o, configured, *kind, *range, i, kinematics, &tally,
                                             std::cerr);
    }
    topay::frontend_bench::WriteFrontEndReport(o, tally, std::cout);
  } catch (const std::exception& e) {
    std::cerr << "topay-frontend-bench: error: " << e.what() << "\n";
    return topay::tools::kExitFileError;
  }
  return topay::tools::kExitSuccess;
}
