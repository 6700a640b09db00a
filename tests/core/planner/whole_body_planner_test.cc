#include "core/planner/whole_body_planner.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <stop_token>
#include <string>

#include <gtest/gtest.h>

#include "tests/common/arm_state.h"

#include "core/io/robot_loader.h"
#include "core/map/scene_distance_fields.h"
#include "core/planning/planner_fields.h"
#include "core/robot/kinematics.h"
#include "core/trajectory/arc_yaw_sampling.h"
#include "tests/common/make_box.h"
#include "tests/common/sanitizer_build.h"

namespace topay {
namespace {

class WholeBodyPlannerTest : public ::testing::Test {
 protected:
  WholeBodyPlannerTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        scene_(PillarRoom()),
        fields_(BuildSceneDistanceFields(scene_, PlannerFieldOptions(kinematics_))) {}

  // A 10 x 10 m room with one pillar between start and goal, and a floating box.
  static Scene PillarRoom() {
    Scene scene;
    scene.kind = "planner test";
    scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(0, 0, 0.75), Eigen::Vector3d(1.0, 1.0, 1.5)));
    scene.boxes.push_back(MakeBox(Eigen::Vector3d(-1.5, 2.5, 1.2), Eigen::Vector3d(0.5, 0.5, 0.4)));
    return scene;
  }

  WholeBodyState State(double x, double y, double yaw) const { return BentArmState(x, y, yaw); }

  static WholeBodyPlannerOptions Options() {
    WholeBodyPlannerOptions options;
    BaseLimits limits;
    limits.omega_max_radps = 1.25;  // the paper's simulation benchmark
    options.base_limits = limits;
    // Generous: the tests run in parallel on loaded cores (and slower in sanitizer builds).
    options.time_limit_s = 20.0 * testing::kBuildSlowdown;
    options.optimizer.time_limit_s = 10.0 * testing::kBuildSlowdown;
    options.front_end.acquisition_budget_s = 5.0 * testing::kBuildSlowdown;
    return options;
  }

  RobotModel model_;
  Kinematics kinematics_;
  Scene scene_;
  SceneDistanceFields fields_;
};

TEST_F(WholeBodyPlannerTest, PlansAValidatedTrajectoryAroundThePillar) {
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 Options());
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal);
  const WholeBodyPlanResult result = planner.Plan(start, X_WE, goal);
  std::cout << result.Report();
  ASSERT_TRUE(result.success()) << result.Report();
  ASSERT_TRUE(result.trajectory.has_value());
  ASSERT_GE(result.chosen, 0);
  EXPECT_TRUE(result.failure_reason.empty());

  // Checked again here by a validator of our own (exact boxes, 10 ms, limits + 1 %).
  BaseLimits limits = *Options().base_limits;
  const TrajectoryValidator validator(kinematics_, scene_, limits);
  const ValidationReport check = validator.Validate(SampleArcYaw(*result.trajectory), start, X_WE);
  EXPECT_TRUE(check.ok) << check.Report();
  EXPECT_LE(check.end_position_error_m, 0.01);
  EXPECT_LE(check.end_orientation_error_rad, 0.02);
  EXPECT_GT(check.min_obstacle.clearance_m, 0.0);
  // The chosen trajectory is the shortest validated one.
  for (const CandidateReport& c : result.candidates) {
    if (c.validated()) {
      EXPECT_LE(result.candidates[result.chosen].optimization.duration_s,
                c.optimization.duration_s);
    }
  }
  ASSERT_TRUE(result.sampled.has_value());
  EXPECT_NEAR(result.sampled->duration_s, result.trajectory->duration_s(), 1e-9);
  EXPECT_NEAR(result.trajectory->duration_s(),
              result.candidates[result.chosen].optimization.duration_s, 1e-9);
  EXPECT_GT(result.timings.total_ms, 0.0);
  EXPECT_GE(result.timings.total_ms, result.timings.front_end_ms);
}

