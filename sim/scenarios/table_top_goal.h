#pragma once
// A whole-body goal with the end effector above a table top of a generated room, exactly clear
// by a margin and reachable through passages the sensed map keeps open: the ends of the
// pick-and-place scenario (pick_place_scenario.h).

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/planning/base_reachability.h"
#include "core/robot/kinematics.h"
#include "core/robot/whole_body_state.h"
#include "sim/scenarios/pick_place_options.h"
#include "sim/scenes/generated_scene.h"
#include "sim/scenes/task_generator.h"

namespace topay {

struct TableTopGoal {
  int table_top = -1;          ///< Index in the scene's boxes of the top (BoxRole::kTableTop).
  WholeBodyState state;        ///< The whole-body configuration (the planner's hint).
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();  ///< FK of state.
  double clearance_m = 0.0;    ///< Exact obstacle clearance (base and arm spheres) of state.
};

/// Where a goal may be: its base reached by `reachable` and at least min_base_distance_m from
/// p_W_from_m, on a table top other than exclude_table_top.
struct TableTopGoalQuery {
  const ProvenBaseRegion* reachable = nullptr;  ///< required
  Eigen::Vector2d p_W_from_m = Eigen::Vector2d::Zero();
  double min_base_distance_m = 0.0;
  int exclude_table_top = -1;
};

/// The on-table test of options' heights (GoalKindHolds, TightGoalKind::kOnTable): p_WE inside
/// the footprint of `table_top`, height_min_m..height_max_m above its upper face.
bool AboveTableTop(const OrientedBox& table_top, const Eigen::Vector3d& p_WE, const PickPlaceScenarioOptions& options);

/// Draws goals in one room. The scene and the kinematics must outlive it.
class TableTopGoalSampler {
 public:
  /// Throws std::invalid_argument if the roles do not match the boxes.
  TableTopGoalSampler(const GeneratedScene& room, const Kinematics& kinematics, const PickPlaceScenarioOptions& options);

  /// Up to options.max_targets draws, each: a table top (uniform among the allowed: upper face
  /// at most top_height_max_m high, not excluded, NextToReachedBase), p_WE
  /// uniform over its footprint inset by edge_inset_m at a uniform height in range, the tool's
  /// yaw uniform; a whole-body IK (seeded from `rng`, deterministic) with obstacle clearance
  /// > obstacle_clearance_m; its solutions, cheapest first, until one meets the query and
  /// AboveTableTop, with every arm sphere above the floor. nullopt if none.
  std::optional<TableTopGoal> Draw(const TableTopGoalQuery& query, Rng* rng) const;

  /// Every condition Draw asks of a goal (for tests): exactly clear by the margin (self
  /// clearance > 0), above the table top, the arm above the floor, the base in the query.
  bool Admits(const TableTopGoal& goal, const TableTopGoalQuery& query) const;

 private:
  Eigen::Isometry3d DrawTarget(const OrientedBox& top, Rng* rng) const;
  std::optional<TableTopGoal> Solve(int top, const Eigen::Isometry3d& X_WE, const TableTopGoalQuery& query,
                                    Rng* rng) const;
  bool ArmAboveFloor(const WholeBodyState& state) const;
  /// Some base position next to `top` (on its footprint grown by the base radius + 0.1 m) is
  /// reached and far enough from the query's `from`: else no goal there is likely.
  bool NextToReachedBase(const OrientedBox& top, const TableTopGoalQuery& query) const;

  const GeneratedScene& room_;
  const Kinematics& kinematics_;
  PickPlaceScenarioOptions options_;
  SceneClearanceChecker checker_;
  double reach_m_;  // ArmReachBound: no base farther than this from its end effector
  std::vector<int> table_tops_;
};

}  // namespace topay
