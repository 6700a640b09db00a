#include "sim/scenes/task_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/quantize.h"
#include "sim/scenes/task_sampling.h"
#include "sim/scenes/tight_task_generator.h"

namespace topay {
namespace {

WholeBodyState DrawBasePose(const BaseRegion& region, int num_joints, Rng& rng) {
  WholeBodyState state;
  state.x_m = QuantizeMicro(rng.Uniform(region.min_m.x(), region.max_m.x()));
  state.y_m = QuantizeMicro(rng.Uniform(region.min_m.y(), region.max_m.y()));
  state.yaw_rad = QuantizeMicro(rng.Uniform(-std::numbers::pi, std::numbers::pi));
  state.q_rad = Eigen::VectorXd::Zero(num_joints);
  return state;
}

// Draws (start, goal) base pose pairs until their distance is in range (the protocol's
// "redrawn until the base distance is in range": both poses are redrawn).
void DrawBasePairInRange(const BaseRegion& region, int num_joints, DistanceRange range,
                         const TaskGeneratorOptions& options, Rng& rng, PlanningTask* task) {
  const DistanceBounds bounds = DistanceRangeBounds(range);
  for (int i = 0; i < options.max_base_pair_tries; ++i) {
    task->start = DrawBasePose(region, num_joints, rng);
    task->goal = DrawBasePose(region, num_joints, rng);
    if (bounds.Contains(BaseDistance(task->start, task->goal))) return;
  }
  throw std::runtime_error("task generator: no base pose pair in range \"" +
                           std::string(DistanceRangeName(range)) + "\" in " +
                           std::to_string(options.max_base_pair_tries) + " draws");
}

// Draws arm configurations uniformly within the joint limits until the state is free (none
// if the base itself is not clear).
bool DrawFreeArm(const SceneClearanceChecker& checker, const JointLimits& limits,
                 const TaskGeneratorOptions& options, Rng& rng,
                 SceneClearanceWorkspace* workspace, WholeBodyState* state) {
  const Eigen::Vector2d p_WB(state->x_m, state->y_m);
  const double margin = options.obstacle_margin_m;
  if (!(checker.BaseClearance(p_WB, margin) > margin)) return false;
  for (int i = 0; i < options.max_arm_tries; ++i) {
    DrawUniformArm(limits, rng, state);
    if (checker.IsCollisionFree(*state, options.obstacle_margin_m, options.self_margin_m,
                                workspace)) {
      return true;
    }
  }
  return false;
}

void FillGoal(const Kinematics& kinematics, PlanningTask* task) {
  task->X_WE_goal = kinematics.EndEffectorPose(task->goal);
  task->base_distance_m = BaseDistance(task->start, task->goal);
}

void CheckOptions(const TaskGeneratorOptions& options) {
  if (options.max_base_pair_tries <= 0 || options.max_arm_tries <= 0 ||
      options.max_base_pose_tries <= 0 || options.max_tight_scene_tries <= 0) {
    throw std::invalid_argument("task generator: the max_*_tries options must be positive");
  }
}

// A tight case: the first of max_tight_scene_tries scenes in which GenerateTightTask finds a
// task (its search failing in every one: the last failure, with the number of scenes).
BenchmarkCase GenerateTightCase(SceneKind kind, DistanceRange range, std::uint64_t seed,
                                const Kinematics& kinematics,
                                const TaskGeneratorOptions& options) {
  for (int k = 0;; ++k) {
    BenchmarkCase out;
    const std::uint64_t scene_seed = k == 0 ? DeriveSeed(seed, 1) : DeriveSeed(seed, 100 + k);
    out.scene = GenerateBenchmarkScene(kind, scene_seed);
    try {
      out.task = GenerateTightTask(out.scene, range, seed, kinematics, options);
      return out;
    } catch (const std::runtime_error& e) {
      if (k + 1 >= options.max_tight_scene_tries) {
        throw std::runtime_error(std::string(e.what()) + "; in each of " +
                                 std::to_string(k + 1) + " scene(s)");
      }
    }
  }
}

}  // namespace

double ArmReachBound(const RobotModel& model) {
  double reach = 0.0;
  for (const CollisionSphere& sphere : model.spheres) {
    double length = sphere.p_LS_m.norm() + sphere.radius_m;
    for (int link = sphere.link; link >= 0; link = model.links[link].parent) {
      length += model.links[link].X_PJ.translation().norm();
    }
    reach = std::max(reach, length);
  }
  return reach;
}

BenchmarkCase GenerateBenchmarkCase(SceneKind kind, DistanceRange range, std::uint64_t seed,
                                    const Kinematics& kinematics,
                                    const TaskGeneratorOptions& options) {
  CheckOptions(options);
  if (options.tightness == TaskTightness::kTight) {
    return GenerateTightCase(kind, range, seed, kinematics, options);
  }
  const RobotModel& model = kinematics.model();
  const Scene room_shape;  // Default bounds: the benchmark room.
  const BaseRegion region = MakeBaseRegion(room_shape.bounds_W_m, range, options.wall_margin_m);
  BenchmarkCase out;
  PlanningTask& task = out.task;
  task.range = range;
  task.seed = seed;
  Rng pose_rng(seed);
  DrawBasePairInRange(region, model.num_joints(), range, options, pose_rng, &task);

  KeepOutRegions keep_out;
  const double radius =
      model.base_cylinder.radius_m + ArmReachBound(model) + options.keep_out_margin_m;
  for (const WholeBodyState* state : {&task.start, &task.goal}) {
    keep_out.cylinders.push_back(
        {Eigen::Vector2d(state->x_m, state->y_m), radius, 0.0, room_shape.bounds_W_m.max().z()});
  }
  task.scene_seed = DeriveSeed(seed, 1);
  out.scene = GenerateBenchmarkScene(kind, task.scene_seed, keep_out);

  const SceneClearanceChecker checker(kinematics, out.scene.scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  Rng arm_rng(DeriveSeed(seed, 2));
  for (WholeBodyState* state : {&task.start, &task.goal}) {
    if (!DrawFreeArm(checker, model.joint_limits, options, arm_rng, &workspace, state)) {
      throw std::runtime_error("GenerateBenchmarkCase: no collision-free arm configuration in " +
                               std::to_string(options.max_arm_tries) + " draws (seed " +
                               std::to_string(seed) + ")");
    }
  }
  FillGoal(kinematics, &task);
  return out;
}

PlanningTask GenerateTask(const Scene& scene, DistanceRange range, std::uint64_t seed,
                          const Kinematics& kinematics, const TaskGeneratorOptions& options) {
  CheckOptions(options);
  if (options.tightness == TaskTightness::kTight) {
    throw std::invalid_argument(
        "GenerateTask: tight tasks need the scene's box roles (use GenerateTightTask)");
  }
  const RobotModel& model = kinematics.model();
  const BaseRegion region = MakeBaseRegion(scene.bounds_W_m, range, options.wall_margin_m);
  const SceneClearanceChecker checker(kinematics, scene);
  SceneClearanceWorkspace workspace = checker.MakeWorkspace();
  Rng rng(seed);
  PlanningTask task;
  task.range = range;
  task.seed = seed;
  task.scene_seed = scene.seed;
  for (int i = 0; i < options.max_base_pose_tries; ++i) {
    DrawBasePairInRange(region, model.num_joints(), range, options, rng, &task);
    if (DrawFreeArm(checker, model.joint_limits, options, rng, &workspace, &task.start) &&
        DrawFreeArm(checker, model.joint_limits, options, rng, &workspace, &task.goal)) {
      FillGoal(kinematics, &task);
      return task;
    }
  }
  throw std::runtime_error("GenerateTask: no collision-free start and goal states in range \"" +
                           std::string(DistanceRangeName(range)) + "\" in " +
                           std::to_string(options.max_base_pose_tries) + " base pose pairs");
}

}  // namespace topay
