// topay-bench: the benchmark harness. Runs N generated benchmark tasks (a fresh scene per
// task) with one planner method or several on identical tasks, and writes tasks.jsonl (one
// line per task and method), summary.json (one object per method) and, with
// --dump-trajectories, each task's scene, task and trajectory JSON. Prints a Markdown table;
// a progress bar on stderr when stderr is a terminal. Logic: tools/topay_bench/bench_run.h.
// Exit codes: 0 ran (whatever the success rate), 1 a file error, 2 a usage error.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "core/common/heap_retention.h"
#include "core/common/stopwatch.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_bench/bench_run.h"
#include "tools/topay_bench/progress_line.h"
#include "tools/common/usage_error.h"

namespace {

namespace bench = topay::bench;

void AddTaskOptions(CLI::App* app, bench::BenchOptions* o) {
  app->add_option("--scene", o->scene, "Scene kind: cuboids | tables")->capture_default_str();
  app->add_option("--range", o->range, "Task range: small | medium | large")->capture_default_str();
  app->add_option("--tasks", o->num_tasks, "Number of tasks N")->capture_default_str();
  app->add_option("--seed", o->seed, "Base seed S (task i: DeriveSeed(S, i))")
      ->capture_default_str()
      ->check(topay::tools::NonNegativeInteger());
}

void AddMethodOptions(CLI::App* app, bench::BenchOptions* o, std::string* method,
                      std::string* compare) {
  auto* one = app->add_option("--method", *method,
                              "One method: topay | jps-only | sequential | flatness (default "
                              "topay)");
  auto* many = app->add_option("--compare", *compare,
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

void AddFileOptions(CLI::App* app, bench::BenchOptions* o) {
  const std::string config = topay::tools::ConfigDir(TOPAY_CONFIG_DIR);
  o->planner_config = config + "/planner/topay.yaml";
  o->robot_urdf = config + "/robot/topay_mm.urdf";
  o->robot_yaml = config + "/robot/topay_mm.yaml";
  app->add_option("--config", o->planner_config, "Planner options YAML")->capture_default_str();
  app->add_option("--robot", o->robot_urdf, "Robot URDF")->capture_default_str();
  app->add_option("--robot-config", o->robot_yaml, "Robot YAML")->capture_default_str();
  app->add_option("--out", o->out_dir, "Output folder (created)")->required();
  app->add_flag("--dump-trajectories", o->dump_trajectories,
                "Also write each task's scene, task and trajectory JSON");
}

bench::BenchProgress TerminalProgress() {
  if (::isatty(STDERR_FILENO) == 0) return {};
  const topay::Stopwatch watch;
  return [watch](int done, int total) {
    const double elapsed_s = watch.ElapsedS();
    std::cerr << "\r" << bench::ProgressLine(done, total, elapsed_s) << (done == total ? "\n" : "")
              << std::flush;
  };
}

int Usage(const std::string& message) {
  std::cerr << "topay-bench: " << message << "\n(run with --help for usage)\n";
  return bench::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
  topay::RetainFreedHeapMemory();  // plans reuse their grids' memory (heap_retention.h)
  CLI::App app{"Benchmark TopAY (and its baselines) on N generated tasks."};
  bench::BenchOptions options;
  std::string method;
  std::string compare;
  AddTaskOptions(&app, &options);
  AddMethodOptions(&app, &options, &method, &compare);
  AddFileOptions(&app, &options);
  app.footer(topay::tools::ExitCodesFooter(false) +
             " A run exits 0 whatever its success rate.");
  try {
    app.parse(argc, argv);
    if (method.find(',') != std::string::npos) {
      return Usage("--method: one method only; use --compare " + method + " for several");
    }
    if (!method.empty()) options.methods = bench::ParseMethodList(method, "--method");
    if (!compare.empty()) options.methods = bench::ParseMethodList(compare, "--compare");
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return Usage(e.what());
  } catch (const topay::plan::UsageError& e) {
    return Usage(e.what());
  }
  try {
    const bench::BenchReport report = bench::RunBench(options, TerminalProgress());
    std::cout << report.Markdown();
    std::cout << "Wrote " << report.tasks_jsonl << " and " << report.summary_json << "\n";
    return bench::kExitRan;
  } catch (const topay::plan::UsageError& e) {
    return Usage(e.what());
  } catch (const std::exception& e) {
    std::cerr << "topay-bench: error: " << e.what() << "\n";
    return bench::kExitError;
  }
}

