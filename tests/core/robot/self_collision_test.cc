#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/robot/self_collision.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

using testing::LoadTopayModel;
using testing::RandomState;

constexpr int kNumRandomStates = 100;
constexpr double kStep = 1e-6;
constexpr double kMaxRelativeError = 1e-6;

bool HasPair(const RobotModel& model, int i, int j) {
  return std::find(model.self_collision_pairs.begin(), model.self_collision_pairs.end(),
                   std::make_pair(i, j)) != model.self_collision_pairs.end();
}

// Central differences of a vector-valued function of z: column c = d f / d z_c.
template <typename Fn>
Eigen::MatrixXd NumericJacobian(const Eigen::VectorXd& z, int rows, Fn f) {
  Eigen::MatrixXd J(rows, z.size());
  for (int c = 0; c < z.size(); ++c) {
    Eigen::VectorXd plus = z, minus = z;
    plus(c) += kStep;
    minus(c) -= kStep;
    J.col(c) = (f(plus) - f(minus)) / (2 * kStep);
  }
  return J;
}

double RelativeError(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  return (analytic - numeric).norm() / std::max(1.0, numeric.norm());
}

TEST(SelfCollisionPairsTest, TopayPairsAreNonAdjacentAndSeparatedAtZero) {
  const RobotModel model = LoadTopayModel();
  // From the authors' code: the arm link each sphere moves with, its height at q = 0 (all on
  // the arm axis) and radius. Links k and k +- 1 are adjacent (one joint apart).
  const int arm_link[] = {1, 1, 2, 3, 3, 4, 5, 5, 6, 7, 7, 7};
  const double height_m[] = {0.220, 0.310, 0.4115, 0.484,  0.564,  0.6675,
                             0.726, 0.796, 0.8775, 0.9515, 1.0215, 1.1215};
  const double radius_m[] = {0.06,  0.06,  0.08, 0.04,  0.04,  0.07,
                             0.035, 0.035, 0.06, 0.035, 0.035, 0.08};
  ASSERT_EQ(model.spheres.size(), std::size(arm_link));
  int expected_count = 0;
  for (int i = 0; i < 12; ++i) {
    for (int j = i + 1; j < 12; ++j) {
      const bool adjacent = std::abs(arm_link[i] - arm_link[j]) <= 1;
      const bool separated = std::abs(height_m[i] - height_m[j]) > radius_m[i] + radius_m[j];
      const bool expected = !adjacent && separated;
      expected_count += expected;
      EXPECT_EQ(HasPair(model, i, j), expected) << "pair " << i << ", " << j;
    }
  }
  EXPECT_EQ(static_cast<int>(model.self_collision_pairs.size()), expected_count);
  EXPECT_GT(expected_count, 0);
}

TEST(SelfCollisionPairsTest, LinksWeldedByFixedJointsCountAsOneBody) {
  const std::string dir = std::string(TOPAY_SOURCE_DIR) + "/tests/data/robot/";
  const RobotModel model = LoadRobotModel(dir + "six_joint_arm.urdf", dir + "six_joint_arm.yaml");
  // Spheres: 0 link1, 1 link2, 2 link3, 3 link5, 4 tool0 (welded to link6).
  const std::vector<int> body = RigidBodiesOfLinks(model);
  EXPECT_EQ(body[model.FindLink("tool0")], model.FindLink("link6"));
  EXPECT_EQ(body[model.FindLink("mount")], 0);
  EXPECT_FALSE(HasPair(model, 3, 4));  // link5 - tool0: adjacent through j6 (0.2 m apart)
  EXPECT_TRUE(HasPair(model, 2, 4));   // link3 - tool0: three joints apart
  EXPECT_TRUE(HasPair(model, 0, 2));   // link1 - link3
  EXPECT_FALSE(HasPair(model, 0, 1));  // link1 - link2: adjacent
}