TEST_F(WholeBodyPlannerTest, SequentialModeRunsEveryCandidate) {
  WholeBodyPlannerOptions options = Options();
  options.sequential = true;
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 options);
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const WholeBodyPlanResult result =
      planner.Plan(start, kinematics_.EndEffectorPose(goal), goal);
  ASSERT_TRUE(result.success()) << result.Report();
  ASSERT_EQ(result.candidates.size(),
            std::min<std::size_t>(options.max_candidates, result.front_end.paths.size()));
  for (const CandidateReport& c : result.candidates) EXPECT_TRUE(c.started);
  // Sequential: no early termination, so no candidate was cut by the window, and the stages
  // add up to no more than the whole.
  for (const CandidateReport& c : result.candidates) {
    EXPECT_NE(c.optimization.status, BackEndStatus::kCancelled);
  }
  EXPECT_GT(result.timings.optimization_ms, 0.0);
  EXPECT_LE(result.timings.front_end_ms + result.timings.optimization_ms + result.timings.wait_ms,
            result.timings.total_ms + 1e-6);
}

// The flatness baseline behind the same planner: it may fail (it is a baseline), but cleanly,
// and anything it reports as a success passed the validator.
TEST_F(WholeBodyPlannerTest, FlatnessBaselineRunsBehindTheSamePlanner) {
  WholeBodyPlannerOptions options = Options();
  options.optimizer.parameterisation = TrajectoryParameterisation::kFlatness;
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 options);
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal);
  const WholeBodyPlanResult result = planner.Plan(start, X_WE, goal);
  std::cout << result.Report();
  EXPECT_TRUE(result.status == PlanStatus::kSuccess ||
              result.status == PlanStatus::kOptimizationFailed)
      << result.Report();
  EXPECT_FALSE(result.trajectory.has_value());  // not an arc length-yaw trajectory
  if (result.success()) {
    ASSERT_TRUE(result.sampled.has_value());
    const TrajectoryValidator validator(kinematics_, scene_, *Options().base_limits);
    EXPECT_TRUE(validator.Validate(*result.sampled, start, X_WE).ok);
  } else {
    EXPECT_FALSE(result.failure_reason.empty());
  }
}

TEST_F(WholeBodyPlannerTest, BadInputAndUnreachableTargetsFailWithAReason) {
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 Options());
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal);

  WholeBodyState nan_start = start;
  nan_start.q_rad(3) = std::numeric_limits<double>::quiet_NaN();
  const WholeBodyPlanResult nan_result = planner.Plan(nan_start, X_WE);
  EXPECT_EQ(nan_result.status, PlanStatus::kInvalidInput) << nan_result.Report();
  EXPECT_NE(nan_result.failure_reason.find("start"), std::string::npos) << nan_result.failure_reason;
  EXPECT_FALSE(nan_result.trajectory.has_value());

  Eigen::Isometry3d high = X_WE;
  high.translation().z() = 3.0;  // out of the arm's reach
  const WholeBodyPlanResult unreachable = planner.Plan(start, high);
  EXPECT_EQ(unreachable.status, PlanStatus::kFrontEndFailed) << unreachable.Report();
  EXPECT_NE(unreachable.failure_reason.find("outside the room"), std::string::npos)
      << unreachable.failure_reason;  // above the scene bounds' 1.6 m

  Eigen::Isometry3d inside = X_WE;
  inside.translation() << 0.0, 0.0, 0.8;  // inside the pillar
  const WholeBodyPlanResult blocked = planner.Plan(start, inside);
  EXPECT_EQ(blocked.status, PlanStatus::kFrontEndFailed) << blocked.Report();
  std::cout << unreachable.failure_reason << "\n" << blocked.failure_reason << "\n";
  EXPECT_NE(blocked.failure_reason.find("inside box 0 "), std::string::npos)
      << blocked.failure_reason;
}

// A start in collision names the box and the body; a joint out of its limits names the joint.
TEST_F(WholeBodyPlannerTest, AnInvalidStartNamesTheCause) {
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 Options());
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(State(3.0, 0.5, 1.0));
  const WholeBodyPlanResult in_pillar = planner.Plan(State(0.7, 0.0, 0.0), X_WE);
  EXPECT_NE(in_pillar.status, PlanStatus::kSuccess);
  EXPECT_NE(in_pillar.failure_reason.find("the base"), std::string::npos)
      << in_pillar.failure_reason;
  EXPECT_NE(in_pillar.failure_reason.find("penetrates box 0 "), std::string::npos)
      << in_pillar.failure_reason;

  WholeBodyState bent = State(-3.0, 0.0, 0.0);
  bent.q_rad(2) = model_.joint_limits.q_max_rad(2) + 0.5;
  const WholeBodyPlanResult out_of_limits = planner.Plan(bent, X_WE);
  std::cout << in_pillar.failure_reason << "\n" << out_of_limits.failure_reason << "\n";
  EXPECT_NE(out_of_limits.status, PlanStatus::kSuccess);
  EXPECT_NE(out_of_limits.failure_reason.find("joint '" + model_.joint_names[2] + "'"),
            std::string::npos)
      << out_of_limits.failure_reason;
}

