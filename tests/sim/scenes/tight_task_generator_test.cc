#include "sim/scenes/tight_task_generator.h"

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/planning/base_reachability.h"
#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_generator.h"
#include "sim/scenes/task_json.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

TaskGeneratorOptions TightOptions() {
  TaskGeneratorOptions options;
  options.tightness = TaskTightness::kTight;
  return options;
}

class TightTaskGeneratorTest : public ::testing::Test {
 protected:
  TightTaskGeneratorTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  // Checks, with a fresh exact checker (no cutoff), what a tight end must be, and that the
  // generator's record of it is right.
  void ExpectTightEnd(const SceneClearanceChecker& checker, const Scene& scene,
                      const WholeBodyState& state, const TightEnd& end,
                      const TaskGeneratorOptions& options) {
    const SceneClearance clearance = checker.Compute(state);
    EXPECT_TRUE(clearance.IsCollisionFree(options.obstacle_margin_m, options.self_margin_m))
        << "base " << clearance.base_m << " spheres " << clearance.spheres_m << " self "
        << clearance.self_m << " chassis " << clearance.chassis_m;
    EXPECT_GT(clearance.obstacle_m(), options.obstacle_margin_m);
    EXPECT_LE(clearance.obstacle_m(), options.tight_clearance_max_m);
    EXPECT_DOUBLE_EQ(end.clearance_m, clearance.obstacle_m());
    const bool base = clearance.base_m <= clearance.spheres_m;
    EXPECT_EQ(end.body, base ? TightBody::kBase : TightBody::kArm);
    EXPECT_EQ(end.box, base ? clearance.base_box : clearance.sphere_box);
    // The base region (2 m from the room's border), joint limits, the 1e-6 grid.
    EXPECT_GE(state.x_m, -8.0);
    EXPECT_LE(state.x_m, 8.0);
    EXPECT_GE(state.y_m, -8.0);
    EXPECT_LE(state.y_m, 8.0);
    EXPECT_EQ(state.x_m, std::round(state.x_m * 1e6) / 1e6);
    ASSERT_EQ(state.num_joints(), model_.num_joints());
    EXPECT_TRUE((state.q_rad.array() >= model_.joint_limits.q_min_rad.array()).all());
    EXPECT_TRUE((state.q_rad.array() <= model_.joint_limits.q_max_rad.array()).all());
    // Above the floor, the end effector inside the bounds.
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(state, &cache);
    for (std::size_t s = 0; s < model_.spheres.size(); ++s) {
      EXPECT_GE(cache.p_WS[s].z() - model_.spheres[s].radius_m, 0.0) << "sphere " << s;
    }
    EXPECT_TRUE(scene.bounds_W_m.contains(cache.X_WE.translation()));
    // Not shut in a pocket the robot could not have driven into, nor behind a gap within
    // the passage clearance of the base's width: proven able to leave the window.
    BaseOpennessOptions openness;
    openness.clearance_m = options.tight_passage_clearance_m;
    openness.approach_radius_m = options.tight_approach_radius_m;
    const Eigen::Vector2d p_WB(state.x_m, state.y_m);
    EXPECT_FALSE(CertifyBaseOpen(scene, kinematics_, p_WB, options.tight_pocket_window_m,
                                 openness)
                     .certified_unreachable);
    EXPECT_FALSE(CertifyBaseEnclosed(scene, kinematics_, p_WB, options.tight_pocket_window_m)
                     .certified_unreachable);
  }

  void ExpectValidTightCase(const BenchmarkCase& c, DistanceRange range,
                            const TaskGeneratorOptions& options) {
    const PlanningTask& task = c.task;
    ASSERT_TRUE(task.tight.has_value());
    const SceneClearanceChecker checker(kinematics_, c.scene.scene);
    // The goal's base is one the start's can reach (passages with a centimetre to spare).
    BaseOpennessOptions openness;
    openness.clearance_m = options.tight_passage_clearance_m;
    openness.approach_radius_m = options.tight_approach_radius_m;
    if (options.tight_pocket_window_m > 0.0) {
      EXPECT_TRUE(ProvenBaseRegion(c.scene.scene, kinematics_,
                                   Eigen::Vector2d(task.start.x_m, task.start.y_m), openness)
                      .Reaches(Eigen::Vector2d(task.goal.x_m, task.goal.y_m)));
    }
    {
      SCOPED_TRACE("start");
      ExpectTightEnd(checker, c.scene.scene, task.start, task.tight->start, options);
    }
    {
      SCOPED_TRACE("goal");
      ExpectTightEnd(checker, c.scene.scene, task.goal, task.tight->goal, options);
    }
    const double distance = std::hypot(task.goal.x_m - task.start.x_m,
                                       task.goal.y_m - task.start.y_m);
    EXPECT_EQ(task.base_distance_m, distance);
    EXPECT_TRUE(DistanceRangeBounds(range).Contains(distance)) << distance;
    EXPECT_EQ(task.range, range);
    EXPECT_TRUE(kinematics_.EndEffectorPose(task.goal).matrix().isApprox(task.X_WE_goal.matrix(),
                                                                         1e-12));
  }

