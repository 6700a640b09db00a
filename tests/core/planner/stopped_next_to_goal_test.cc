// A robot stopped next to its goal (finding 29, docs/reliability.md): in the fault campaign a
// lost drive heartbeat stopped the robot 0.4 s before the end of its trajectory to a pickup,
// 4 cm and 0.33 rad from the goal's base pose, its base 2.6 cm from a table leg's voxels, its
// arm reaching over the table top. Every plan from rest then failed ("no arm path"): the base
// paths left the tight spot and came back (0.37 m, turns in place up to 2.7 rad), and where
// the base stood it could not turn towards the goal at all. The planner now also tries the
// goal where the robot stands, with the arm alone (a standing candidate, the base sequence
// given time for the arm, the optimizer restarted if the duration collapses).
//
// tests/data/maps/finding29_map.json: the planner's voxel boxes within 2.5 m of the robot in
// that run (its own footprint cleared, as the planner clears it for a plan from rest); load
// it with `topay-plan --scene-file` to look at it.

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/io/planner_config.h"
#include "core/io/robot_loader.h"
#include "core/planner/plan_in_scene.h"
#include "core/robot/kinematics.h"
#include "tests/common/make_box.h"
#include "tests/common/sanitizer_build.h"

namespace topay {
namespace {

Scene LoadMapScene(const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json json = nlohmann::json::parse(in);
  Scene scene;
  scene.kind = "map";
  const auto& b = json.at("bounds");
  scene.bounds_W_m = Eigen::AlignedBox3d(
      Eigen::Vector3d(b.at("min").at(0).get<double>(), b.at("min").at(1).get<double>(), b.at("min").at(2).get<double>()),
      Eigen::Vector3d(b.at("max").at(0).get<double>(), b.at("max").at(1).get<double>(), b.at("max").at(2).get<double>()));
  const auto vector3 = [](const nlohmann::json& v) {
    return Eigen::Vector3d(v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>());
  };
  for (const auto& box : json.at("boxes")) {
    scene.boxes.push_back(MakeBox(vector3(box.at("center")), vector3(box.at("size"))));
  }
  return scene;
}

WholeBodyState State(double x, double y, double yaw, std::initializer_list<double> q) {
  WholeBodyState state;
  state.x_m = x;
  state.y_m = y;
  state.yaw_rad = yaw;
  state.q_rad.resize(static_cast<Eigen::Index>(q.size()));
  int i = 0;
  for (double v : q) state.q_rad(i++) = v;
  return state;
}

class StoppedNextToGoalTest : public ::testing::Test {
 protected:
  StoppedNextToGoalTest()
      : model_(LoadRobotModel(TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf",
                              TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        scene_(LoadMapScene(TOPAY_SOURCE_DIR "/tests/data/maps/finding29_map.json")) {}

  // The shipped planner options with the robot's limits, as the planner process plans; the
  // time limits generous: the outcome is tested here, not the speed (docs/benchmarks.md).
  WholeBodyPlannerOptions Options() const {
    WholeBodyPlannerOptions options = LoadPlannerOptions(TOPAY_SOURCE_DIR "/config/planner/topay.yaml");
    options.base_limits = model_.base_limits;
    options.time_limit_s = 20.0 * testing::kBuildSlowdown;
    options.optimizer.time_limit_s *= testing::kBuildSlowdown;  // 2 s, ended it under ASan
    options.front_end.acquisition_budget_s *= testing::kBuildSlowdown;
    return options;
  }

  // Where the robot stood (the ROBOT_STATE of the campaign's log) and its goal.
  const WholeBodyState start_ = State(2.542303, -1.776927, -1.563879,
                                      {-0.925797, -0.137792, 1.823221, 1.000736, -0.684505, 0.739296, -5.587509});
  const WholeBodyState hint_ = State(2.506295641515098, -1.8032438422677117, -1.2285254281788411,
                                     {-1.1197114772602268, -0.21820439148347917, 1.7567991503990474,
                                      0.9618798510431747, -0.6857929099304676, 0.8287649548962587,
                                      -5.526693018228671});
  const Eigen::Isometry3d X_WE_goal_ = [] {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = Eigen::Quaterniond(0.4154081157704333, 0.5742283319417993, 0.42185824114223736,
                                    -0.5654498603128089).normalized().toRotationMatrix();
    X.translation() = Eigen::Vector3d(2.685446547668378, -2.0704298046552654, 0.7695826718647235);
    return X;
  }();

  RobotModel model_;
  Kinematics kinematics_;
  Scene scene_;
};

// The chosen candidate, validated.
const CandidateReport& ExpectValidated(const ScenePlan& plan) {
  EXPECT_TRUE(plan.result.success()) << plan.result.failure_reason;
  if (!plan.result.success() || plan.result.chosen < 0) throw std::runtime_error("no plan");
  const CandidateReport& chosen = plan.result.candidates[plan.result.chosen];
  EXPECT_TRUE(chosen.validation.has_value() && chosen.validation->ok);
  return chosen;
}

void ExpectFinishedWithTheArmAlone(const ScenePlan& plan) {
  const CandidateReport& chosen = ExpectValidated(plan);
  const BasePath& base = plan.result.front_end.paths[chosen.path_index].base_path;
  EXPECT_EQ(base.source, BasePathSource::kStanding);
  EXPECT_EQ(base.length_m, 0.0);
  std::printf("%s\n", chosen.optimization.Report().c_str());
}

TEST_F(StoppedNextToGoalTest, PlansFromWhereItStoppedWithTheArmAlone) {
  const ScenePlan plan = PlanInScene(kinematics_, scene_, Options(), start_, X_WE_goal_);
  ExpectFinishedWithTheArmAlone(plan);
  EXPECT_TRUE(plan.result.front_end.stats.standing_base_path);
}

// The mission sends its goal with the hint it planned the first time: that goal's base pose
// is 4 cm away, and the base paths there leave the tight spot and come back. Before the
// other-way turns (finding 29's third case, below) none had an arm path and the standing
// candidate, after the hint, was planned; now the hint's own goal is reached that way.
TEST_F(StoppedNextToGoalTest, PlansFromWhereItStoppedWithTheMissionsHint) {
  const ScenePlan plan = PlanInScene(kinematics_, scene_, Options(), start_, X_WE_goal_, hint_);
  ExpectValidated(plan);
}

// What the optimizer's restart does there: without it the standing candidate's optimization
// collapsed (the duration shrank towards 0 with the end effector 2.5 cm off target).
TEST_F(StoppedNextToGoalTest, WithoutTheOptimizerRestartTheStandingCandidateCollapses) {
  WholeBodyPlannerOptions options = Options();
  options.optimizer.max_collapse_restarts = 0;
  options.retry.max_rounds = 1;
  const ScenePlan plan = PlanInScene(kinematics_, scene_, options, start_, X_WE_goal_);
  ASSERT_FALSE(plan.result.candidates.empty()) << plan.result.failure_reason;
  const BackEndSummary& first = plan.result.candidates.front().optimization;
  std::printf("%s\n", first.Report().c_str());
  EXPECT_EQ(first.status, BackEndStatus::kNotConverged);
  EXPECT_LT(first.duration_s, 0.01);
  EXPECT_GT(first.ee_position_error_m, 0.01);
}

// Finding 29's third case, on the same map: a drive fault stopped the robot 0.3 s after it
// left the pickup for the drop-off, its arm still out over the table. Its base escape is
// straight back, so every base path began with a half turn in place (3.1416 rad: the way
// round decided by the start yaw's last milliradians), and that way swept the arm through the
// table: no arm path, plan after plan. Tried the other way round too (other_way_turn_min_rad),
// the arm clears the table at once. The target here is behind the robot as the drop-off was.
class StoppedWithTheArmOverTheTableTest : public StoppedNextToGoalTest {
 protected:
  const WholeBodyState start_over_table_ =
      State(2.47403405, -1.76545509, -1.63972551, {-0.641774, -0.288659, 1.690748, 0.927928, -0.629314, 0.883198, -5.517302});
  const Eigen::Isometry3d X_WE_behind_ = [] {
    Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
    X.linear() = Eigen::Quaterniond(-0.242232728, -0.585451702, -0.189031317, 0.750224481).normalized().toRotationMatrix();
    X.translation() = Eigen::Vector3d(2.3, 0.3, 0.8);
    return X;
  }();
};

TEST_F(StoppedWithTheArmOverTheTableTest, PlansWithTheHalfTurnTheOtherWayRound) {
  const ScenePlan plan = PlanInScene(kinematics_, scene_, Options(), start_over_table_, X_WE_behind_);
  const CandidateReport& chosen = ExpectValidated(plan);
  // The chosen path turns the longer way: more than half a turn at the start.
  const FrontEndPath& path = plan.result.front_end.paths[chosen.path_index];
  EXPECT_GT(std::abs(StartTurnRad(path.base_sequence)), 3.1416);
}

TEST_F(StoppedWithTheArmOverTheTableTest, OnlyTheShorterWayRoundFindsNoArmPath) {
  WholeBodyPlannerOptions options = Options();
  options.front_end.other_way_turn_min_rad = std::numeric_limits<double>::infinity();
  options.retry.max_rounds = 1;
  const ScenePlan plan = PlanInScene(kinematics_, scene_, options, start_over_table_, X_WE_behind_);
  EXPECT_FALSE(plan.result.success());
  EXPECT_NE(plan.result.failure_reason.find("no arm path"), std::string::npos) << plan.result.failure_reason;
}

}  // namespace
}  // namespace topay
