#pragma once

#include <cstdint>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "core/robot/kinematics.h"
#include "sim/scenes/distance_range.h"
#include "sim/scenes/generated_scene.h"
#include "sim/scenes/planning_task.h"
#include "sim/scenes/task_generator.h"
#include "sim/scenes/task_tightness.h"

namespace topay {

/// Whether the end-effector point p_WE (the origin of E, the planner's target position) meets
/// a tight goal kind for `table_top` (a BoxRole::kTableTop box; ignored for kNearBox, which
/// always holds):
///  - kOnTable: p_WE is inside the top's footprint (xy signed distance <= 0) and between
///    on_table_height_min_m and on_table_height_max_m above its upper face;
///  - kUnderTable: p_WE is inside the footprint, below the top's lower face and above the
///    floor (z > floor_z_m).
bool GoalKindHolds(TightGoalKind kind, const OrientedBox& table_top, const Eigen::Vector3d& p_WE,
                   const TaskGeneratorOptions& options, double floor_z_m);

/// A tight task in a generated scene (no keep-outs needed): both ends are exactly collision
/// free (SceneClearanceChecker at obstacle_margin_m / self_margin_m, no distance field) and
/// tight, i.e. their exact obstacle clearance is at most tight_clearance_max_m; every arm
/// sphere is above the floor (z - r >= the bounds' minimum z: the floor is not a box) and
/// the end-effector point inside the scene's bounds. Base positions lie in the region of
/// TaskGeneratorOptions::wall_margin_m, their distance in `range`.
///
/// From Rng(seed), in this order:
///  1. the goal kind, once: with probability table_goal_fraction (Tables scenes, i.e. scenes with a
///     kTableTop box; otherwise never) kOnTable or kUnderTable (even odds), else kNearBox;
///  then at most max_tight_pair_tries (start, goal) pairs, each:
///  2. the start: up to max_tight_base_tries base poses, each near an anchor box drawn
///     uniformly among the non-wall boxes from which the range can still be met: position
///     uniform over the anchor's footprint grown by the base radius + tight_base_spread_m,
///     inside the base region with the base cylinder clear, yaw uniform in [-pi, pi); at each,
///     up to tight_arm_tries arm configurations uniform within the joint limits, the first
///     that is clear and tight is taken, unless the base is not proven able to leave the
///     square of half side tight_pocket_window_m around it with tight_passage_clearance_m to
///     spare (CertifyBaseOpen: then the next base pose; a region shut
///     off on a larger scale is not excluded, as in the open protocol: topay-bench's
///     base_unreachable certificate reports such tasks);
///  3. the goal likewise, its anchor among the boxes whose grown footprint meets the range's
///     annulus around the start (table tops only for kOnTable / kUnderTable, whose end
///     effector must then meet GoalKindHolds for the anchor), its base distance in range,
///     and its base one the start's can reach through passages with
///     tight_passage_clearance_m to spare (ProvenBaseRegion from the start; unless
///     tight_pocket_window_m is 0): the robot drove from the one to the other.
/// Every number is on the 1e-6 grid (quantize.h). task.tight records each end's exact
/// clearance, nearest box and body, the goal kind and its table top; task.seed = seed,
/// task.scene_seed = scene.scene.seed, X_WE_goal = FK(goal). Same scene, seed and options,
/// same task.
/// Throws std::invalid_argument for bad options (tight_clearance_max_m <= obstacle_margin_m,
/// a fraction outside [0, 1], non-positive tries, on-table heights out of order), a scene
/// whose roles do not match its boxes, or an impossible range; std::runtime_error when the
/// bounded search fails (naming the seed).
PlanningTask GenerateTightTask(const GeneratedScene& scene, DistanceRange range,
                               std::uint64_t seed, const Kinematics& kinematics,
                               const TaskGeneratorOptions& options = {});

}  // namespace topay
