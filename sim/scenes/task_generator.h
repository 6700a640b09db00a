#pragma once

#include <cstdint>

#include "core/geometry/scene.h"
#include "core/robot/kinematics.h"
#include "sim/scenes/distance_range.h"
#include "sim/scenes/generated_scene.h"
#include "sim/scenes/planning_task.h"
#include "sim/scenes/scene_kind.h"
#include "sim/scenes/task_tightness.h"

namespace topay {

struct TaskGeneratorOptions {
  /// Base positions are uniform in the scene's bounds (xy) shrunk by this margin on every
  /// side: the protocol's "2 m from walls", measured from the room's outer border, i.e.
  /// x, y in [-8, 8] m for the 20 x 20 m room. Yaw uniform in [-pi, pi).
  double wall_margin_m = 2.0;
  /// A state counts as free if its exact obstacle clearance (base and arm spheres) exceeds
  /// obstacle_margin_m and its self clearances (sphere pairs, arm above chassis) exceed
  /// self_margin_m (SceneClearance::IsCollisionFree).
  double obstacle_margin_m = 0.0;
  double self_margin_m = 0.0;
  /// Draws of a (start, goal) base pose pair until its distance is in range (both redrawn).
  int max_base_pair_tries = 100000;
  /// Draws of an arm configuration (uniform within the joint limits) for one base pose.
  int max_arm_tries = 1000;
  /// GenerateTask: in-range base pose pairs tried before giving up.
  int max_base_pose_tries = 1000;
  /// GenerateBenchmarkCase: keep-out cylinders of radius base radius + arm reach bound
  /// (ArmReachBound) + this margin, around the start and goal base positions.
  double keep_out_margin_m = 0.1;

  // ---- Tight tasks (sim/scenes/tight_task_generator.h) ----------------------------------
  /// kOpen: the protocol above. kTight: GenerateBenchmarkCase makes the scene without
  /// keep-outs and draws both ends with GenerateTightTask.
  TaskTightness tightness = TaskTightness::kOpen;
  /// A tight end's exact obstacle clearance (its closest body, base cylinder or arm sphere,
  /// to its nearest box) must lie in (obstacle_margin_m, tight_clearance_max_m] (m).
  double tight_clearance_max_m = 0.05;
  /// A tight end's base position is uniform over the footprint of a chosen box grown by the
  /// base radius + tight_base_spread_m on every side (m); positions where the base cylinder
  /// is not clear are redrawn.
  double tight_base_spread_m = 0.5;
  /// A tight end whose base the robot could not have driven to (shut in a pocket between
  /// table legs, say, or behind a gap barely wider than the base) is redrawn: unless
  /// CertifyBaseOpen (base_reachability.h) proves that the base can leave the square of this
  /// half side (m) around it with tight_passage_clearance_m to spare. 0: no such check.
  double tight_pocket_window_m = 2.0;
  /// The spare clearance (m) of that way out (BaseOpennessOptions::clearance_m), except in
  /// the last tight_approach_radius_m (m) before the end; the goal's base must also be
  /// reachable from the start's with it (ProvenBaseRegion). A passage within a centimetre of
  /// the base's width is not one a robot is driven through: with the lenient pocket test
  /// alone (CertifyBaseEnclosed), 5 of 50 Tables small tight tasks had an end behind such a
  /// gap, reached by no straight exact move (docs/benchmarks.md, "Close quarters").
  double tight_passage_clearance_m = 0.01;
  double tight_approach_radius_m = 0.1;
  /// Arm configurations drawn (uniform within the joint limits) per tight base pose.
  int tight_arm_tries = 200;
  /// Base poses drawn per tight end before the (start, goal) pair is given up.
  int max_tight_base_tries = 2000;
  /// (start, goal) pairs tried before GenerateTightTask throws.
  int max_tight_pair_tries = 10;
  /// GenerateBenchmarkCase (kTight): scenes tried. A scene where GenerateTightTask finds no
  /// task (no under-table goal in range, say) holds no task to plan, so the case draws a
  /// fresh scene rather than having no task (DeriveSeed(seed, 1) first, then
  /// DeriveSeed(seed, 100 + k) for try k); every try's task is drawn from `seed`.
  int max_tight_scene_tries = 3;
  /// Tables scenes (boxes with BoxRole::kTableTop): the share of tight goals whose end
  /// effector is on or under a table top, half each (TightGoalKind); the others are near
  /// any box. In [0, 1].
  double table_goal_fraction = 0.5;
  /// kOnTable: the end-effector point is this far (m) above the top's upper face, within
  /// [min, max], and inside its footprint.
  double on_table_height_min_m = 0.02;
  double on_table_height_max_m = 0.15;
};

/// A generated scene with a task in it.
struct BenchmarkCase {
  GeneratedScene scene;
  PlanningTask task;
};

/// Upper bound (m) on the distance from the base frame's origin of any point of any arm
/// sphere, over all joint values: for each sphere, the lengths of the fixed joint offsets
/// |p_PJ| on the path from the root to its link, plus |p_LS| + r (triangle inequality).
double ArmReachBound(const RobotModel& model);

/// options.tightness == kOpen: the paper's benchmark protocol (Sec. IV-C, with the authors'
/// code's figures) for one task: from `seed`, draw the start and goal base poses (uniform,
/// see TaskGeneratorOptions) until their straight-line distance is in `range`; then generate
/// a fresh `kind` scene with seed DeriveSeed(seed, 1) and keep-out cylinders around both base
/// positions; then draw the start and goal arm configurations
/// (uniform within the joint limits, from DeriveSeed(seed, 2)) until each state is exactly
/// collision free (SceneClearanceChecker, no distance field).
/// options.tightness == kTight: a fresh `kind` scene with seed DeriveSeed(seed, 1) and no
/// keep-out regions, then GenerateTightTask(scene, range, seed) (tight_task_generator.h):
/// both ends exactly clear and within tight_clearance_max_m of a box; a scene without such a
/// task is replaced by a fresh one, at most max_tight_scene_tries scenes.
/// Same seed and options, same case. Throws std::runtime_error if a bounded search fails
/// (e.g. no free arm configuration in max_arm_tries), std::invalid_argument for an
/// impossible range for the room or bad options.
BenchmarkCase GenerateBenchmarkCase(SceneKind kind, DistanceRange range, std::uint64_t seed,
                                    const Kinematics& kinematics,
                                    const TaskGeneratorOptions& options = {});

/// A task in an existing scene: from `seed`, base pose pairs are drawn as above (in range),
/// and a pair is kept if both its poses have a collision-free arm configuration (each drawn up
/// to max_arm_tries times; a pose whose base cylinder is not clear is rejected at once);
/// at most max_base_pose_tries pairs. task.scene_seed = scene.seed. Throws std::runtime_error
/// when the bounded search fails, std::invalid_argument for an impossible range or for
/// options.tightness == kTight (tight tasks need the box roles: GenerateTightTask).
PlanningTask GenerateTask(const Scene& scene, DistanceRange range, std::uint64_t seed,
                          const Kinematics& kinematics, const TaskGeneratorOptions& options = {});

}  // namespace topay
