#include "core/robot/whole_body_ik.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/angles.h"
#include "core/common/random.h"
#include "core/io/robot_loader.h"
#include "core/robot/joint_turns.h"
#include "core/robot/kinematics.h"
#include "core/robot/self_collision.h"
#include "tests/core/robot/allocation_counter.h"

namespace topay {
namespace {

constexpr double kPositionTolerance_m = 1e-3;     // the acceptance criteria
constexpr double kOrientationTolerance_rad = 1e-2;

class WholeBodyIkTest : public ::testing::Test {
 protected:
  WholeBodyIkTest()
      : model_(LoadRobotModel(std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
                              std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml")),
        kinematics_(model_),
        self_collision_(kinematics_) {}

  // Options for tests: no wall-clock budget, so results do not depend on machine load.
  static WholeBodyIkOptions TestOptions() {
    WholeBodyIkOptions options;
    options.time_budget_s = std::numeric_limits<double>::infinity();
    return options;
  }

  // Self-collision distance and chassis margin recomputed independently of WholeBodyIk.
  double SelfDistance(const WholeBodyState& state) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(state, &cache);
    Eigen::VectorXd margins(self_collision_.num_spheres());
    self_collision_.ChassisMargins(cache, margins);
    return std::min(self_collision_.MinDistance(cache), margins.minCoeff());
  }

  double SpherePairDistance(const WholeBodyState& state) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(state, &cache);
    return self_collision_.MinDistance(cache);
  }

  // A random whole-body state: base in [-5, 5]^2 m, any yaw, joints uniform within limits,
  // redrawn until free of self-collision (a target from a self-colliding configuration may
  // have no valid solution at all).
  WholeBodyState RandomFreeState(Rng* rng) const {
    WholeBodyState state;
    state.q_rad.resize(model_.num_joints());
    do {
      state.x_m = rng->Uniform(-5.0, 5.0);
      state.y_m = rng->Uniform(-5.0, 5.0);
      state.yaw_rad = rng->Uniform(-std::numbers::pi, std::numbers::pi);
      for (int j = 0; j < model_.num_joints(); ++j) {
        state.q_rad(j) = rng->Uniform(model_.joint_limits.q_min_rad(j),
                                      model_.joint_limits.q_max_rad(j));
      }
    } while (SelfDistance(state) <= 0.0);
    return state;
  }

  // A random free state whose sphere pairs are 5 cm apart: a solution near it need not touch.
  WholeBodyState SpacedFreeState(Rng* rng) const {
    WholeBodyState state;
    do {
      state = RandomFreeState(rng);
    } while (SpherePairDistance(state) < 0.05);
    return state;
  }

  // Every acceptance criterion of a returned solution, recomputed here with FK.
  void ExpectValid(const IkSolution& solution, const Eigen::Isometry3d& X_WE_target) const {
    const WholeBodyState& state = solution.state;
    ASSERT_EQ(state.num_joints(), model_.num_joints());
    ASSERT_TRUE(state.IsFinite());
    const Eigen::Isometry3d X_WE = kinematics_.EndEffectorPose(state);
    const double position_error_m = (X_WE.translation() - X_WE_target.translation()).norm();
    const double orientation_error_rad =
        Eigen::AngleAxisd(X_WE_target.linear() * X_WE.linear().transpose()).angle();
    EXPECT_LE(position_error_m, kPositionTolerance_m);
    EXPECT_LE(orientation_error_rad, kOrientationTolerance_rad);
    EXPECT_NEAR(solution.position_error_m, position_error_m, 1e-12);
    for (int j = 0; j < model_.num_joints(); ++j) {
      EXPECT_GE(state.q_rad(j), model_.joint_limits.q_min_rad(j)) << "joint " << j;
      EXPECT_LE(state.q_rad(j), model_.joint_limits.q_max_rad(j)) << "joint " << j;
    }
    EXPECT_GT(SelfDistance(state), 0.0);
  }

