#include "core/planner/deterministic_options.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/trajectory_sample.h"
#include "tests/common/make_box.h"

namespace topay {
namespace {

TEST(MakeDeterministicTest, ReplacesEveryWallClockBudgetByWork) {
  WholeBodyPlannerOptions options;
  DeterministicBudgets budgets;
  budgets.prm_samples = 1234;
  budgets.rrt_iterations = 567;
  MakeDeterministic(&options, budgets);
  EXPECT_EQ(options.num_threads, 1);
  EXPECT_EQ(options.early_termination_window_s, 0.0);
  EXPECT_EQ(options.front_end.num_threads, 1);
  EXPECT_TRUE(std::isinf(options.front_end.ik.time_budget_s));
  EXPECT_LE(options.front_end.topology.prm.max_time_s, 0.0);
  EXPECT_EQ(options.front_end.topology.prm.max_samples, 1234);
  EXPECT_TRUE(std::isinf(options.front_end.rrt.time_budget_s));
  EXPECT_EQ(options.front_end.rrt.max_iterations, 567);
  EXPECT_TRUE(std::isinf(options.front_end.improvement_window_s));
  EXPECT_TRUE(std::isinf(options.front_end.acquisition_budget_s));
  EXPECT_EQ(options.optimizer.time_limit_s, options.time_limit_s);  // only the plan's bound
  EXPECT_EQ(options.retry.round_time_share, 1.0);  // rounds not cut by their share of time
  EXPECT_EQ(options.retry.min_time_left_s, 0.0);
  EXPECT_NO_THROW(CheckWholeBodyPlannerOptions(options));
}

// Two plans of one query with deterministic options agree in everything but timings.
TEST(MakeDeterministicTest, RepeatedPlansAgree) {
  const RobotModel model = LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                                          TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml");
  const Kinematics kinematics(model);
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
  scene.boxes.push_back(MakeBox(Eigen::Vector3d(0, 0, 0.75), Eigen::Vector3d(1.0, 1.0, 1.5)));
  scene.boxes.push_back(MakeBox(Eigen::Vector3d(0.5, 2.5, 0.3), Eigen::Vector3d(0.6, 1.0, 0.6)));
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(scene, PlannerFieldOptions(kinematics));
  WholeBodyPlannerOptions options;
  options.time_limit_s = 60.0;  // far from binding: only work budgets end this plan
  options.optimizer.time_limit_s = 30.0;
  MakeDeterministic(&options);
  const WholeBodyPlanner planner(kinematics, fields.base_field_2d, fields.field_3d, scene,
                                 options);
  WholeBodyState start;
  start.x_m = -3.0;
  start.q_rad = Eigen::VectorXd::Zero(model.num_joints());
  start.q_rad << 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1;
  WholeBodyState goal = start;
  goal.x_m = 3.0;
  goal.y_m = 0.5;
  goal.yaw_rad = 1.0;
  const Eigen::Isometry3d X_WE = kinematics.EndEffectorPose(goal);

  const WholeBodyPlanResult a = planner.Plan(start, X_WE);  // no hint: the IK runs too
  const WholeBodyPlanResult b = planner.Plan(start, X_WE);
  ASSERT_TRUE(a.success()) << a.Report();
  ASSERT_TRUE(b.success()) << b.Report();
  EXPECT_EQ(a.front_end.paths.size(), b.front_end.paths.size());
  EXPECT_EQ(a.front_end.stats.rrt_iterations, b.front_end.stats.rrt_iterations);
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  for (std::size_t i = 0; i < a.candidates.size(); ++i) {
    EXPECT_EQ(a.candidates[i].started, b.candidates[i].started) << "candidate " << i;
    EXPECT_EQ(a.candidates[i].optimization.duration_s, b.candidates[i].optimization.duration_s)
        << "candidate " << i;
  }
  EXPECT_EQ(a.chosen, b.chosen);
  ASSERT_TRUE(a.sampled.has_value() && b.sampled.has_value());
  EXPECT_EQ(a.sampled->duration_s, b.sampled->duration_s);
  TrajectorySample end_a = MakeTrajectorySample(model.num_joints());
  TrajectorySample end_b = MakeTrajectorySample(model.num_joints());
  a.sampled->make_sampler()(a.sampled->duration_s, &end_a);
  b.sampled->make_sampler()(b.sampled->duration_s, &end_b);
  EXPECT_EQ(end_a.state.x_m, end_b.state.x_m);
  EXPECT_EQ(end_a.state.y_m, end_b.state.y_m);
  EXPECT_EQ(end_a.state.q_rad, end_b.state.q_rad);
}

}  // namespace
}  // namespace topay
