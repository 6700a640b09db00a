#include "tools/topay_bench/bench_run.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"
#include "tools/topay_bench/bench_record_json.h"
#include "tools/topay_bench/bench_task.h"
#include "procs/mapper/mapper_options.h"
#include "sim/lidar/lidar_options.h"
#include "tools/topay_plan/planner_overrides.h"

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

// The settings in force: the planner YAML's, then the flags that were given.
BenchPlannerSettings SettingsInForce(const BenchOptions& o, const RobotModel& model,
                                     const WholeBodyPlannerOptions& loaded,
                                     plan::BaseLimitChoice* choice) {
  plan::PlannerOverrides overrides;
  overrides.num_threads = o.num_threads;
  if (o.time_limit_ms) overrides.time_limit_s = *o.time_limit_ms / 1000.0;
  if (!o.base_limits.empty()) overrides.base_limits = plan::ParseBaseLimitChoice(o.base_limits);
  WholeBodyPlannerOptions in_force = loaded;
  *choice = plan::ApplyPlannerOverrides(overrides, model, &in_force);
  BenchPlannerSettings settings;
  settings.base_limits = *in_force.base_limits;
  settings.num_threads = in_force.num_threads;
  settings.time_limit_ms = 1000.0 * in_force.time_limit_s;
  return settings;
}

BenchRunInfo RunInfo(const BenchOptions& o, const BenchTaskContext& c) {
  BenchRunInfo info;
  info.scene = o.scene;
  info.range = o.range;
  info.tight = o.tight;
  info.tight_clearance_max_m = c.generator.tight_clearance_max_m;
  info.seed = o.seed;
  info.threads = c.settings.num_threads > 0
                     ? c.settings.num_threads
                     : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  info.time_limit_ms = c.settings.time_limit_ms;
  info.use_hint = o.use_hint;
  info.base_limits = std::string(plan::BaseLimitChoiceName(c.limit_choice));
  info.planner_config = o.planner_config;
  info.sensed_map = o.sensed_map;
  info.sensed_unknown = o.sensed_unknown;
  info.sensed_margin_m = o.sensed_margin_m;
  return info;
}

// The sensed maps' settings: the mapper's and the LiDAR's files (ConfigError on a bad one).
SensedMapSettings SensedSettingsOf(const BenchOptions& o) {
  SensedMapSettings s;
  s.tour.kind = *ParseSensingTourKind(o.sensed_map);
  const mapper::MapperOptions mapper = mapper::LoadMapperOptions(o.mapper_config);
  s.filter = mapper.filter;
  s.map = mapper.map;
  s.lidar = sim::LoadLidarOptionsFile(o.lidar_config);
  s.unknown = o.sensed_unknown == "occupied" ? UnknownVoxelPolicy::kOccupied : UnknownVoxelPolicy::kFree;
  s.map_margin_m = o.sensed_margin_m;
  return s;
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
  context.settings = SettingsInForce(options, model, loaded, &context.limit_choice);
  context.kind = *ParseSceneKind(options.scene);
  context.range = *ParseDistanceRange(options.range);
  context.generator.tightness = options.tight ? TaskTightness::kTight : TaskTightness::kOpen;
  context.seed = options.seed;
  context.methods = MethodsOf(options);
  context.use_hint = options.use_hint;
  if (options.dump_trajectories) context.dump_dir = options.out_dir;
  std::optional<SensedMapSettings> sensed;
  if (!options.sensed_map.empty()) {
    sensed = SensedSettingsOf(options);
    context.sensed = &*sensed;
  }

  BenchReport report;
  report.info = RunInfo(options, context);
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
  report.summaries = SummarizeMethods(report.records, RunMethodNames(options));
  WriteText(report.summary_json, SummaryJson(report.summaries, report.info).dump(2) + "\n");
  return report;
}

}  // namespace topay::bench
