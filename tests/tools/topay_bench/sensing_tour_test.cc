// The sensing tours of topay-bench's sensed maps (tools/topay_bench/sensing_tour.h).
#include "tools/topay_bench/sensing_tour.h"

#include <cmath>

#include <gtest/gtest.h>

#include "tests/common/make_box.h"

namespace topay::bench {
namespace {

PlanningTask Task(double x0, double y0, double x1, double y1) {
  PlanningTask t;
  t.start.x_m = x0;
  t.start.y_m = y0;
  t.start.yaw_rad = 0.3;
  t.start.q_rad = Eigen::VectorXd::LinSpaced(7, 0.1, 0.7);
  t.goal = t.start;
  t.goal.x_m = x1;
  t.goal.y_m = y1;
  t.goal.yaw_rad = -1.0;
  t.goal.q_rad.setZero();
  return t;
}

TEST(SensingTourTest, TheLineRunsFromTheStartToTheGoalWithTheStartsArm) {
  const Scene empty;
  const PlanningTask task = Task(-4.0, 0.0, 4.0, 0.0);
  const std::vector<WholeBodyState> states = SensingTourStates(empty, task, {.line_step_m = 1.0});
  ASSERT_EQ(states.size(), 9u);  // start, 7 between, goal
  EXPECT_EQ(states.front().yaw_rad, 0.3);
  for (std::size_t k = 1; k + 1 < states.size(); ++k) {
    EXPECT_NEAR(states[k].x_m, -4.0 + static_cast<double>(k), 1e-12);
    EXPECT_NEAR(states[k].yaw_rad, 0.0, 1e-12);  // along the line
    EXPECT_EQ(states[k].q_rad, task.start.q_rad);
  }
  EXPECT_EQ(states.back().x_m, 4.0);
  EXPECT_EQ(states.back().yaw_rad, -1.0);
  EXPECT_EQ(states.back().q_rad, task.start.q_rad);
}

TEST(SensingTourTest, PosesWhereTheBaseCannotStandAreLeftOut) {
  Scene scene;
  scene.boxes.push_back(MakeBox({0.0, 0.0, 0.5}, {1.0, 1.0, 1.0}));   // on the line
  scene.boxes.push_back(MakeBox({2.0, 0.0, 1.8}, {1.0, 1.0, 0.2}));   // above the robot: harmless
  const std::vector<WholeBodyState> states =
      SensingTourStates(scene, Task(-4.0, 0.0, 4.0, 0.0), {.line_step_m = 1.0, .footprint_radius_m = 0.35});
  // x = 0 is inside the box's footprint ([-0.5, 0.5]); x = +-1 are 0.5 m from it, clear; x = 2
  // is under a box above the robot's height, clear.
  ASSERT_EQ(states.size(), 8u);
  for (const WholeBodyState& s : states) EXPECT_GT(std::abs(s.x_m), 0.85) << s.x_m;
}

TEST(SensingTourTest, TheTourAddsAGridOverTheRoom) {
  const Scene empty;
  const PlanningTask task = Task(-4.0, 0.0, 4.0, 0.0);
  const auto line = SensingTourStates(empty, task, {.kind = SensingTourKind::kLine});
  const auto tour = SensingTourStates(empty, task, {.kind = SensingTourKind::kTour, .grid_per_axis = 3, .grid_inset_m = 2.0});
  ASSERT_EQ(tour.size(), line.size() + 9);
  EXPECT_EQ(tour[line.size()].x_m, -8.0);
  EXPECT_EQ(tour[line.size()].y_m, -8.0);
  EXPECT_EQ(tour.back().x_m, 8.0);
  EXPECT_EQ(tour.back().y_m, 8.0);
  EXPECT_EQ(ParseSensingTourKind("tour"), SensingTourKind::kTour);
  EXPECT_EQ(SensingTourKindName(SensingTourKind::kLine), "line");
  EXPECT_FALSE(ParseSensingTourKind("spiral"));
}

}  // namespace
}  // namespace topay::bench
