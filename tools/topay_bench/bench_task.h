#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/planner/whole_body_planner_options.h"
#include "core/robot/kinematics.h"
#include "tools/topay_bench/bench_method.h"
#include "tools/topay_bench/bench_planner_options.h"
#include "tools/topay_bench/bench_record.h"
#include "tools/topay_bench/sensed_map.h"
#include "tools/topay_plan/base_limit_choice.h"
#include "sim/scenes/distance_range.h"
#include "sim/scenes/scene_kind.h"
#include "sim/scenes/task_generator.h"

namespace topay::bench {

/// What every task of a run shares. The pointers must outlive RunBenchTask.
struct BenchTaskContext {
  const Kinematics* kinematics = nullptr;
  const WholeBodyPlannerOptions* loaded_options = nullptr;  ///< From the planner YAML.
  BenchPlannerSettings settings;
  plan::BaseLimitChoice limit_choice = plan::BaseLimitChoice::kBenchmark;
  SceneKind kind = SceneKind::kCuboids;
  DistanceRange range = DistanceRange::kSmall;
  /// The task generator's options (tightness: open or tight tasks).
  TaskGeneratorOptions generator;
  std::uint64_t seed = 1;            ///< Base seed S.
  std::vector<BenchMethod> methods;  ///< At least one.
  bool use_hint = true;
  /// Set: every method also runs on a sensed map of the task's scene (BuildSensedMap), as
  /// method "<name>@sensed" (SensedMethodName), after the exact runs.
  const SensedMapSettings* sensed = nullptr;
  /// Non-empty: write the task's scene and task JSON and each method's trajectory JSON here
  /// (TaskFilePath names).
  std::string dump_dir;
};

/// DIR/task_0007_<suffix>, e.g. suffix "scene.json", "task.json", "topay_trajectory.json",
/// "flatness_pieces.json" (indices below 10000 have 4 digits).
std::string TaskFilePath(const std::string& dir, int index, const std::string& suffix);

/// Task `index`: GenerateBenchmarkCase(kind, range, DeriveSeed(seed, index), generator), its distance
/// fields (PlannerFieldOptions, built once and timed: map_ms, not part of T.P.), then every
/// method in rotation starting with method index mod M, each with its own planner
/// (BenchPlannerOptions) and the task's goal state as hint when use_hint. One record per
/// method, in run order; a tight task's records carry its PlanningTask::tight. A task the
/// generator cannot make gives records with status "generation_failed" (category
/// kGenerationFailed) and the generator's message. With context.sensed, each method then also
/// plans on the task's sensed map (its fields and its blocked voxels as the planner's scene);
/// a plan the planner validated on the map counts only if the validator also accepts it on the
/// exact scene (else kValidatorRejected, "exact scene: ..."). Throws ConfigError if a dump cannot be
/// written.
/// "<method>@sensed": a method's runs on sensed maps.
std::string SensedMethodName(BenchMethod method);

std::vector<BenchRecord> RunBenchTask(const BenchTaskContext& context, int index);

}  // namespace topay::bench
