#include "sim/scenes/task_generator.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/geometry/primitive_box_distance.h"
#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_json.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

class TaskGeneratorTest : public ::testing::Test {
 protected:
  TaskGeneratorTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  // Checks every property a generated task must have in `scene`.
  void ExpectValidTask(const PlanningTask& task, const Scene& scene, DistanceRange range) {
    const SceneClearanceChecker checker(kinematics_, scene);
    for (const WholeBodyState* state : {&task.start, &task.goal}) {
      const SceneClearance clearance = checker.Compute(*state);
      EXPECT_TRUE(clearance.IsCollisionFree())
          << "base " << clearance.base_m << " spheres " << clearance.spheres_m << " self "
          << clearance.self_m << " chassis " << clearance.chassis_m;
      EXPECT_GE(state->x_m, -8.0);
      EXPECT_LE(state->x_m, 8.0);
      EXPECT_GE(state->y_m, -8.0);
      EXPECT_LE(state->y_m, 8.0);
      EXPECT_LE(std::abs(state->yaw_rad), std::numbers::pi);
      ASSERT_EQ(state->num_joints(), model_.num_joints());
      EXPECT_TRUE((state->q_rad.array() >= model_.joint_limits.q_min_rad.array()).all());
      EXPECT_TRUE((state->q_rad.array() <= model_.joint_limits.q_max_rad.array()).all());
    }
    const double distance = std::hypot(task.goal.x_m - task.start.x_m,
                                       task.goal.y_m - task.start.y_m);
    EXPECT_EQ(task.base_distance_m, distance);
    EXPECT_TRUE(DistanceRangeBounds(range).Contains(distance)) << distance;
    EXPECT_EQ(task.range, range);
    const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(task.goal);
    EXPECT_TRUE(X_WE.matrix().isApprox(task.X_WE_goal.matrix(), 1e-12));
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(TaskGeneratorTest, FiftyBenchmarkCasesPerRange) {
  const double keep_out_radius = model_.base_cylinder.radius_m + ArmReachBound(model_);
  for (const DistanceRange range :
       {DistanceRange::kSmall, DistanceRange::kMedium, DistanceRange::kLarge}) {
    for (std::uint64_t i = 0; i < 50; ++i) {
      const std::uint64_t seed = DeriveSeed(1000 + static_cast<int>(range), i);
      const SceneKind kind = i % 2 == 0 ? SceneKind::kCuboids : SceneKind::kTables;
      const BenchmarkCase generated = GenerateBenchmarkCase(kind, range, seed, kinematics_);
      const PlanningTask& task = generated.task;
      SCOPED_TRACE("range " + std::string(DistanceRangeName(range)) + " case " +
                   std::to_string(i));
      ExpectValidTask(task, generated.scene.scene, range);
      EXPECT_EQ(task.seed, seed);
      EXPECT_EQ(task.scene_seed, DeriveSeed(seed, 1));
      EXPECT_EQ(generated.scene.scene.seed, task.scene_seed);
      EXPECT_EQ(generated.scene.scene.kind, SceneKindName(kind));
      // No obstacle near the start or goal base (keep-outs of base radius + arm reach).
      for (const WholeBodyState* state : {&task.start, &task.goal}) {
        const VerticalCylinder region{Eigen::Vector2d(state->x_m, state->y_m), keep_out_radius,
                                      0.0, 1.6};
        for (std::size_t b = 0; b < generated.scene.scene.boxes.size(); ++b) {
          EXPECT_GE(SignedDistanceCylinderToBox(generated.scene.scene.boxes[b], region), 0.0);
        }
      }
    }
  }
}

TEST_F(TaskGeneratorTest, ArmReachBoundCoversRandomConfigurations) {
  Rng rng(3);
  const double reach = ArmReachBound(model_);
  EXPECT_GT(reach, 1.0);  // the arm is over a metre long
  EXPECT_LT(reach, 2.0);
  KinematicsCache cache = kinematics_.MakeCache();
  double farthest = 0.0;
  for (int i = 0; i < 2000; ++i) {
    WholeBodyState state = testing::RandomState(model_, &rng);
    state.x_m = state.y_m = 0.0;
    kinematics_.Update(state, &cache);
    for (std::size_t s = 0; s < model_.spheres.size(); ++s) {
      farthest = std::max(farthest, cache.p_WS[s].norm() + model_.spheres[s].radius_m);
    }
  }
  EXPECT_LE(farthest, reach);
  EXPECT_GT(farthest, 0.8 * reach);
}

TEST_F(TaskGeneratorTest, SameSeedSameFilesDifferentSeedDifferentFiles) {
  const BenchmarkCase a =
      GenerateBenchmarkCase(SceneKind::kTables, DistanceRange::kMedium, 99, kinematics_);
  const BenchmarkCase b =
      GenerateBenchmarkCase(SceneKind::kTables, DistanceRange::kMedium, 99, kinematics_);
  const BenchmarkCase c =
      GenerateBenchmarkCase(SceneKind::kTables, DistanceRange::kMedium, 100, kinematics_);
  EXPECT_EQ(SceneToJson(a.scene.scene, &a.scene.roles), SceneToJson(b.scene.scene, &b.scene.roles));
  EXPECT_EQ(TaskToJson(a.task), TaskToJson(b.task));
  EXPECT_NE(SceneToJson(a.scene.scene, &a.scene.roles), SceneToJson(c.scene.scene, &c.scene.roles));
  EXPECT_NE(TaskToJson(a.task), TaskToJson(c.task));
}

TEST_F(TaskGeneratorTest, TasksInAnExistingScene) {
  const GeneratedScene scene = GenerateTablesScene(2024);
  for (const DistanceRange range :
       {DistanceRange::kSmall, DistanceRange::kMedium, DistanceRange::kLarge}) {
    for (std::uint64_t i = 0; i < 20; ++i) {
      const PlanningTask task = GenerateTask(scene.scene, range, i, kinematics_);
      ExpectValidTask(task, scene.scene, range);
      EXPECT_EQ(task.scene_seed, 2024u);
      EXPECT_EQ(task.seed, i);
    }
  }
  TaskGeneratorOptions options;
  options.obstacle_margin_m = 0.1;
  const PlanningTask task = GenerateTask(scene.scene, DistanceRange::kSmall, 5, kinematics_,
                                         options);
  const SceneClearanceChecker checker(kinematics_, scene.scene);
  EXPECT_GT(checker.Compute(task.start).obstacle_m(), 0.1);
  EXPECT_GT(checker.Compute(task.goal).obstacle_m(), 0.1);
}

TEST_F(TaskGeneratorTest, ImpossibleRequestsThrow) {
  Scene small_room;
  small_room.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0),
                                              Eigen::Vector3d(5, 5, 1.6));
  // 6 x 6 m of base positions: at most 8.5 m apart, so "large" (15 m) cannot be met.
  EXPECT_THROW(GenerateTask(small_room, DistanceRange::kLarge, 1, kinematics_),
               std::invalid_argument);
  // A room full of one box: no free base pose.
  Scene full = small_room;
  OrientedBox box;
  box.center_W_m = {0, 0, 0.5};
  box.size_m = {10, 10, 1};
  full.boxes.push_back(box);
  TaskGeneratorOptions options;
  options.max_base_pose_tries = 20;
  EXPECT_THROW(GenerateTask(full, DistanceRange::kSmall, 1, kinematics_, options),
               std::runtime_error);
  // An obstacle margin no arm configuration can meet.
  options = {};
  options.self_margin_m = 1.0;
  options.max_arm_tries = 10;
  EXPECT_THROW(
      GenerateBenchmarkCase(SceneKind::kCuboids, DistanceRange::kSmall, 1, kinematics_, options),
      std::runtime_error);
}

}  // namespace
}  // namespace topay