  RobotModel model_;
  Kinematics kinematics_;
  SelfCollision self_collision_;
};

TEST_F(WholeBodyIkTest, DerivesShoulderWristAndReachFromTheModel) {
  const WholeBodyIk ik(kinematics_);
  // Facts sheet: arm mount at (0, 0.115, 0.171) m, d1 = 0.2405 m to the shoulder; the wrist
  // centre d7 = 0.144 m behind the flange (the end-effector frame); reach d3 + d5.
  EXPECT_TRUE(ik.p_BS().isApprox(Eigen::Vector3d(0.0, 0.115, 0.171 + 0.2405), 1e-9));
  EXPECT_TRUE(ik.p_EW().isApprox(Eigen::Vector3d(0.0, 0.0, -0.144), 1e-9));
  EXPECT_NEAR(ik.shoulder_to_wrist_reach_m(), 0.256 + 0.21, 1e-9);
}

// Reachable targets: FK of a random self-collision-free state (joints uniform within limits,
// random base pose). Measured (TOPAY_IK_TEST_TARGETS=2000 TOPAY_IK_TEST_SEED=<s>): 2000 of
// 2000 solved for the seeds 1, 2 and 20240611 with this test's options, and 2000 of 2000 as
// well with max_solutions 1 (seeds 1, 2) and 6 (seed 20240611). With the base free the pose
// is reachable from many base poses, and 16 base poses x 4 restarts always found one; so every
// target must be solved (no slack: a miss is a regression).
TEST_F(WholeBodyIkTest, ReachesRandomTargets) {
  WholeBodyIkOptions options = TestOptions();
  options.max_solutions = 3;
  const WholeBodyIk ik(kinematics_, options);
  const char* seed_env = std::getenv("TOPAY_IK_TEST_SEED");
  const char* targets_env = std::getenv("TOPAY_IK_TEST_TARGETS");
  Rng rng(seed_env ? std::strtoull(seed_env, nullptr, 10) : 20240611);
  const int num_targets = targets_env ? std::atoi(targets_env) : 100;
  int solved = 0, solutions = 0;
  for (int i = 0; i < num_targets; ++i) {
    const WholeBodyState truth = RandomFreeState(&rng);
    const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
    const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr);
    if (result.success()) {
      ++solved;
      EXPECT_TRUE(result.failure_reason.empty());
    } else {
      EXPECT_FALSE(result.failure_reason.empty());
      ADD_FAILURE() << "target " << i << " unsolved: " << result.failure_reason;
    }
    for (const IkSolution& solution : result.solutions) {
      ++solutions;
      ExpectValid(solution, X_WE_target);
    }
  }
  EXPECT_EQ(solved, num_targets);
  EXPECT_GE(solutions, 2 * num_targets);  // several base poses per target (3 asked for)
}

TEST_F(WholeBodyIkTest, RespectsAClearanceFunctionThatForbidsARegion) {
  Rng rng(7);
  WholeBodyIkOptions options = TestOptions();
  options.max_solutions = 8;
  const WholeBodyIk ik(kinematics_, options);
  WholeBodyState truth = RandomFreeState(&rng);
  truth.x_m = 0.0;
  truth.y_m = 0.0;
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
  // Unconstrained, base poses all around the target: some on the forbidden side x < 0
  // (otherwise this test could not fail).
  const WholeBodyIkResult free_result = ik.Solve(X_WE_target, nullptr);
  ASSERT_TRUE(free_result.success()) << free_result.failure_reason;
  int on_forbidden_side = 0;
  for (const IkSolution& solution : free_result.solutions) {
    if (solution.state.x_m <= 0.0) ++on_forbidden_side;
  }
  ASSERT_GT(on_forbidden_side, 0);
  // Clearance = base x: the half plane x <= 0 is in collision.
  int calls = 0;
  const StateClearanceFn clearance = [&calls](const WholeBodyState& state) {
    ++calls;
    return state.x_m;
  };
  const WholeBodyIkResult result = ik.Solve(X_WE_target, clearance);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  EXPECT_GT(calls, 0);
  EXPECT_GT(result.rejected_clearance, 0);
  for (const IkSolution& solution : result.solutions) {
    ExpectValid(solution, X_WE_target);
    EXPECT_GT(solution.state.x_m, 0.0);
    EXPECT_EQ(solution.clearance_m, solution.state.x_m);
  }
}

TEST_F(WholeBodyIkTest, RequiresClearanceAboveTheMinimum) {
  Rng rng(8);
  WholeBodyIkOptions options = TestOptions();
  options.min_clearance_m = 0.5;
  const WholeBodyIk ik(kinematics_, options);
  WholeBodyState truth = RandomFreeState(&rng);
  truth.x_m = 0.6;  // the truth itself has clearance 0.6 m > 0.5 m: a solution exists
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
  const WholeBodyIkResult result =
      ik.Solve(X_WE_target, [](const WholeBodyState& state) { return state.x_m; });
  ASSERT_TRUE(result.success()) << result.failure_reason;
  for (const IkSolution& solution : result.solutions) {
    EXPECT_GT(solution.state.x_m, 0.5);
  }
}

TEST_F(WholeBodyIkTest, ClearanceBlockingEverythingFailsWithAReason) {
  Rng rng(9);
  WholeBodyIkOptions options = TestOptions();
  const WholeBodyIk ik(kinematics_, options);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(RandomFreeState(&rng));
  const WholeBodyIkResult result =
      ik.Solve(X_WE_target, [](const WholeBodyState&) { return -0.1; });
  EXPECT_FALSE(result.success());
  EXPECT_NE(result.failure_reason.find("clearance"), std::string::npos) << result.failure_reason;
  EXPECT_EQ(result.base_candidates_tried, options.max_base_candidates);
  EXPECT_GT(result.rejected_clearance, 0);
  EXPECT_LE(result.dls_runs, 2 * options.max_base_candidates * options.restarts_per_base);
}

TEST_F(WholeBodyIkTest, AValidHintIsReturnedAsIs) {
  Rng rng(10);
  WholeBodyIkOptions options = TestOptions();
  options.max_base_candidates = 0;  // only the hint
  const WholeBodyIk ik(kinematics_, options);
  const WholeBodyState truth = RandomFreeState(&rng);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);

