// Issue 18: planning from a moving start. Random moving starts taken along earlier planned
// trajectories (plan, pick t0, StateAt(t0), replan to another goal): every new trajectory is
// accepted by the validator (with the start's rates) and joins the old one C2; the stopping
// trajectory from the same t0 stops on the old path within the limits.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/common/expect_same_motion.h"

#include "core/common/random.h"
#include "core/common/sample_statistics.h"
#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planner/stopping_trajectory.h"
#include "core/planner/whole_body_planner.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/arc_yaw_sampling.h"
#include "core/trajectory/arc_yaw_state_at.h"
#include "tests/common/arm_state.h"
#include "tests/common/make_box.h"

namespace topay {
namespace {

class MovingStartTest : public ::testing::Test {
 protected:
  MovingStartTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        scene_(Room()),
        fields_(BuildSceneDistanceFields(scene_, PlannerFieldOptions(kinematics_))),
        planner_(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_, Options()) {}

  // A 10 x 10 m room with a pillar in the middle and a floating box.
  static Scene Room() {
    Scene scene;
    scene.kind = "moving start test";
    scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(0, 0, 0.75), Eigen::Vector3d(1.0, 1.0, 1.5)));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(-1.5, 2.5, 1.2), Eigen::Vector3d(0.5, 0.5, 0.4)));
    return scene;
  }

  static WholeBodyPlannerOptions Options() {
    WholeBodyPlannerOptions options;
    BaseLimits limits;
    limits.omega_max_radps = 1.25;  // the paper's simulation benchmark
    options.base_limits = limits;
    options.time_limit_s = 20.0;  // generous: the tests run in parallel on loaded cores
    options.optimizer.time_limit_s = 10.0;
    options.front_end.acquisition_budget_s = 5.0;
    return options;
  }

  // A goal: the end-effector pose of the bent arm on a base at a random place of the room,
  // clear of the pillar and the walls.
  WholeBodyState RandomGoal(Rng* rng) const {
    for (;;) {
      const double x = rng->Uniform(-3.8, 3.8), y = rng->Uniform(-3.8, 3.8);
      if (std::abs(x) < 1.6 && std::abs(y) < 1.6) continue;
      if (std::hypot(x + 1.5, y - 2.5) < 1.3) continue;  // under the floating box
      return BentArmState(x, y, rng->Uniform(-3.1, 3.1));
    }
  }

  // The new trajectory at 0 against the old one at t0, by value and by central differences
  // across the join (old before t0, new after; s of the new one offset by s_old(t0)).
  static void ExpectC2Join(const ArcYawTrajectory& old, double t0, const ArcYawTrajectory& next) {
    TrajectorySample a = old.MakePoint(), b = next.MakePoint();
    old.Evaluate(t0, &a);
    next.Evaluate(0.0, &b);
    testing::ExpectSameMotion(a, b, 1e-9, 1e-8);
    // Across the join: first and second central differences of s, yaw, q, x, y from the old
    // trajectory at t0 - h and the new one at +h match the rates at the join (O(h^2) + jerk
    // and snap jumps of O(h)).
    if (t0 < 2e-3) return;
    const double h = 1e-3;
    TrajectorySample before = old.MakePoint(), after = next.MakePoint();
    old.Evaluate(t0 - h, &before);
    next.Evaluate(h, &after);
    const double s_before = before.s_m - a.s_m, s_after = after.s_m;  // relative to the join
    EXPECT_NEAR((s_after - s_before) / (2 * h), a.v_mps, 1e-3);
    EXPECT_NEAR((s_after + s_before) / (h * h), a.a_mps2, 2e-2);
    EXPECT_NEAR((after.state.yaw_rad - before.state.yaw_rad) / (2 * h), a.omega_radps, 1e-3);
    EXPECT_NEAR((after.state.yaw_rad - 2 * a.state.yaw_rad + before.state.yaw_rad) / (h * h),
                a.beta_radps2, 2e-2);
    const Eigen::VectorXd qd = (after.state.q_rad - before.state.q_rad) / (2 * h);
    const Eigen::VectorXd qdd =
        (after.state.q_rad - 2 * a.state.q_rad + before.state.q_rad) / (h * h);
    EXPECT_LT((qd - a.qd_radps).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_LT((qdd - a.qdd_radps2).cwiseAbs().maxCoeff(), 2e-2);
    // x' = s' cos yaw, y' = s' sin yaw (eqs. (1)-(2)).
    EXPECT_NEAR((after.state.x_m - before.state.x_m) / (2 * h), a.v_mps * std::cos(a.state.yaw_rad),
                1e-3);
    EXPECT_NEAR((after.state.y_m - before.state.y_m) / (2 * h), a.v_mps * std::sin(a.state.yaw_rad),
                1e-3);
  }

  struct ChainFigures {
    int tasks = 0;
    int successes = 0;
    int lead_in_collisions = 0;
    double max_speed_mps = 0.0;
    std::vector<double> moving_ms, rest_ms;
  };

  // `tasks` replans, each from a moving state on the last validated trajectory.
  ChainFigures RunChain(int tasks, std::uint64_t seed, bool time_rest_too) {
    Rng rng(seed);
    ChainFigures figures;
    const WholeBodyState first_goal = BentArmState(3.0, 0.5, 1.0);
    WholeBodyPlanResult first = planner_.Plan(BentArmState(-3.0, 0.0, 0.0),
                                              kinematics_.EndEffectorPose(first_goal), first_goal);
    EXPECT_TRUE(first.success()) << first.Report();
    if (!first.success()) return figures;
    ArcYawTrajectory current = *first.trajectory;
    const TrajectoryValidator validator(kinematics_, scene_, planner_.base_limits());
    for (int task = 0; task < tasks; ++task) {
      SCOPED_TRACE("task " + std::to_string(task));
      const double t0 = rng.Uniform(0.1, 0.9) * current.duration_s();
      const MovingState start = ArcYawStateAt(current, t0);
      figures.max_speed_mps = std::max(figures.max_speed_mps, std::abs(start.rates.v_mps));
      const WholeBodyState goal = RandomGoal(&rng);
      const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal);
      // The stopping trajectory from the same t0.
      const StoppingTrajectory stop = MakeStoppingTrajectory(
          current, t0, planner_.base_limits(), model_.joint_limits);
      EXPECT_TRUE(stop.success()) << stop.reason;
      if (stop.success()) {
        EXPECT_LE(stop.max_path_deviation_m, 0.005);
        ExpectC2Join(current, t0, *stop.trajectory);
        TrajectorySample end = stop.trajectory->MakePoint();
        stop.trajectory->Evaluate(stop.duration_s, &end);
        const ValidationReport check = validator.Validate(
            SampleArcYaw(*stop.trajectory), start, kinematics_.EndEffectorPose(end.state));
        EXPECT_TRUE(check.ok) << check.Report();
      }
      ++figures.tasks;
      const WholeBodyPlanResult result = planner_.Plan(start, X_WE, goal);
      if (time_rest_too) {
        const WholeBodyPlanResult rest = planner_.Plan(start.state, X_WE, goal);
        if (rest.success()) figures.rest_ms.push_back(rest.timings.total_ms);
      }
      if (!result.success()) {
        std::printf("task %d (v %.2f m/s): %s\n", task, start.rates.v_mps,
                    result.failure_reason.c_str());
        if (result.failure_reason.rfind("moving start: the lead-in", 0) == 0) {
          ++figures.lead_in_collisions;
        }
        continue;
      }
      ++figures.successes;
      figures.moving_ms.push_back(result.timings.total_ms);
      const ValidationReport check =
          validator.Validate(SampleArcYaw(*result.trajectory), start, X_WE);
      EXPECT_TRUE(check.ok) << check.Report();
      ExpectC2Join(current, t0, *result.trajectory);
      current = *result.trajectory;
    }
    return figures;
  }

  static void Print(const char* what, std::vector<double> ms) {
    if (ms.empty()) return;
    std::sort(ms.begin(), ms.end());
    const auto at = [&](double f) { return ms[std::min<std::size_t>(ms.size() - 1, f * ms.size())]; };
    std::printf("%s: %zu plans, T.P. median %.0f ms, p95 %.0f ms\n", what, ms.size(), at(0.5),
                at(0.95));
  }

  RobotModel model_;
  Kinematics kinematics_;
  Scene scene_;
  SceneDistanceFields fields_;
  WholeBodyPlanner planner_;
};