// A hand-made chain root -> a -> b -> c (revolute about z, 0.1 m apart): spheres on root
// and b overlap at q = 0 and must be skipped; root and c do not and must be kept.
TEST(SelfCollisionPairsTest, PairsOverlappingAtZeroAreSkipped) {
  RobotModel model;
  model.links.resize(4);
  const char* names[] = {"root", "a", "b", "c"};
  for (int i = 0; i < 4; ++i) {
    model.links[i].name = names[i];
    if (i == 0) continue;
    model.links[i].parent = i - 1;
    model.links[i].joint_type = JointType::kRevolute;
    model.links[i].q_index = i - 1;
    model.links[i].X_PJ.translation() = Eigen::Vector3d(0, 0, 0.1);
    model.joint_names.push_back(names[i]);
  }
  model.spheres = {{0, Eigen::Vector3d::Zero(), 0.15},
                   {2, Eigen::Vector3d::Zero(), 0.1},
                   {3, Eigen::Vector3d(0, 0, 0.2), 0.1}};
  const auto pairs = FindSelfCollisionPairs(model);
  ASSERT_EQ(pairs.size(), 1u);  // (0,1) overlaps: 0.2 < 0.25; (1,2) adjacent; (0,2) kept
  EXPECT_EQ(pairs[0], std::make_pair(0, 2));
}

class SelfCollisionTest : public ::testing::Test {
 protected:
  SelfCollisionTest()
      : model_(LoadTopayModel()),
        kinematics_(model_),
        self_collision_(kinematics_),
        cache_(kinematics_.MakeCache()) {}

  Eigen::VectorXd DistancesAt(const Eigen::VectorXd& z) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache);
    Eigen::VectorXd d(self_collision_.num_pairs());
    self_collision_.Distances(cache, d);
    return d;
  }

  Eigen::VectorXd MarginsAt(const Eigen::VectorXd& z) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache);
    Eigen::VectorXd m(self_collision_.num_spheres());
    self_collision_.ChassisMargins(cache, m);
    return m;
  }

  RobotModel model_;
  Kinematics kinematics_;
  SelfCollision self_collision_;
  KinematicsCache cache_;
};

TEST_F(SelfCollisionTest, DistancesAreCentreDistanceMinusRadii) {
  Rng rng(21);
  Eigen::VectorXd d(self_collision_.num_pairs());
  for (int trial = 0; trial < 10; ++trial) {
    kinematics_.Update(RandomState(model_, &rng), &cache_);
    self_collision_.Distances(cache_, d);
    for (int k = 0; k < self_collision_.num_pairs(); ++k) {
      const auto [i, j] = model_.self_collision_pairs[k];
      const double expected = (cache_.p_WS[i] - cache_.p_WS[j]).norm() -
                              model_.spheres[i].radius_m - model_.spheres[j].radius_m;
      EXPECT_NEAR(d(k), expected, 1e-12);
    }
  }
}

TEST_F(SelfCollisionTest, DistanceGradientsMatchCentralDifferences) {
  Rng rng(22);
  Eigen::VectorXd d(self_collision_.num_pairs());
  Eigen::MatrixXd gradients(kinematics_.num_states(), self_collision_.num_pairs());
  for (int trial = 0; trial < kNumRandomStates; ++trial) {
    const Eigen::VectorXd z = RandomState(model_, &rng).ToVector();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache_);
    self_collision_.Distances(cache_, d, &gradients);
    const Eigen::MatrixXd numeric = NumericJacobian(
        z, self_collision_.num_pairs(), [&](const Eigen::VectorXd& zz) { return DistancesAt(zz); });
    for (int k = 0; k < self_collision_.num_pairs(); ++k) {
      ASSERT_LT(RelativeError(gradients.col(k).transpose(), numeric.row(k)), kMaxRelativeError)
          << "trial " << trial << " pair " << k;
    }
  }
}

TEST_F(SelfCollisionTest, MinDistanceIsTheSmallestPairWithItsGradient) {
  Rng rng(23);
  Eigen::VectorXd d(self_collision_.num_pairs());
  Eigen::MatrixXd gradients(kinematics_.num_states(), self_collision_.num_pairs());
  Eigen::VectorXd min_gradient(kinematics_.num_states());
  for (int trial = 0; trial < 20; ++trial) {
    kinematics_.Update(RandomState(model_, &rng), &cache_);
    self_collision_.Distances(cache_, d, &gradients);
    Eigen::Index k_min = 0;
    const double expected = d.minCoeff(&k_min);
    EXPECT_EQ(self_collision_.MinDistance(cache_, &min_gradient), expected);
    EXPECT_TRUE(min_gradient.isApprox(gradients.col(k_min)));
  }
}