  const WholeBodyIkResult without_hint = ik.Solve(X_WE_target, nullptr);
  EXPECT_FALSE(without_hint.success());
  EXPECT_FALSE(without_hint.failure_reason.empty());

  WholeBodyIkQuery query;
  query.hint = truth;
  const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
  ASSERT_EQ(result.solutions.size(), 1u) << result.failure_reason;
  EXPECT_TRUE(result.hint_used);
  const IkSolution& solution = result.solutions.front();
  EXPECT_TRUE(solution.from_hint);
  EXPECT_EQ(result.dls_runs, 0);  // accepted without iterating
  EXPECT_EQ(solution.state.x_m, truth.x_m);
  EXPECT_EQ(solution.state.y_m, truth.y_m);
  EXPECT_NEAR(solution.state.yaw_rad, truth.yaw_rad, 1e-15);
  EXPECT_EQ(solution.state.q_rad, truth.q_rad);
  ExpectValid(solution, X_WE_target);
}

TEST_F(WholeBodyIkTest, ANearbyHintSeedsTheSolution) {
  Rng rng(11);
  WholeBodyIkOptions options = TestOptions();
  options.max_base_candidates = 0;  // only the hint
  const WholeBodyIk ik(kinematics_, options);
  int used = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const WholeBodyState truth = SpacedFreeState(&rng);
    const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
    WholeBodyIkQuery query;
    query.hint = truth;
    query.hint->x_m += 0.03;
    query.hint->yaw_rad -= 0.05;
    for (int j = 0; j < truth.num_joints(); ++j) query.hint->q_rad(j) += rng.Uniform(-0.1, 0.1);
    const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
    if (!result.success()) {
      ADD_FAILURE() << "trial " << trial << ": " << result.failure_reason;
      continue;
    }
    ++used;
    EXPECT_TRUE(result.hint_used);
    ASSERT_EQ(result.solutions.size(), 1u);
    const IkSolution& solution = result.solutions.front();
    EXPECT_TRUE(solution.from_hint);
    ExpectValid(solution, X_WE_target);
    // The arm-only run keeps the hint's base; the whole-body polish moves it by a few cm at
    // most (no base candidates were sampled).
    EXPECT_LT(std::hypot(solution.state.x_m - query.hint->x_m,
                         solution.state.y_m - query.hint->y_m), 0.1);
  }
  // Measured: 10 of 10 (the perturbation is small next to the arm's reach).
  EXPECT_EQ(used, 10);
}

