#include "core/robot/joint_turns.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/robot/kinematics.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

class JointTurnsTest : public ::testing::Test {
 protected:
  JointTurnsTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  WholeBodyState WithJoints(const Eigen::VectorXd& q_rad) const {
    WholeBodyState state;
    state.x_m = 1.0;
    state.y_m = -2.0;
    state.yaw_rad = 0.4;
    state.q_rad = q_rad;
    return state;
  }

  // Every collision sphere and the end effector where they were (the same pose).
  void ExpectSamePose(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
    KinematicsCache cache_a = kinematics_.MakeCache(), cache_b = kinematics_.MakeCache();
    kinematics_.Update(WithJoints(a), &cache_a);
    kinematics_.Update(WithJoints(b), &cache_b);
    for (int s = 0; s < static_cast<int>(model_.spheres.size()); ++s) {
      EXPECT_LE((cache_a.p_WS[s] - cache_b.p_WS[s]).norm(), 1e-9) << "sphere " << s;
    }
    EXPECT_TRUE(kinematics_.EndEffectorPose(WithJoints(a)).isApprox(kinematics_.EndEffectorPose(WithJoints(b)), 1e-9));
  }

  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(JointTurnsTest, TheWristIsTurnedToTheNearestTurnWithinItsLimits) {
  // Finding 29's case: goal q7 = 5.87 rad, the robot at q7 = -5.52 rad.
  Eigen::VectorXd q(7), reference(7);
  q << 0.2, -0.3, 1.0, 0.9, -0.6, 0.8, 5.87;
  reference << 0.1, -0.2, 1.1, 0.8, -0.5, 0.7, -5.52;
  const Eigen::VectorXd turned = NearestJointTurns(model_, q, reference);
  EXPECT_NEAR(turned(6), 5.87 - kTurn, 1e-12);
  EXPECT_EQ(turned.head<6>(), q.head<6>());  // +-3.1 rad and less: no other turn fits
  ExpectSamePose(q, turned);
}

TEST_F(JointTurnsTest, AJointWithoutAnotherTurnWithinItsLimitsStays) {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(7), reference = Eigen::VectorXd::Zero(7);
  q(0) = 3.0;           // joint 1, limits +-3.1: 3.0 - 2 pi is outside
  reference(0) = -3.0;
  q(6) = 6.0;           // joint 7: already on the turn nearest 6.2 (6.0 - 2 pi = -0.28 is not)
  reference(6) = 6.2;
  const Eigen::VectorXd turned = NearestJointTurns(model_, q, reference);
  EXPECT_EQ(turned, q);
}

TEST_F(JointTurnsTest, ARandomTurnIsTheNearestWithinLimitsAndTheSamePose) {
  Rng rng(7);
  const JointLimits& limits = model_.joint_limits;
  for (int trial = 0; trial < 200; ++trial) {
    const WholeBodyState q = testing::RandomState(model_, &rng);
    const WholeBodyState reference = testing::RandomState(model_, &rng);
    const Eigen::VectorXd turned = NearestJointTurns(model_, q.q_rad, reference.q_rad);
    for (int i = 0; i < model_.num_joints(); ++i) {
      EXPECT_GE(turned(i), limits.q_min_rad(i));
      EXPECT_LE(turned(i), limits.q_max_rad(i));
      const double turns = (turned(i) - q.q_rad(i)) / kTurn;
      EXPECT_NEAR(turns, std::round(turns), 1e-9);
      // Brute force over every turn within a few of it.
      double best = std::abs(q.q_rad(i) - reference.q_rad(i));
      for (int k = -3; k <= 3; ++k) {
        const double other = q.q_rad(i) + k * kTurn;
        if (other >= limits.q_min_rad(i) && other <= limits.q_max_rad(i)) {
          best = std::min(best, std::abs(other - reference.q_rad(i)));
        }
      }
      EXPECT_NEAR(std::abs(turned(i) - reference.q_rad(i)), best, 1e-12) << "trial " << trial << " joint " << i;
    }
    ExpectSamePose(q.q_rad, turned);
  }
}

TEST_F(JointTurnsTest, APrismaticJointIsNeverTurned) {
  RobotModel model = model_;
  for (Link& link : model.links) {
    if (link.q_index == 6) link.joint_type = JointType::kPrismatic;
  }
  Eigen::VectorXd q = Eigen::VectorXd::Zero(7), reference = Eigen::VectorXd::Zero(7);
  q(6) = 5.87;
  reference(6) = -5.52;
  EXPECT_EQ(NearestJointTurns(model, q, reference)(6), 5.87);
}

TEST_F(JointTurnsTest, BadSizesThrowAndNonFiniteValuesStay) {
  EXPECT_THROW(NearestJointTurns(model_, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(7)), std::invalid_argument);
  EXPECT_THROW(NearestJointTurns(model_, Eigen::VectorXd::Zero(7), Eigen::VectorXd::Zero(8)), std::invalid_argument);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(7), reference = Eigen::VectorXd::Zero(7);
  q(6) = std::numeric_limits<double>::quiet_NaN();
  reference(5) = std::numeric_limits<double>::infinity();
  const Eigen::VectorXd turned = NearestJointTurns(model_, q, reference);
  EXPECT_TRUE(std::isnan(turned(6)));
  EXPECT_EQ(turned(5), 0.0);
}

}  // namespace
}  // namespace topay