  BenchmarkCase Generate(SceneKind kind, DistanceRange range, std::uint64_t seed,
                         const TaskGeneratorOptions& options = TightOptions()) {
    return GenerateBenchmarkCase(kind, range, seed, kinematics_, options);
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(TightTaskGeneratorTest, SameSeedSameCaseDifferentSeedDifferentCase) {
  const BenchmarkCase a = Generate(SceneKind::kTables, DistanceRange::kMedium, 7);
  const BenchmarkCase b = Generate(SceneKind::kTables, DistanceRange::kMedium, 7);
  const BenchmarkCase c = Generate(SceneKind::kTables, DistanceRange::kMedium, 8);
  EXPECT_EQ(SceneToJson(a.scene.scene, &a.scene.roles), SceneToJson(b.scene.scene, &b.scene.roles));
  EXPECT_EQ(TaskToJson(a.task), TaskToJson(b.task));
  EXPECT_NE(TaskToJson(a.task), TaskToJson(c.task));
  // The scene is the benchmark scene of DeriveSeed(seed, 1) without keep-out regions.
  const GeneratedScene plain = GenerateTablesScene(DeriveSeed(7, 1));
  EXPECT_EQ(SceneToJson(a.scene.scene, &a.scene.roles), SceneToJson(plain.scene, &plain.roles));
  // The task file reads back as the same task, tightness included.
  const PlanningTask read = TaskFromJson(TaskToJson(a.task), "tight.json", model_.num_joints());
  EXPECT_EQ(read.start.ToVector(), a.task.start.ToVector());
  EXPECT_EQ(read.goal.ToVector(), a.task.goal.ToVector());
  ASSERT_TRUE(read.tight.has_value());
  for (const auto& [r, w] : {std::pair(read.tight->start, a.task.tight->start),
                             std::pair(read.tight->goal, a.task.tight->goal)}) {
    EXPECT_EQ(r.clearance_m, w.clearance_m);
    EXPECT_EQ(r.box, w.box);
    EXPECT_EQ(r.body, w.body);
  }
  EXPECT_EQ(read.tight->goal_kind, a.task.tight->goal_kind);
  EXPECT_EQ(read.tight->goal_table_top, a.task.tight->goal_table_top);
  EXPECT_EQ(a.task.seed, 7u);
  EXPECT_EQ(a.task.scene_seed, DeriveSeed(7, 1));
}

TEST_F(TightTaskGeneratorTest, EveryEndIsExactlyClearAndTightInEveryRange) {
  for (const DistanceRange range :
       {DistanceRange::kSmall, DistanceRange::kMedium, DistanceRange::kLarge}) {
    for (std::uint64_t i = 0; i < 8; ++i) {
      const SceneKind kind = i % 2 == 0 ? SceneKind::kCuboids : SceneKind::kTables;
      SCOPED_TRACE(std::string(DistanceRangeName(range)) + " case " + std::to_string(i));
      const BenchmarkCase c = Generate(kind, range, DeriveSeed(77, i));
      ExpectValidTightCase(c, range, TightOptions());
      if (kind == SceneKind::kCuboids) {
        EXPECT_EQ(c.task.tight->goal_kind, TightGoalKind::kNearBox);  // no table tops
        EXPECT_EQ(c.task.tight->goal_table_top, -1);
      }
    }
  }
}

TEST_F(TightTaskGeneratorTest, AMarginAndATighterBoundAreMet) {
  TaskGeneratorOptions options = TightOptions();
  options.obstacle_margin_m = 0.01;
  options.tight_clearance_max_m = 0.02;
  for (std::uint64_t i = 0; i < 4; ++i) {
    const SceneKind kind = i % 2 == 0 ? SceneKind::kCuboids : SceneKind::kTables;
    SCOPED_TRACE("case " + std::to_string(i));
    ExpectValidTightCase(Generate(kind, DistanceRange::kSmall, 300 + i, options),
                         DistanceRange::kSmall, options);
  }
}

TEST_F(TightTaskGeneratorTest, TablesGoalsOnAndUnderATableTopMeetTheirCondition) {
  std::map<TightGoalKind, int> kinds;
  const int cases = 24;
  for (int i = 0; i < cases; ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    const BenchmarkCase c = Generate(SceneKind::kTables, DistanceRange::kSmall, 500 + i);
    ExpectValidTightCase(c, DistanceRange::kSmall, TightOptions());
    const TightTaskInfo& info = *c.task.tight;
    ++kinds[info.goal_kind];
    if (info.goal_kind == TightGoalKind::kNearBox) {
      EXPECT_EQ(info.goal_table_top, -1);
      continue;
    }
    ASSERT_GE(info.goal_table_top, 0);
    ASSERT_LT(info.goal_table_top, static_cast<int>(c.scene.roles.size()));
    EXPECT_EQ(c.scene.roles[info.goal_table_top], BoxRole::kTableTop);
    // The end-effector point in the top's frame: inside its footprint, and above its upper
    // face by 0.02-0.15 m (on) or between the floor and its lower face (under).
    const OrientedBox& top = c.scene.scene.boxes[info.goal_table_top];
    const Eigen::Vector3d p_B = top.ToBoxFrame(c.task.X_WE_goal.translation());
    const Eigen::Vector3d half = top.HalfSize();
    EXPECT_LE(std::abs(p_B.x()), half.x());
    EXPECT_LE(std::abs(p_B.y()), half.y());
    if (info.goal_kind == TightGoalKind::kOnTable) {
      EXPECT_GE(p_B.z() - half.z(), 0.02);
      EXPECT_LE(p_B.z() - half.z(), 0.15);
    } else {
      EXPECT_LT(p_B.z(), -half.z());
      EXPECT_GT(c.task.X_WE_goal.translation().z(), 0.0);
    }
  }
  // Half of the goals on or under a table (table_goal_fraction 0.5), drawn per task: for
  // these seeds every kind occurs.
  EXPECT_GT(kinds[TightGoalKind::kNearBox], 0);
  EXPECT_GT(kinds[TightGoalKind::kOnTable], 0);
  EXPECT_GT(kinds[TightGoalKind::kUnderTable], 0);
}

TEST_F(TightTaskGeneratorTest, AllGoalsOnTablesWithFractionOneNoneWithZero) {
  TaskGeneratorOptions options = TightOptions();
  for (const double fraction : {0.0, 1.0}) {
    options.table_goal_fraction = fraction;
    for (std::uint64_t i = 0; i < 3; ++i) {
      const BenchmarkCase c = Generate(SceneKind::kTables, DistanceRange::kSmall, 40 + i, options);
      EXPECT_EQ(c.task.tight->goal_kind == TightGoalKind::kNearBox, fraction == 0.0)
          << TightGoalKindName(c.task.tight->goal_kind);
    }
  }
}

TEST_F(TightTaskGeneratorTest, WithoutThePocketCheckSomeEndsAreShutBetweenTableLegs) {
  // Table legs 0.65-1.15 m apart and a base 0.80 m wide: a base drawn under a table can be
  // shut in. These seeds give such ends without the check (and none with it, see
  // ExpectTightEnd).
  TaskGeneratorOptions options = TightOptions();
  options.tight_pocket_window_m = 0.0;
  int shut = 0;
  for (std::uint64_t i = 0; i < 5; ++i) {
    const BenchmarkCase c = Generate(SceneKind::kTables, DistanceRange::kMedium, DeriveSeed(1, i),
                                     options);
    for (const WholeBodyState* state : {&c.task.start, &c.task.goal}) {
      shut += CertifyBaseEnclosed(c.scene.scene, kinematics_,
                                  Eigen::Vector2d(state->x_m, state->y_m), 2.0)
                  .certified_unreachable
                  ? 1
                  : 0;
    }
  }
  EXPECT_GT(shut, 0);
}

// Tables large, seed DeriveSeed(2, 5) (topay-bench --scene tables --range large --tight
// --seed 2, task 5): its first scene holds no tight start with a near-box goal in range.
TEST_F(TightTaskGeneratorTest, ASceneWithoutATightTaskIsReplacedByAFreshOne) {
  const std::uint64_t seed = DeriveSeed(2, 5);
  TaskGeneratorOptions one_scene = TightOptions();
  one_scene.max_tight_scene_tries = 1;
  try {
    Generate(SceneKind::kTables, DistanceRange::kLarge, seed, one_scene);
    ADD_FAILURE() << "the first scene was expected to hold no tight task";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("in each of 1 scene(s)"), std::string::npos)
        << e.what();
  }
  const BenchmarkCase c = Generate(SceneKind::kTables, DistanceRange::kLarge, seed);
  ExpectValidTightCase(c, DistanceRange::kLarge, TightOptions());
  EXPECT_EQ(c.task.seed, seed);
  EXPECT_NE(c.task.scene_seed, DeriveSeed(seed, 1));
  EXPECT_EQ(c.task.scene_seed, c.scene.scene.seed);
  TaskGeneratorOptions none = TightOptions();
  none.max_tight_scene_tries = 0;
  EXPECT_THROW(Generate(SceneKind::kTables, DistanceRange::kLarge, seed, none),
               std::invalid_argument);
}

TEST(GoalKindHoldsTest, OnAndUnderATableTop) {
  OrientedBox top;
  top.center_W_m = {1.0, 2.0, 0.775};  // upper face 0.8, lower face 0.75
  top.size_m = {1.0, 0.6, 0.05};
  top.yaw_rad = std::numbers::pi / 2;  // footprint 0.6 along x, 1.0 along y
  const TaskGeneratorOptions o;
  const auto holds = [&](TightGoalKind kind, double x, double y, double z) {
    return GoalKindHolds(kind, top, Eigen::Vector3d(x, y, z), o, 0.0);
  };
  EXPECT_TRUE(holds(TightGoalKind::kOnTable, 1.0, 2.0, 0.9));
  EXPECT_TRUE(holds(TightGoalKind::kOnTable, 1.25, 2.45, 0.83));
  EXPECT_FALSE(holds(TightGoalKind::kOnTable, 1.0, 2.0, 0.81));  // 1 cm above: too low
  EXPECT_FALSE(holds(TightGoalKind::kOnTable, 1.0, 2.0, 0.96));  // 16 cm: too high
  EXPECT_FALSE(holds(TightGoalKind::kOnTable, 1.4, 2.0, 0.9));   // outside in x (yawed)
  EXPECT_TRUE(holds(TightGoalKind::kOnTable, 1.0, 2.45, 0.9));   // inside in y (yawed)
  EXPECT_TRUE(holds(TightGoalKind::kUnderTable, 1.0, 2.0, 0.5));
  EXPECT_FALSE(holds(TightGoalKind::kUnderTable, 1.0, 2.0, 0.76));  // inside the top
  EXPECT_FALSE(holds(TightGoalKind::kUnderTable, 1.0, 2.0, -0.01));  // below the floor
  EXPECT_FALSE(holds(TightGoalKind::kUnderTable, 1.0, 2.6, 0.5));    // outside the footprint
  EXPECT_TRUE(holds(TightGoalKind::kNearBox, 5.0, 5.0, 5.0));
}

TEST_F(TightTaskGeneratorTest, BadOptionsAndImpossibleSearchesThrow) {
  const GeneratedScene scene = GenerateCuboidsScene(3);
  const auto with = [](void (*change)(TaskGeneratorOptions*)) {
    TaskGeneratorOptions o = TightOptions();
    change(&o);
    return o;
  };
  const TaskGeneratorOptions bad[] = {
      with([](TaskGeneratorOptions* o) { o->tight_clearance_max_m = 0.0; }),
      with([](TaskGeneratorOptions* o) {
        o->obstacle_margin_m = 0.06;  // above the 0.05 bound
      }),
      with([](TaskGeneratorOptions* o) { o->table_goal_fraction = 1.5; }),
      with([](TaskGeneratorOptions* o) { o->tight_arm_tries = 0; }),
      with([](TaskGeneratorOptions* o) { o->tight_base_spread_m = -0.1; }),
      with([](TaskGeneratorOptions* o) {
        o->on_table_height_min_m = 0.2;  // above the max
      }),
  };
  for (const TaskGeneratorOptions& o : bad) {
    EXPECT_THROW(GenerateTightTask(scene, DistanceRange::kSmall, 1, kinematics_, o),
                 std::invalid_argument);
  }
  GeneratedScene no_roles = scene;
  no_roles.roles.pop_back();
  EXPECT_THROW(GenerateTightTask(no_roles, DistanceRange::kSmall, 1, kinematics_),
               std::invalid_argument);
  // GenerateTask has no roles to draw tight ends near.
  EXPECT_THROW(GenerateTask(scene.scene, DistanceRange::kSmall, 1, kinematics_, TightOptions()),
               std::invalid_argument);
  // A bound no drawn state meets in a tiny budget.
  TaskGeneratorOptions tiny = TightOptions();
  tiny.tight_clearance_max_m = 1e-9;
  tiny.tight_arm_tries = 2;
  tiny.max_tight_base_tries = 2;
  tiny.max_tight_pair_tries = 2;
  try {
    GenerateTightTask(scene, DistanceRange::kSmall, 1, kinematics_, tiny);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("seed 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay
