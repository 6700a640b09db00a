#include "core/planning/goal_candidates.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "core/common/angles.h"
#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/robot/kinematics.h"

namespace topay {
namespace {

class GoalCandidatesTest : public ::testing::Test {
 protected:
  GoalCandidatesTest()
      : model_(LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                              std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml")),
        kinematics_(model_) {}

  // No wall-clock budget: results do not depend on machine load.
  WholeBodyIk MakeIk(int max_solutions = 6) const {
    WholeBodyIkOptions options;
    options.time_budget_s = std::numeric_limits<double>::infinity();
    options.max_solutions = max_solutions;
    return WholeBodyIk(kinematics_, options);
  }

  // A goal state with the arm reaching forward and down (well inside the joint limits).
  WholeBodyState GoalState() const {
    WholeBodyState state;
    state.x_m = 3.0;
    state.y_m = 1.0;
    state.yaw_rad = 0.7;
    state.q_rad.resize(model_.num_joints());
    state.q_rad << 0.3, 0.8, 0.1, 1.2, 0.2, 0.6, 0.1;
    return state;
  }

  WholeBodyState StartState() const {
    WholeBodyState state = GoalState();
    state.x_m = -2.0;
    state.y_m = -1.0;
    state.yaw_rad = -0.4;
    return state;
  }

  void ExpectReachesTarget(const WholeBodyState& state, const Eigen::Isometry3d& X_WE) const {
    const Eigen::Isometry3d X_WE_reached = kinematics_.EndEffectorPose(state);
    EXPECT_LE((X_WE_reached.translation() - X_WE.translation()).norm(), 1e-3);
    EXPECT_LE(Eigen::AngleAxisd(X_WE.linear() * X_WE_reached.linear().transpose()).angle(), 1e-2);
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(GoalCandidatesTest, RanksByTravelAndClearanceAndReachesTheTarget) {
  const WholeBodyIk ik = MakeIk();
  const WholeBodyState start = StartState();
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(GoalState());
  // Clearance grows with distance from a pillar at (3.5, 1.0): ranking must weigh it.
  const StateClearanceFn clearance = [](const WholeBodyState& s) {
    return std::hypot(s.x_m - 3.5, s.y_m - 1.0) - 0.45;
  };
  GoalCandidatesOptions options;
  options.max_candidates = 4;
  const GoalCandidatesResult result =
      FindGoalCandidates(ik, X_WE, start, std::nullopt, clearance, options);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  EXPECT_TRUE(result.failure_reason.empty());
  EXPECT_LE(static_cast<int>(result.candidates.size()), options.max_candidates);
  EXPECT_GE(result.candidates.size(), 2u);
  for (std::size_t i = 0; i < result.candidates.size(); ++i) {
    const GoalCandidate& c = result.candidates[i];
    ExpectReachesTarget(c.state, X_WE);
    EXPECT_FALSE(c.from_hint);
    EXPECT_GT(clearance(c.state), 0.0);
    EXPECT_DOUBLE_EQ(c.clearance_m, clearance(c.state));
    const double travel_m = std::hypot(c.state.x_m - start.x_m, c.state.y_m - start.y_m);
    EXPECT_NEAR(c.base_travel_m, travel_m, 1e-12);
    const double expected_cost =
        options.travel_weight * travel_m +
        options.yaw_weight_m_per_rad * std::abs(WrapAngle(c.state.yaw_rad - start.yaw_rad)) +
        options.clearance_weight * std::max(0.0, options.clearance_saturation_m - c.clearance_m);
    EXPECT_NEAR(c.cost, expected_cost, 1e-12);
    if (i > 0) {
      EXPECT_LE(result.candidates[i - 1].cost, c.cost);
    }
  }
}

TEST_F(GoalCandidatesTest, AValidHintComesFirstEvenIfFartherAway) {
  const WholeBodyIk ik = MakeIk();
  const WholeBodyState start = StartState();
  const WholeBodyState hint = GoalState();
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(hint);
  const GoalCandidatesResult result = FindGoalCandidates(ik, X_WE, start, hint, nullptr);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  ASSERT_GE(result.candidates.size(), 2u);
  EXPECT_TRUE(result.candidates.front().from_hint);
  // The hint is exact, so the IK accepts it as is.
  EXPECT_TRUE(result.candidates.front().state.ToVector().isApprox(hint.ToVector(), 1e-12));
  // The other candidates are ranked among themselves.
  for (std::size_t i = 2; i < result.candidates.size(); ++i) {
    EXPECT_LE(result.candidates[i - 1].cost, result.candidates[i].cost);
  }

  GoalCandidatesOptions by_cost;
  by_cost.hint_first = false;
  by_cost.max_candidates = 6;
  const GoalCandidatesResult ranked = FindGoalCandidates(ik, X_WE, start, hint, nullptr, by_cost);
  ASSERT_TRUE(ranked.success());
  for (std::size_t i = 1; i < ranked.candidates.size(); ++i) {
    EXPECT_LE(ranked.candidates[i - 1].cost, ranked.candidates[i].cost);
  }
}

// A start a few centimetres off the goal (finding 29): a candidate at the start's base pose,
// found from the start's joints with the arm alone, ranked first by travel (no hint).
TEST_F(GoalCandidatesTest, AStartWithinReachGivesACandidateWhereItStands) {
  const WholeBodyIk ik = MakeIk();
  WholeBodyState start = GoalState();
  start.x_m += 0.04;
  start.yaw_rad -= 0.3;
  start.q_rad(0) += 0.2;
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(GoalState());
  const GoalCandidatesResult result = FindGoalCandidates(ik, X_WE, start, std::nullopt, nullptr);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  const GoalCandidate& first = result.candidates.front();
  EXPECT_TRUE(first.base_stays);
  EXPECT_EQ(first.base_travel_m, 0.0);
  EXPECT_EQ(first.state.x_m, start.x_m);
  EXPECT_EQ(first.state.y_m, start.y_m);
  EXPECT_EQ(first.state.yaw_rad, start.yaw_rad);
  ExpectReachesTarget(first.state, X_WE);

  GoalCandidatesOptions without;
  without.standing_candidate = false;
  const GoalCandidatesResult other = FindGoalCandidates(ik, X_WE, start, std::nullopt, nullptr, without);
  ASSERT_TRUE(other.success()) << other.failure_reason;
  for (const GoalCandidate& candidate : other.candidates) EXPECT_FALSE(candidate.base_stays);
}

// Finding 29's third case: a goal whose wrist angle (joint 7, +-6.28 rad) is a turn away from
// the start's. Every candidate, the hint's too, is on the turn nearest the start (the same
// pose, the least travel): none has another turn within the limits that is nearer.
TEST_F(GoalCandidatesTest, CandidatesLieOnTheWristTurnNearestTheStart) {
  const WholeBodyIk ik = MakeIk();
  WholeBodyState goal = GoalState();
  goal.q_rad(6) = 5.9;
  WholeBodyState start = StartState();
  start.q_rad(6) = -5.5;
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(goal);
  const GoalCandidatesResult result = FindGoalCandidates(ik, X_WE, start, goal, nullptr);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  ASSERT_TRUE(result.candidates.front().from_hint);
  EXPECT_NEAR(result.candidates.front().state.q_rad(6), 5.9 - 2.0 * std::numbers::pi, 1e-9);
  const double q7_max = model_.joint_limits.q_max_rad(6);
  for (const GoalCandidate& candidate : result.candidates) {
    ExpectReachesTarget(candidate.state, X_WE);
    const double q7 = candidate.state.q_rad(6);
    for (double other : {q7 - 2.0 * std::numbers::pi, q7 + 2.0 * std::numbers::pi}) {
      if (std::abs(other) <= q7_max) {
        EXPECT_GE(std::abs(other - start.q_rad(6)), std::abs(q7 - start.q_rad(6)));
      }
    }
  }
}

TEST_F(GoalCandidatesTest, AHintInCollisionIsNotReturned) {
  const WholeBodyIk ik = MakeIk();
  const WholeBodyState hint = GoalState();
  const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(hint);
  // Everything within 0.5 m of the hint's base is blocked.
  const StateClearanceFn clearance = [&hint](const WholeBodyState& s) {
    return std::hypot(s.x_m - hint.x_m, s.y_m - hint.y_m) - 0.5;
  };
  const GoalCandidatesResult result =
      FindGoalCandidates(ik, X_WE, StartState(), hint, clearance);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  for (const GoalCandidate& c : result.candidates) {
    EXPECT_GT(clearance(c.state), 0.0);
    ExpectReachesTarget(c.state, X_WE);
  }
}

TEST_F(GoalCandidatesTest, BadInputGivesAReasonNotACrash) {
  const WholeBodyIk ik = MakeIk();
  const WholeBodyState start = StartState();
  // Out of reach: 3 m above the floor.
  Eigen::Isometry3d X_WE_high = Eigen::Isometry3d::Identity();
  X_WE_high.translation() << 1.0, 1.0, 3.0;
  GoalCandidatesResult result = FindGoalCandidates(ik, X_WE_high, start, std::nullopt, nullptr);
  EXPECT_FALSE(result.success());
  EXPECT_NE(result.failure_reason.find("reach"), std::string::npos) << result.failure_reason;

  // NaN in the target.
  Eigen::Isometry3d X_WE_nan = kinematics_.EndEffectorPose(GoalState());
  X_WE_nan.translation().x() = std::numeric_limits<double>::quiet_NaN();
  result = FindGoalCandidates(ik, X_WE_nan, start, std::nullopt, nullptr);
  EXPECT_FALSE(result.success());
  EXPECT_NE(result.failure_reason.find("bad input"), std::string::npos) << result.failure_reason;

  // NaN in the start (the reference base pose).
  WholeBodyState bad_start = start;
  bad_start.yaw_rad = std::numeric_limits<double>::quiet_NaN();
  result = FindGoalCandidates(ik, kinematics_.EndEffectorPose(GoalState()), bad_start,
                              std::nullopt, nullptr);
  EXPECT_FALSE(result.success());
  EXPECT_NE(result.failure_reason.find("NaN"), std::string::npos) << result.failure_reason;

  // Everything in collision.
  result = FindGoalCandidates(ik, kinematics_.EndEffectorPose(GoalState()), start, std::nullopt,
                              [](const WholeBodyState&) { return -1.0; });
  EXPECT_FALSE(result.success());
  EXPECT_NE(result.failure_reason.find("clearance"), std::string::npos) << result.failure_reason;
}

TEST_F(GoalCandidatesTest, RejectsBadOptionsByName) {
  GoalCandidatesOptions options;
  options.max_candidates = 0;
  try {
    CheckGoalCandidatesOptions(options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("max_candidates"), std::string::npos);
  }
  options = GoalCandidatesOptions();
  options.clearance_weight = -1.0;
  EXPECT_THROW(CheckGoalCandidatesOptions(options), std::invalid_argument);
}

}  // namespace
}  // namespace topay
