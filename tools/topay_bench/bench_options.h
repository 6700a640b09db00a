#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tools/common/tool_cli.h"
#include "tools/topay_bench/bench_method.h"

namespace topay::bench {

/// Exit codes of topay-bench.
inline constexpr int kExitRan = tools::kExitSuccess;  ///< Ran (whatever the success rate).
inline constexpr int kExitError = tools::kExitFileError;  ///< A file, config or output error.
inline constexpr int kExitUsage = tools::kExitUsageError;  ///< A command-line mistake.

/// What topay-bench does, as plain values (the CLI only fills this in). Defaults in brackets.
struct BenchOptions {
  /// Scene kind ("cuboids" | "tables") [cuboids] and task range ("small" | "medium" |
  /// "large") [medium]. Task i is GenerateBenchmarkCase(kind, range, DeriveSeed(seed, i)):
  /// a fresh scene per task, as in the paper.
  std::string scene = "cuboids";
  std::string range = "medium";
  /// Tight tasks [false]: GenerateBenchmarkCase with TaskTightness::kTight (no keep-outs;
  /// start and goal exactly clear and within TaskGeneratorOptions::tight_clearance_max_m,
  /// 5 cm, of a box; sim/scenes/tight_task_generator.h). The cell is "<scene> <range> tight".
  bool tight = false;
  int num_tasks = 20;      ///< [20], in [1, 1000000].
  std::uint64_t seed = 1;  ///< Base seed S [1].
  /// Methods run on every task (BenchMethodName spellings), unique, at least one [topay].
  /// Task i runs them starting with method i mod M, in rotation.
  std::vector<std::string> methods = {"topay"};

  std::string planner_config;  ///< Planner YAML (core/io/planner_config.h); required.
  std::string robot_urdf;      ///< Robot description; required.
  std::string robot_yaml;

  /// Planner workers (both the planner's num_threads and front_end.num_threads); 0: all
  /// cores. 1: MakeDeterministic (core/planner/deterministic_options.h), reproducible.
  /// Unset: the planner YAML's planner.num_threads (config/planner/topay.yaml: 0).
  std::optional<int> num_threads;
  /// Per-task planning time limit (ms), in [10, 600000]: the planner's time_limit_s, and a
  /// success whose T.P. exceeds it counts as a failure ("time limit"). Unset: the YAML's
  /// planner.time_limit_s (config/planner/topay.yaml: 3 s).
  std::optional<double> time_limit_ms;
  /// "benchmark" (the paper's simulation limits) | "robot" (the robot YAML's) | "config"
  /// (the planner YAML's planner.base_limits). Empty: the YAML's if it sets them, else
  /// benchmark (plan::BaseLimitChoiceInForce).
  std::string base_limits;
  /// Give the task's generating goal state to the planner as its hint [true].
  bool use_hint = true;

  /// Sensed maps [""]: "line" or "tour" (SensingTourKind): every method also plans on the
  /// task's scene as the simulated LiDAR maps it from that tour, as "<method>@sensed"
  /// (tools/topay_bench/sensed_map.h), beside its runs on the exact scene.
  std::string sensed_map;
  /// How never-seen voxels count on a sensed map: "free" [default] or "occupied".
  std::string sensed_unknown = "free";
  /// The planner's extra obstacle margin on sensed maps (m) [0] (SensedMapSettings).
  double sensed_margin_m = 0.0;
  /// The mapper's options (scan filter, map) and the LiDAR's, for sensed maps; required with
  /// sensed_map.
  std::string mapper_config;
  std::string lidar_config;

  std::string out_dir;  ///< Output folder (created); required.
  /// Also write, per task, the scene and task JSON and per method the trajectory JSON (and
  /// the flatness baseline's pieces) [false].
  bool dump_trajectories = false;
};

/// Splits "topay,flatness" at commas (blanks around names ignored). Throws plan::UsageError
/// naming `option` for an empty list, an empty or unknown name or a repeated one.
std::vector<std::string> ParseMethodList(const std::string& text, const std::string& option);

/// Checks everything that needs no file: known names (scene, range, methods, base limits),
/// unique methods, ranges of the numbers, required paths. Throws plan::UsageError naming the
/// option as the CLI spells it.
void CheckBenchOptions(const BenchOptions& options);

/// The methods of checked options, parsed.
std::vector<BenchMethod> MethodsOf(const BenchOptions& options);

/// The names the run's records carry: the methods, then (sensed_map set) "<method>@sensed"
/// for each.
std::vector<std::string> RunMethodNames(const BenchOptions& options);

}  // namespace topay::bench