TEST_F(SelfCollisionTest, ChassisMarginsAtZeroAreHeightMinusRadiusMinusChassisTop) {
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(model_.num_joints());
  kinematics_.Update(state, &cache_);
  Eigen::VectorXd margins(self_collision_.num_spheres());
  self_collision_.ChassisMargins(cache_, margins);
  // Lowest sphere (the authors' code): centre 0.220 m, radius 0.06 m, chassis top 0.155 m.
  EXPECT_NEAR(margins(0), 0.220 - 0.06 - 0.155, 1e-12);
  EXPECT_NEAR(margins(11), 1.1215 - 0.08 - 0.155, 1e-12);
  EXPECT_GT(margins.minCoeff(), 0.0);
}

TEST_F(SelfCollisionTest, ChassisMarginGoesNegativeWhenTheArmReachesDown) {
  WholeBodyState state;
  state.q_rad = Eigen::VectorXd::Zero(model_.num_joints());
  state.q_rad(1) = 2.0;  // shoulder pitched 115 deg: the arm points down past horizontal
  kinematics_.Update(state, &cache_);
  Eigen::VectorXd margins(self_collision_.num_spheres());
  self_collision_.ChassisMargins(cache_, margins);
  // Tool sphere: 0.71 m from the shoulder at 0.4115 m, at 2.0 rad from the vertical.
  const double tool_z_m = 0.4115 + 0.71 * std::cos(2.0);
  EXPECT_NEAR(margins(11), tool_z_m - 0.08 - 0.155, 1e-12);
  EXPECT_LT(margins(11), 0.0);
}

TEST_F(SelfCollisionTest, ChassisMarginGradientsMatchCentralDifferences) {
  Rng rng(24);
  Eigen::VectorXd margins(self_collision_.num_spheres());
  Eigen::MatrixXd gradients(kinematics_.num_states(), self_collision_.num_spheres());
  for (int trial = 0; trial < kNumRandomStates; ++trial) {
    const Eigen::VectorXd z = RandomState(model_, &rng).ToVector();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache_);
    self_collision_.ChassisMargins(cache_, margins, &gradients);
    const Eigen::MatrixXd numeric = NumericJacobian(
        z, self_collision_.num_spheres(), [&](const Eigen::VectorXd& zz) { return MarginsAt(zz); });
    ASSERT_LT(RelativeError(gradients.transpose(), numeric), kMaxRelativeError) << trial;
  }
}

TEST_F(SelfCollisionTest, EvaluationDoesNotAllocate) {
  Rng rng(25);
  kinematics_.Update(RandomState(model_, &rng), &cache_);
  Eigen::VectorXd d(self_collision_.num_pairs());
  Eigen::MatrixXd d_gradients(kinematics_.num_states(), self_collision_.num_pairs());
  Eigen::VectorXd m(self_collision_.num_spheres());
  Eigen::MatrixXd m_gradients(kinematics_.num_states(), self_collision_.num_spheres());
  Eigen::VectorXd min_gradient(kinematics_.num_states());
  const testing::AllocationCounter allocations;
  self_collision_.Distances(cache_, d, &d_gradients);
  const double min_distance = self_collision_.MinDistance(cache_, &min_gradient);
  self_collision_.ChassisMargins(cache_, m, &m_gradients);
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_EQ(min_distance, d.minCoeff());
}

TEST_F(SelfCollisionTest, RejectsWrongSizedBuffers) {
  Rng rng(26);
  kinematics_.Update(RandomState(model_, &rng), &cache_);
  Eigen::VectorXd short_d(self_collision_.num_pairs() - 1);
  EXPECT_THROW(self_collision_.Distances(cache_, short_d), std::invalid_argument);
  Eigen::VectorXd d(self_collision_.num_pairs());
  Eigen::MatrixXd transposed(self_collision_.num_pairs(), kinematics_.num_states());
  EXPECT_THROW(self_collision_.Distances(cache_, d, &transposed), std::invalid_argument);
  Eigen::VectorXd m(self_collision_.num_spheres() + 1);
  EXPECT_THROW(self_collision_.ChassisMargins(cache_, m), std::invalid_argument);
}

}  // namespace
}  // namespace topay
