#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>

#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "tools/topay_plan/plan_tool.h"

namespace topay::plan {

/// One planning query: the scene and the task, wherever they came from.
struct PlanQuery {
  Scene scene;
  std::string scene_source;  ///< "generated from --seed N" or the scene file's path.
  WholeBodyState start;
  Eigen::Isometry3d X_WE_goal = Eigen::Isometry3d::Identity();
  /// The task's goal state (generated or loaded tasks); unset for a command-line task.
  std::optional<WholeBodyState> goal_state;
  std::string task_source;  ///< "generated", "task file <path>" or "command line".
  std::string task_range;   ///< Empty for a command-line task.
  std::uint64_t task_seed = 0;
};

/// Checks everything about the options that needs no file and no robot: one scene source,
/// one task source, the sizes of the target vectors, finite numbers, known names, ranges of
/// the planner and drawing settings. Throws UsageError naming the option.
void CheckPlanToolOptions(const PlanToolOptions& options);

/// Checks that every requested output's folder exists, so that a plan is not lost to a typo
/// in a path. Throws std::runtime_error naming the option and the path.
void CheckOutputFolders(const PlanToolOptions& options);

/// Generates or loads the scene and the task (see PlanToolOptions). Throws UsageError for an
/// unknown scene kind or range or a --start of the wrong size for the robot, ConfigError for
/// a missing or malformed scene or task file (or a task file for another joint count), and
/// std::runtime_error when a generator gives up.
PlanQuery ResolvePlanQuery(const PlanToolOptions& options, const Kinematics& kinematics);

}  // namespace topay::plan