TEST_F(WholeBodyPlannerTest, StopBeforeTheStartCancels) {
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 Options());
  const WholeBodyState start = State(-3.0, 0.0, 0.0);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  std::stop_source stop;
  stop.request_stop();
  const WholeBodyPlanResult result =
      planner.Plan(start, kinematics_.EndEffectorPose(goal), goal, stop.get_token());
  EXPECT_EQ(result.status, PlanStatus::kCancelled) << result.Report();
  EXPECT_FALSE(result.trajectory.has_value());
}

// Retry rounds (PlanRetryOptions): a round without a validated trajectory is followed by
// another with other seeds, up to max_rounds, and the reason lists the earlier rounds. Here
// the target lies inside a walled enclosure the base cannot enter: every round finds goal
// states only inside it, and no base path.
TEST_F(WholeBodyPlannerTest, ARoundWithoutBasePathIsRetriedUpToMaxRounds) {
  Scene walled = PillarRoom();
  const Eigen::Vector3d c(3.0, -3.0, 0.75);  // a 2.4 m square of 1.5 m walls around (3, -3)
  walled.boxes.push_back(MakeBox(c + Eigen::Vector3d(1.2, 0, 0), Eigen::Vector3d(0.1, 2.5, 1.5)));
  walled.boxes.push_back(MakeBox(c - Eigen::Vector3d(1.2, 0, 0), Eigen::Vector3d(0.1, 2.5, 1.5)));
  walled.boxes.push_back(MakeBox(c + Eigen::Vector3d(0, 1.2, 0), Eigen::Vector3d(2.5, 0.1, 1.5)));
  walled.boxes.push_back(MakeBox(c - Eigen::Vector3d(0, 1.2, 0), Eigen::Vector3d(2.5, 0.1, 1.5)));
  const SceneDistanceFields fields =
      BuildSceneDistanceFields(walled, PlannerFieldOptions(kinematics_));
  WholeBodyPlannerOptions options = Options();
  options.retry.min_time_left_s = 0.0;
  const WholeBodyPlanner planner(kinematics_, fields.base_field_2d, fields.field_3d, walled,
                                 options);
  // The end effector of the robot standing at the enclosure's centre.
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(State(3.0, -3.0, 0.0));
  const WholeBodyPlanResult result = planner.Plan(State(-3.0, 0.0, 0.0), X_WE);
  std::cout << result.Report();
  EXPECT_EQ(result.status, PlanStatus::kFrontEndFailed);
  EXPECT_EQ(result.front_end.status, FrontEndStatus::kNoBasePath);
  EXPECT_EQ(result.rounds, 3);
  EXPECT_EQ(result.margin_level, 0);  // no validator rejection
  EXPECT_NE(result.failure_reason.find("(after 3 rounds; round 1: no_base_path; round 2: "
                                       "no_base_path)"),
            std::string::npos)
      << result.failure_reason;

  options.retry.max_rounds = 1;  // the paper: one round
  const WholeBodyPlanner once(kinematics_, fields.base_field_2d, fields.field_3d, walled,
                              options);
  const WholeBodyPlanResult single = once.Plan(State(-3.0, 0.0, 0.0), X_WE);
  EXPECT_EQ(single.front_end.status, FrontEndStatus::kNoBasePath);
  EXPECT_EQ(single.rounds, 1);
  EXPECT_EQ(single.failure_reason.find("rounds"), std::string::npos) << single.failure_reason;

  options.retry.max_rounds = 3;
  options.retry.min_time_left_s = 1e6;  // more than the time limit: no time for a retry
  const WholeBodyPlanner hurried(kinematics_, fields.base_field_2d, fields.field_3d, walled,
                                 options);
  EXPECT_EQ(hurried.Plan(State(-3.0, 0.0, 0.0), X_WE).rounds, 1);
}