TEST_F(MovingStartTest, AFewReplansFromMovingStatesJoinC2AndValidate) {
  const ChainFigures figures = RunChain(4, 18, false);
  EXPECT_EQ(figures.tasks, 4);
  EXPECT_GE(figures.successes, 3);
  EXPECT_GT(figures.max_speed_mps, 0.2);  // the starts do move
}

// Long (label long/...): 100 replans; at least 90 % succeed (a lead-in into an obstacle is a
// legitimate refusal, reported).
TEST_F(MovingStartTest, HundredReplansFromMovingStatesJoinC2AndValidate) {
  const ChainFigures figures = RunChain(100, 1818, true);
  std::printf("%d of %d replans from moving states succeeded (%d lead-in collisions), max "
              "|v| %.2f m/s\n",
              figures.successes, figures.tasks, figures.lead_in_collisions,
              figures.max_speed_mps);
  Print("moving", figures.moving_ms);
  Print("rest (same states and goals, zero rates)", figures.rest_ms);
  EXPECT_EQ(figures.tasks, 100);
  EXPECT_GE(figures.successes, 90);
}

TEST_F(MovingStartTest, AStartAtRestPlansAsBefore) {
  const WholeBodyState goal = BentArmState(3.0, 0.5, 1.0);
  MovingState start;
  start.state = BentArmState(-3.0, 0.0, 0.0);
  const WholeBodyPlanResult result =
      planner_.Plan(start, kinematics_.EndEffectorPose(goal), goal);
  ASSERT_TRUE(result.success()) << result.Report();
  TrajectorySample s = result.trajectory->MakePoint();
  result.trajectory->Evaluate(0.0, &s);
  EXPECT_EQ(s.v_mps, 0.0);
  EXPECT_EQ(s.a_mps2, 0.0);
}

TEST_F(MovingStartTest, ALeadInIntoThePillarFailsWithAReason) {
  MovingState start;
  // Driving at the pillar (face at x = -0.5) at 1 m/s: 0.725 m to stop, the base (r 0.4)
  // 0.6 m from it.
  start.state = BentArmState(-1.5, 0.0, 0.0);
  start.rates = WholeBodyRates::Zero(7);
  start.rates.v_mps = 1.0;
  const WholeBodyState goal = BentArmState(-3.0, 0.5, 1.0);
  const WholeBodyPlanResult result =
      planner_.Plan(start, kinematics_.EndEffectorPose(goal), goal);
  EXPECT_FALSE(result.success());
  EXPECT_EQ(result.status, PlanStatus::kFrontEndFailed);
  EXPECT_EQ(result.failure_reason.rfind("moving start: the lead-in", 0), 0u)
      << result.failure_reason;
}

}  // namespace
}  // namespace topay
