#include "sim/bench/bench_run.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "sim/bench/bench_record_json.h"
#include "sim/bench/bench_task.h"

namespace topay::bench {
namespace {

void CreateOutputFolder(const std::string& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (!std::filesystem::is_directory(dir)) {
    throw std::runtime_error("--out: cannot create the folder '" + dir + "'" +
                             (error ? ": " + error.message() : ""));
  }
}

void WriteText(const std::string& path, const std::string& text) {
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw std::runtime_error("cannot write '" + path + "'");
}

BenchRunInfo RunInfo(const BenchOptions& o) {
  BenchRunInfo info;
  info.scene = o.scene;
  info.range = o.range;
  info.seed = o.seed;
  info.threads = o.num_threads > 0
                     ? o.num_threads
                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  info.time_limit_ms = o.time_limit_ms;
  info.use_hint = o.use_hint;
  info.base_limits = o.base_limits;
  info.planner_config = o.planner_config;
  return info;
}

}  // namespace

std::string BenchReport::Markdown() const { return SummaryMarkdown(summaries, info); }

BenchReport RunBench(const BenchOptions& options, const BenchProgress& progress) {
  CheckBenchOptions(options);
  const RobotModel model = LoadRobotModel(options.robot_urdf, options.robot_yaml);
  const Kinematics kinematics(model);
  const WholeBodyPlannerOptions loaded = LoadPlannerOptions(options.planner_config);
  CreateOutputFolder(options.out_dir);

  BenchTaskContext context;
  context.kinematics = &kinematics;
  context.loaded_options = &loaded;
  context.limit_choice = *plan::ParseBaseLimitChoice(options.base_limits);
  context.settings.base_limits = plan::ChooseBaseLimits(context.limit_choice, model);
  context.settings.num_threads = options.num_threads;
  context.settings.time_limit_ms = options.time_limit_ms;
  context.kind = *ParseSceneKind(options.scene);
  context.range = *ParseDistanceRange(options.range);
  context.seed = options.seed;
  context.methods = MethodsOf(options);
  context.use_hint = options.use_hint;
  if (options.dump_trajectories) context.dump_dir = options.out_dir;

  BenchReport report;
  report.info = RunInfo(options);
  report.tasks_jsonl = options.out_dir + "/tasks.jsonl";
  report.summary_json = options.out_dir + "/summary.json";
  std::ofstream lines(report.tasks_jsonl, std::ios::binary | std::ios::trunc);
  if (!lines) throw std::runtime_error("cannot write '" + report.tasks_jsonl + "'");
  for (int i = 0; i < options.num_tasks; ++i) {
    for (BenchRecord& record : RunBenchTask(context, i)) {
      lines << RecordJsonLine(record) << "\n";
      report.records.push_back(std::move(record));
    }
    lines.flush();
    if (!lines) throw std::runtime_error("cannot write '" + report.tasks_jsonl + "'");
    if (progress) progress(i + 1, options.num_tasks);
  }
  report.summaries = SummarizeMethods(report.records, options.methods);
  WriteText(report.summary_json, SummaryJson(report.summaries, report.info).dump(2) + "\n");
  return report;
}

}  // namespace topay::bench
