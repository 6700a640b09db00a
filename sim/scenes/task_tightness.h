#pragma once

#include <optional>
#include <string_view>

namespace topay {

/// How close to the obstacles a generated task's start and goal states lie.
///  - kOpen: the paper's protocol (Sec. IV-C): keep-out cylinders of base radius + arm reach
///    around the start and goal base positions, so both ends are far from every box.
///  - kTight: no keep-outs; each end is exactly collision free and its closest body (base
///    cylinder or an arm sphere) is at most TaskGeneratorOptions::tight_clearance_max_m from
///    a box, as after a pick at a table or for a pick or place goal near a surface.
enum class TaskTightness { kOpen, kTight };

/// What the goal of a tight task is close to.
enum class TightGoalKind {
  kNearBox,     ///< Any box (Cuboids: floating cubes too; Tables: tops, legs, grounded boxes).
  kOnTable,     ///< The end-effector point just above a table top (tight_task_generator.h).
  kUnderTable,  ///< The end-effector point under a table top, above the floor.
};

/// "near_box", "on_table", "under_table".
std::string_view TightGoalKindName(TightGoalKind kind);
/// Inverse of TightGoalKindName; nullopt for anything else.
std::optional<TightGoalKind> ParseTightGoalKind(std::string_view name);

/// The body of the robot nearest to a box.
enum class TightBody { kBase, kArm };

/// "base" (the base cylinder) or "arm" (an arm sphere).
std::string_view TightBodyName(TightBody body);
/// Inverse of TightBodyName; nullopt for anything else.
std::optional<TightBody> ParseTightBody(std::string_view name);

/// One end (start or goal) of a tight task, as the generator measured it.
struct TightEnd {
  /// Exact obstacle clearance (m) of the state: min of the base cylinder's and every arm
  /// sphere's signed distance to the boxes (SceneClearance::obstacle_m), in
  /// (obstacle_margin_m, tight_clearance_max_m].
  double clearance_m = 0.0;
  int box = -1;  ///< Index in Scene::boxes of the box attaining it.
  TightBody body = TightBody::kBase;  ///< Which body attains it (the base on a tie).
};

/// What a tight task's ends are (PlanningTask::tight); unset for an open task.
struct TightTaskInfo {
  TightEnd start;
  TightEnd goal;
  TightGoalKind goal_kind = TightGoalKind::kNearBox;
  /// kOnTable, kUnderTable: the table top (index in Scene::boxes) the end effector is on or
  /// under; -1 for kNearBox.
  int goal_table_top = -1;
};

}  // namespace topay