// After a validator rejection the next round's back end has wider clearance margins.
TEST_F(WholeBodyPlannerTest, AValidatorRejectionRaisesTheNextRoundsMargins) {
  WholeBodyPlannerOptions options = Options();
  options.validator.ee_position_tolerance_m = 1e-9;  // every optimizer success is rejected
  options.retry.min_time_left_s = 0.0;
  options.retry.max_rounds = 2;
  const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                 options);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const WholeBodyPlanResult result =
      planner.Plan(State(-3.0, 0.0, 0.0), kinematics_.EndEffectorPose(goal), goal);
  std::cout << result.Report();
  EXPECT_EQ(result.status, PlanStatus::kOptimizationFailed);
  EXPECT_EQ(result.rounds, 2);
  EXPECT_EQ(result.margin_level, 1);
  EXPECT_NE(result.failure_reason.find("round 1: "), std::string::npos) << result.failure_reason;
  EXPECT_NE(result.failure_reason.find("rejected by the validator"), std::string::npos)
      << result.failure_reason;
}

// Rounds after the first, from a start at rest, start the optimizer from the warm start slowed
// by retry.warm_start_slowdown: more time, hence more pieces, than the same round's warm start at
// the full rates (every success rejected, so that a second round runs).
TEST_F(WholeBodyPlannerTest, LaterRoundsStartTheOptimizerFromASlowerWarmStart) {
  WholeBodyPlannerOptions options = Options();
  options.validator.ee_position_tolerance_m = 1e-9;  // every optimizer success is rejected
  options.retry.min_time_left_s = 0.0;
  options.retry.max_rounds = 2;
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const auto second_round_pieces = [&](double slowdown, double v_start_mps) {
    options.retry.warm_start_slowdown = slowdown;
    const WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                   options);
    MovingState start{State(-3.0, 0.0, 0.0), WholeBodyRates::Zero(model_.num_joints())};
    start.rates.v_mps = v_start_mps;
    const WholeBodyPlanResult result =
        planner.Plan(start, kinematics_.EndEffectorPose(goal), goal);
    EXPECT_EQ(result.rounds, 2) << result.Report();
    EXPECT_FALSE(result.candidates.empty()) << result.Report();
    return result.candidates.empty() ? 0 : result.candidates[0].optimization.num_pieces;
  };
  const int same = second_round_pieces(1.0, 0.0);
  const int slower = second_round_pieces(0.6, 0.0);
  EXPECT_GT(same, 0);
  EXPECT_GT(slower, same);
  // A moving start keeps the configured warm start in every round.
  EXPECT_EQ(second_round_pieces(0.6, 0.5), second_round_pieces(1.0, 0.5));
}

// No further round after a failure no seed can change (a start in collision, a target
// inside a box).
TEST_F(WholeBodyPlannerTest, NoRetryForABadStartOrAHopelessTarget) {
  WholeBodyPlannerOptions options = Options();
  options.retry.min_time_left_s = 0.0;
  const WholeBodyPlanner retrying(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_,
                                  options);
  const WholeBodyState goal = State(3.0, 0.5, 1.0);
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal);
  const WholeBodyPlanResult in_pillar = retrying.Plan(State(0.7, 0.0, 0.0), X_WE, goal);
  EXPECT_EQ(in_pillar.front_end.status, FrontEndStatus::kStartInvalid);
  EXPECT_EQ(in_pillar.rounds, 1);
  // A target inside a box: no seed finds a goal there.
  Eigen::Isometry3d inside = X_WE;
  inside.translation() << 0.0, 0.0, 0.8;
  const WholeBodyPlanResult hopeless = retrying.Plan(State(-3.0, 0.0, 0.0), inside);
  EXPECT_EQ(hopeless.status, PlanStatus::kFrontEndFailed);
  EXPECT_EQ(hopeless.rounds, 1) << hopeless.failure_reason;
  EXPECT_NE(hopeless.failure_reason.find("inside box 0 "), std::string::npos)
      << hopeless.failure_reason;
}

TEST_F(WholeBodyPlannerTest, RejectsBadOptionsByName) {
  WholeBodyPlannerOptions options = Options();
  options.max_candidates = 0;
  try {
    WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_, options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_candidates"), std::string::npos) << e.what();
  }
  options = Options();
  options.time_limit_s = 0.0;
  EXPECT_THROW(WholeBodyPlanner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_, options),
               std::invalid_argument);
  options = Options();
  options.retry.max_rounds = 0;
  try {
    WholeBodyPlanner planner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_, options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("retry.max_rounds"), std::string::npos) << e.what();
  }
  options = Options();
  options.retry.clearance_step_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(WholeBodyPlanner(kinematics_, fields_.base_field_2d, fields_.field_3d, scene_, options),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