// A robot standing where it can reach the target with the arm alone (finding 29): the
// standing state seeds one arm-only run, whose solution keeps the base exactly.
TEST_F(WholeBodyIkTest, TheStandingStateGivesASolutionThatKeepsItsBase) {
  Rng rng(29);
  WholeBodyIkOptions options = TestOptions();
  options.max_base_candidates = 0;  // only the standing state
  const WholeBodyIk ik(kinematics_, options);
  int found = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const WholeBodyState truth = SpacedFreeState(&rng);
    const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
    // Standing where the truth stands, the joints off by up to 0.1 rad each: the arm alone
    // reaches the target (a base off the truth's may leave it out of the arm's reach at
    // that orientation: 8 of 10 trials with 3 cm and 0.05 rad off).
    WholeBodyIkQuery query;
    query.standing = truth;
    for (int j = 0; j < truth.num_joints(); ++j) query.standing->q_rad(j) += rng.Uniform(-0.1, 0.1);
    const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
    if (!result.success()) {
      ADD_FAILURE() << "trial " << trial << ": " << result.failure_reason;
      continue;
    }
    ++found;
    ASSERT_EQ(result.solutions.size(), 1u);
    const IkSolution& solution = result.solutions.front();
    EXPECT_TRUE(solution.base_stays);
    EXPECT_FALSE(solution.from_hint);
    ExpectValid(solution, X_WE_target);
    EXPECT_EQ(solution.state.x_m, query.standing->x_m);
    EXPECT_EQ(solution.state.y_m, query.standing->y_m);
    EXPECT_EQ(solution.state.yaw_rad, query.standing->yaw_rad);
  }
  EXPECT_EQ(found, 10);
}

// True if q7 + 2 pi k for some k != 0 lies within joint 7's limits and nearer the reference.
bool FartherThanAnotherTurn(double q7_rad, double reference_rad) {
  constexpr double kLimit = 6.28, kTurn = 2.0 * std::numbers::pi;
  for (int k : {-2, -1, 1, 2}) {
    const double other = q7_rad + k * kTurn;
    if (std::abs(other) <= kLimit && std::abs(other - reference_rad) < std::abs(q7_rad - reference_rad)) return true;
  }
  return false;
}

// Finding 29's third case: the wrist (joint 7, limits +-6.28 rad) reaches a pose on two turns;
// with the robot's joints as reference every solution is on the turn nearest them.
TEST_F(WholeBodyIkTest, SolutionsLieOnTheJointTurnsNearestTheReference) {
  Rng rng(31);
  const WholeBodyIk ik(kinematics_, TestOptions());
  int turned = 0;
  for (int trial = 0; trial < 5; ++trial) {
    WholeBodyState truth = RandomFreeState(&rng);
    truth.q_rad(6) = rng.Uniform(3.5, 6.0);
    const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
    const WholeBodyIkResult free = ik.Solve(X_WE_target, nullptr);
    WholeBodyIkQuery query;
    query.reference_q_rad = Eigen::VectorXd::Constant(model_.num_joints(), 0.0);
    (*query.reference_q_rad)(6) = -5.5;
    const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
    ASSERT_TRUE(result.success()) << "trial " << trial << ": " << result.failure_reason;
    for (const IkSolution& solution : result.solutions) {
      ExpectValid(solution, X_WE_target);
      EXPECT_FALSE(FartherThanAnotherTurn(solution.state.q_rad(6), -5.5)) << "trial " << trial;
    }
    for (const IkSolution& solution : free.solutions) turned += FartherThanAnotherTurn(solution.state.q_rad(6), -5.5);
  }
  EXPECT_GT(turned, 0);  // without the reference some solutions were on the far turn
}

TEST_F(WholeBodyIkTest, AStandingStateOutOfReachGivesNoSolutionOfItsOwn) {
  Rng rng(30);
  WholeBodyIkOptions options = TestOptions();
  options.max_base_candidates = 0;
  const WholeBodyIk ik(kinematics_, options);
  const WholeBodyState truth = RandomFreeState(&rng);
  WholeBodyIkQuery query;
  query.standing = truth;
  query.standing->x_m += 3.0;  // the arm reaches about 1 m
  const WholeBodyIkResult result = ik.Solve(kinematics_.EndEffectorPose(truth), nullptr, query);
  EXPECT_FALSE(result.success());
  EXPECT_EQ(result.dls_runs, 1);
}

TEST_F(WholeBodyIkTest, AnUnhelpfulHintDoesNotPreventSolutions) {
  Rng rng(12);
  const WholeBodyIk ik(kinematics_, TestOptions());
  const WholeBodyState truth = RandomFreeState(&rng);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
  WholeBodyIkQuery query;
  query.hint = truth;
  query.hint->x_m += 10.0;  // far out of reach
  const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
  ASSERT_TRUE(result.success()) << result.failure_reason;
  EXPECT_FALSE(result.hint_used);
  for (const IkSolution& solution : result.solutions) {
    EXPECT_FALSE(solution.from_hint);
    ExpectValid(solution, X_WE_target);
  }
}

TEST_F(WholeBodyIkTest, RanksByBaseTravelFromTheReferenceAndRemovesDuplicates) {
  Rng rng(13);
  WholeBodyIkOptions options = TestOptions();
  options.max_solutions = 8;
  const WholeBodyIk ik(kinematics_, options);
  const WholeBodyState truth = RandomFreeState(&rng);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
  WholeBodyIkQuery query;
  query.reference_base = Eigen::Vector3d(truth.x_m + 3.0, truth.y_m - 1.0, 0.5);
  const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
  ASSERT_GE(result.solutions.size(), 3u) << result.failure_reason;
  for (size_t i = 0; i < result.solutions.size(); ++i) {
    const IkSolution& solution = result.solutions[i];
    ExpectValid(solution, X_WE_target);
    // Free space (null clearance): the cost is the base travel alone.
    const double travel =
        std::hypot(solution.state.x_m - query.reference_base->x(),
                   solution.state.y_m - query.reference_base->y()) +
        options.yaw_travel_weight_m_per_rad *
            std::abs(WrapAngle(solution.state.yaw_rad - query.reference_base->z()));
    EXPECT_NEAR(solution.cost, travel, 1e-12);
    if (i > 0) {
      EXPECT_LE(result.solutions[i - 1].cost, solution.cost);
    }
    for (size_t k = 0; k < i; ++k) {
      const WholeBodyState& other = result.solutions[k].state;
      const bool duplicate =
          std::abs(other.x_m - solution.state.x_m) < options.duplicate_distance_m &&
          std::abs(other.y_m - solution.state.y_m) < options.duplicate_distance_m &&
          std::abs(WrapAngle(other.yaw_rad - solution.state.yaw_rad)) <
              options.duplicate_angle_rad &&
          (other.q_rad - solution.state.q_rad).cwiseAbs().maxCoeff() <
              options.duplicate_angle_rad;
      EXPECT_FALSE(duplicate) << "solutions " << k << " and " << i;
    }
  }
  // The first base pose is sampled on the reference's side of the target: the best solution
  // travels less than the reference's distance to the target's foot point.
  const double reference_to_target =
      (query.reference_base->head<2>() - X_WE_target.translation().head<2>()).norm();
  EXPECT_LT(std::hypot(result.solutions.front().state.x_m - query.reference_base->x(),
                       result.solutions.front().state.y_m - query.reference_base->y()),
            reference_to_target);
}

TEST_F(WholeBodyIkTest, ClearanceEntersTheRankingCost) {
  Rng rng(14);
  WholeBodyIkOptions options = TestOptions();
  options.max_solutions = 8;
  const WholeBodyIk ik(kinematics_, options);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(RandomFreeState(&rng));
  const StateClearanceFn clearance = [](const WholeBodyState& state) {
    return 0.05 + 0.1 * (std::sin(state.x_m) + 1.0);  // in (0.05, 0.25) m, below saturation
  };
  const WholeBodyIkResult result = ik.Solve(X_WE_target, clearance);
  ASSERT_GE(result.solutions.size(), 2u) << result.failure_reason;
  for (size_t i = 0; i < result.solutions.size(); ++i) {
    const IkSolution& solution = result.solutions[i];
    EXPECT_NEAR(solution.clearance_m, clearance(solution.state), 1e-15);
    EXPECT_NEAR(solution.cost,
                options.clearance_weight * (options.clearance_saturation_m - solution.clearance_m),
                1e-12);
    if (i > 0) {  // cheapest first = most clearance first
      EXPECT_LE(solution.clearance_m, result.solutions[i - 1].clearance_m);
    }
  }
}

TEST_F(WholeBodyIkTest, SameSeedSameSolutions) {
  Rng rng(15);
  const WholeBodyIk ik(kinematics_, TestOptions());
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(RandomFreeState(&rng));
  const WholeBodyIkResult a = ik.Solve(X_WE_target, nullptr);
  const WholeBodyIkResult b = ik.Solve(X_WE_target, nullptr);
  ASSERT_TRUE(a.success());
  ASSERT_EQ(a.solutions.size(), b.solutions.size());
  for (size_t i = 0; i < a.solutions.size(); ++i) {
    EXPECT_EQ(a.solutions[i].state.ToVector(), b.solutions[i].state.ToVector());
  }
  WholeBodyIkOptions other_seed = TestOptions();
  other_seed.seed = 99;
  const WholeBodyIkResult c = WholeBodyIk(kinematics_, other_seed).Solve(X_WE_target, nullptr);
  ASSERT_TRUE(c.success());
  EXPECT_NE(a.solutions.front().state.ToVector(), c.solutions.front().state.ToVector());
}

TEST_F(WholeBodyIkTest, RejectsBadTargetsQuicklyWithAReason) {
  Rng rng(16);
  const WholeBodyIk ik(kinematics_, TestOptions());
  const Eigen::Isometry3d good = kinematics_.EndEffectorPose(RandomFreeState(&rng));
  ASSERT_TRUE(ik.Solve(good, nullptr).success());

  std::vector<std::pair<std::string, Eigen::Isometry3d>> bad;
  Eigen::Isometry3d X = good;
  X.translation().x() = std::numeric_limits<double>::quiet_NaN();
  bad.emplace_back("bad input", X);
  X = good;
  X.linear()(1, 2) = std::numeric_limits<double>::infinity();
  bad.emplace_back("bad input", X);
  X = good;
  X.linear() *= 1.1;  // not orthonormal
  bad.emplace_back("not a proper rotation", X);
  X = good;
  X.linear().col(0) *= -1.0;  // a reflection
  bad.emplace_back("not a proper rotation", X);
  X = good;
  X.translation().z() = 5.0;  // 5 m above the ground
  bad.emplace_back("out of reach", X);
  X = good;
  X.translation().z() = -2.0;
  bad.emplace_back("out of reach", X);
  for (const auto& [expected, target] : bad) {
    const WholeBodyIkResult result = ik.Solve(target, nullptr);
    EXPECT_FALSE(result.success()) << expected;
    EXPECT_NE(result.failure_reason.find(expected), std::string::npos)
        << "expected '" << expected << "' in: " << result.failure_reason;
    EXPECT_EQ(result.dls_runs, 0) << expected;  // rejected before any search
  }
}

TEST_F(WholeBodyIkTest, RejectsBadHintsAndReferences) {
  Rng rng(17);
  const WholeBodyIk ik(kinematics_, TestOptions());
  const WholeBodyState truth = RandomFreeState(&rng);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(truth);
  WholeBodyIkQuery nan_hint;
  nan_hint.hint = truth;
  nan_hint.hint->q_rad(3) = std::numeric_limits<double>::quiet_NaN();
  WholeBodyIkQuery short_hint;
  short_hint.hint = truth;
  short_hint.hint->q_rad.resize(5);
  WholeBodyIkQuery inf_reference;
  inf_reference.reference_base =
      Eigen::Vector3d(0.0, std::numeric_limits<double>::infinity(), 0.0);
  WholeBodyIkQuery nan_standing;
  nan_standing.standing = truth;
  nan_standing.standing->x_m = std::numeric_limits<double>::quiet_NaN();
  WholeBodyIkQuery short_standing;
  short_standing.standing = truth;
  short_standing.standing->q_rad.resize(6);
  WholeBodyIkQuery nan_reference_q;
  nan_reference_q.reference_q_rad = truth.q_rad;
  (*nan_reference_q.reference_q_rad)(6) = std::numeric_limits<double>::quiet_NaN();
  WholeBodyIkQuery long_reference_q;
  long_reference_q.reference_q_rad = Eigen::VectorXd::Zero(8);
  for (const WholeBodyIkQuery& query : {nan_hint, short_hint, inf_reference, nan_standing, short_standing,
                                        nan_reference_q, long_reference_q}) {
    const WholeBodyIkResult result = ik.Solve(X_WE_target, nullptr, query);
    EXPECT_FALSE(result.success());
    EXPECT_NE(result.failure_reason.find("bad input"), std::string::npos)
        << result.failure_reason;
    EXPECT_EQ(result.dls_runs, 0);
  }
}

TEST_F(WholeBodyIkTest, RejectsOptionsOutOfRange) {
  auto message = [&](WholeBodyIkOptions options) -> std::string {
    try {
      WholeBodyIk ik(kinematics_, options);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message(WholeBodyIkOptions{}), "");
  WholeBodyIkOptions options;
  options.position_tolerance_m = 0.0;
  EXPECT_NE(message(options).find("position_tolerance_m"), std::string::npos);
  options = {};
  options.damping_bias = -1.0;
  EXPECT_NE(message(options).find("damping_bias"), std::string::npos);
  options = {};
  options.min_clearance_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(message(options).find("min_clearance_m"), std::string::npos);
  options = {};
  options.reach_min_m = 0.5;
  options.reach_max_m = 0.3;
  EXPECT_NE(message(options).find("reach_min_m"), std::string::npos);
}

TEST_F(WholeBodyIkTest, StopsAtTheIterationBudget) {
  Rng rng(18);
  WholeBodyIkOptions options = TestOptions();
  options.max_total_iterations = 30;
  const WholeBodyIk ik(kinematics_, options);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(RandomFreeState(&rng));
  const WholeBodyIkResult result =
      ik.Solve(X_WE_target, [](const WholeBodyState&) { return -1.0; });
  EXPECT_FALSE(result.success());
  EXPECT_TRUE(result.budget_exhausted);
  EXPECT_LE(result.total_iterations, 30);
  EXPECT_NE(result.failure_reason.find("budget"), std::string::npos) << result.failure_reason;
}

TEST_F(WholeBodyIkTest, DlsIterationsDoNotAllocate) {
  // A search that never succeeds (clearance blocks everything) allocates per Solve and per
  // base candidate, never per iteration: twice the iterations, the same allocation count.
  Rng rng(19);
  const Eigen::Isometry3d X_WE_target = kinematics_.EndEffectorPose(RandomFreeState(&rng));
  const StateClearanceFn blocked = [](const WholeBodyState&) { return -1.0; };
  auto count_allocations = [&](int max_dls_iterations) {
    WholeBodyIkOptions options = TestOptions();
    options.max_dls_iterations = max_dls_iterations;
    options.max_base_candidates = 2;
    options.convergence_fraction = 0.0;  // iterate to the limit or the stall test
    const WholeBodyIk ik(kinematics_, options);
    const testing::AllocationCounter allocations;
    const WholeBodyIkResult result = ik.Solve(X_WE_target, blocked);
    return std::make_pair(allocations.count(), result.total_iterations);
  };
  const auto [few_allocations, few_iterations] = count_allocations(4);
  const auto [many_allocations, many_iterations] = count_allocations(40);
  ASSERT_GT(many_iterations, few_iterations + 20);
  EXPECT_GT(few_allocations, 0);  // the counter works
  EXPECT_EQ(many_allocations, few_allocations);
}

}  // namespace
}  // namespace topay
