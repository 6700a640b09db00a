#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/planner/whole_body_plan_result.h"
#include "core/robot/robot_model.h"
#include "core/robot/whole_body_state.h"
#include "tools/common/tool_cli.h"
#include "tools/topay_plan/base_limit_choice.h"
#include "tools/topay_plan/planner_overrides.h"

namespace topay::plan {

/// Exit codes of topay-plan.
inline constexpr int kExitSuccess = tools::kExitSuccess;        ///< A validated trajectory.
inline constexpr int kExitError = tools::kExitFileError;        ///< A file, config or output error.
inline constexpr int kExitUsage = tools::kExitUsageError;       ///< A command-line mistake.
inline constexpr int kExitPlanFailed = tools::kExitPlanFailed;  ///< No validated trajectory.

/// What the topay-plan command does, as plain values (the CLI only fills this in).
struct PlanToolOptions {
  /// Scene: exactly one of scene_kind ("cuboids" | "tables", generated from `seed`) and
  /// scene_file (a scene JSON, sim/scenes/scene_json.h).
  std::string scene_kind;
  std::string scene_file;
  std::uint64_t seed = 1;
  /// Task: exactly one of
  ///  - range ("small" | "medium" | "large"): generated from `seed` as topay-scene does (with
  ///    scene_kind: GenerateBenchmarkCase, the benchmark protocol; with scene_file:
  ///    GenerateTask in the loaded scene);
  ///  - task_file: a task JSON (sim/scenes/task_json.h);
  ///  - start and one of target_rpy, target_quaternion, on the command line.
  std::string range;
  std::string task_file;
  /// x (m), y (m), yaw (rad), q1..qN (rad): N + 3 numbers.
  std::vector<double> start;
  /// End-effector target: x, y, z (m), roll, pitch, yaw (rad) about W's fixed axes,
  /// R = Rz(yaw) Ry(pitch) Rx(roll) (the URDF convention).
  std::vector<double> target_rpy;
  /// End-effector target: x, y, z (m), then a unit quaternion w, x, y, z.
  std::vector<double> target_quaternion;
  /// Pass a generated or loaded task's goal state to the planner as a hint (tried first as
  /// the goal). Off by default: the target is an end-effector pose, as in the paper.
  bool use_goal_hint = false;

  /// Outputs; empty: not written. The time plots are written only for a trajectory.
  std::string trajectory_json_out;
  std::string path_png_out;
  std::string time_png_out;

  /// Planner settings that override the planner YAML when given (precedence: defaults, then
  /// YAML, then flags; planner_overrides.h). Unset: the YAML's value.
  PlannerOverrides overrides;
  /// --base-limits as given: "benchmark" | "robot" | "config"; empty: not given (the YAML's
  /// planner.base_limits if it sets them, else benchmark; BaseLimitChoiceInForce).
  std::string base_limits;

  /// Drawing: top-down scale, footprint interval (s); JSON sample period (s, the validator's 10 ms).
  double px_per_m = 40.0;
  double footprint_interval_s = 1.0;
  double sample_period_s = 0.01;

  std::string robot_urdf;  ///< Robot description (required).
  std::string robot_yaml;
  /// Planner options YAML (core/io/planner_config.h); empty: the options structs' defaults.
  /// `overrides` and `base_limits` override what it sets, only where given.
  std::string planner_config;
};

/// One row of the candidate table.
struct CandidateRow {
  int index = 0;
  std::string base_path;    ///< e.g. "PRM class 0, 9.8 m" or "JPS, 10.4 m".
  std::string optimizer;    ///< ToString(BackEndStatus), or "not started".
  double duration_s = 0.0;  ///< 0 if not started.
  int iterations = 0;       ///< L-BFGS iterations.
  double wall_ms = 0.0;
  std::string verdict;  ///< "validated", "rejected: ..", "-" ...
  bool chosen = false;
};

/// What was done, for the report and the exit code.
struct PlanToolSummary {
  // Scene and task.
  std::string scene_kind;
  std::uint64_t scene_seed = 0;
  std::string scene_source;  ///< "generated from --seed N" or the scene file.
  int num_boxes = 0;
  Eigen::Vector3d scene_size_m = Eigen::Vector3d::Zero();
  std::string task_source;  ///< "generated", "task file <path>" or "command line".
  std::string task_range;   ///< Empty for a command-line task.
  std::uint64_t task_seed = 0;
  double base_distance_m = 0.0;  ///< Start to goal base position (0 if unknown: no goal state).
  WholeBodyState start;
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  bool used_goal_hint = false;
  // Limits and planner settings.
  BaseLimitChoice limit_choice = BaseLimitChoice::kBenchmark;
  BaseLimits base_limits;
  int num_threads = 0;
  double time_limit_s = 0.0;
  bool sequential = false;
  // Map (built inside the plan, under its time limit; 0 if the start or target was refused).
  double map_build_ms = 0.0;
  double arm_field_resolution_m = 0.0;
  double base_field_resolution_m = 0.0;
  Eigen::Vector3i arm_field_cells = Eigen::Vector3i::Zero();
  // The plan.
  WholeBodyPlanResult plan;
  std::vector<CandidateRow> candidates;
  // Outputs written (empty path: not written).
  std::string trajectory_json;
  int num_samples = 0;
  std::string path_png;
  int path_png_width_px = 0, path_png_height_px = 0;
  std::string time_png;
  int time_png_width_px = 0, time_png_height_px = 0;
  std::string time_png_skipped;  ///< Why a requested time plot was not written.

  /// kExitSuccess for a validated trajectory, else kExitPlanFailed.
  int ExitCode() const;
  /// Readable multi-line report (trailing newline): verdict and failure reason; scene, task,
  /// limits, map build time; time per stage (search, sampling, optimization, wait, total);
  /// trajectory duration, minimum clearance, worst constraint ratio, end-effector error; the
  /// candidate table; the files written.
  std::string Report() const;
};

/// Loads the robot, gets the scene and the task, builds the distance fields
/// (PlannerFieldOptions, timed), plans one query (WholeBodyPlanner) and writes the requested
/// outputs: the trajectory JSON (tools/topay_plan/trajectory_json.h; on a failure, metadata only),
/// the top-down PNG (always, with the trajectory if there is one) and the time plots (only
/// with a trajectory). A planning failure is not an exception: see summary.ExitCode().
/// Throws UsageError for bad options (naming the option as the CLI spells it),
/// topay::ConfigError for a missing or malformed input file (naming it), and
/// std::runtime_error for an output that cannot be written (naming it; checked before
/// planning) or a task generator that gives up.
PlanToolSummary RunPlanTool(const PlanToolOptions& options);

}  // namespace topay::plan
