#include <cmath>
#include <cstdlib>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/robot/kinematics.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

using testing::LoadTopayModel;
using testing::RandomState;

constexpr int kNumRandomStates = 100;
constexpr double kStep = 1e-6;  // central-difference step
constexpr double kMaxRelativeError = 1e-6;

class KinematicsTest : public ::testing::Test {
 protected:
  KinematicsTest()
      : model_(LoadTopayModel()), kinematics_(model_), cache_(kinematics_.MakeCache()) {}

  WholeBodyState ZeroState() const {
    WholeBodyState state;
    state.q_rad = Eigen::VectorXd::Zero(model_.num_joints());
    return state;
  }

  KinematicsCache At(const Eigen::VectorXd& z) const {
    KinematicsCache cache = kinematics_.MakeCache();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache);
    return cache;
  }

  RobotModel model_;
  Kinematics kinematics_;
  KinematicsCache cache_;
};

double RelativeError(const Eigen::MatrixXd& analytic, const Eigen::MatrixXd& numeric) {
  return (analytic - numeric).norm() / std::max(1.0, numeric.norm());
}

// Central differences of a point (3 rows) or a pose (6 rows: rotation vector of
// R(z+h) R(z-h)^T / 2h, then position) as a function of z.
template <typename PoseFn>
Eigen::MatrixXd NumericPoseJacobian(const Eigen::VectorXd& z, PoseFn pose_at) {
  Eigen::MatrixXd J(6, z.size());
  for (int c = 0; c < z.size(); ++c) {
    Eigen::VectorXd plus = z, minus = z;
    plus(c) += kStep;
    minus(c) -= kStep;
    const Eigen::Isometry3d X_plus = pose_at(plus), X_minus = pose_at(minus);
    const Eigen::AngleAxisd delta(X_plus.linear() * X_minus.linear().transpose());
    J.block<3, 1>(0, c) = delta.angle() * delta.axis() / (2 * kStep);
    J.block<3, 1>(3, c) = (X_plus.translation() - X_minus.translation()) / (2 * kStep);
  }
  return J;
}

TEST_F(KinematicsTest, SphereCentresAtZeroLieOnArmAxisAtTheFactSheetHeights) {
  // TopAY authors' code: sphere centre heights at q = 0, arm axis at (0, 0.115) in the base frame.
  const double heights_m[] = {0.220, 0.310, 0.4115, 0.484,  0.564,  0.6675,
                              0.726, 0.796, 0.8775, 0.9515, 1.0215, 1.1215};
  ASSERT_EQ(model_.spheres.size(), std::size(heights_m));
  kinematics_.Update(ZeroState(), &cache_);
  for (std::size_t s = 0; s < std::size(heights_m); ++s) {
    SCOPED_TRACE("sphere " + std::to_string(s));
    EXPECT_NEAR(cache_.p_WS[s].x(), 0.0, 1e-12);
    EXPECT_NEAR(cache_.p_WS[s].y(), 0.115, 1e-12);
    EXPECT_NEAR(cache_.p_WS[s].z(), heights_m[s], 1e-12);
  }
}

TEST_F(KinematicsTest, JointsAndEndEffectorAtZeroAreAtTheSrsHeights) {
  kinematics_.Update(ZeroState(), &cache_);
  // Shoulder (joint 2), elbow (joint 4), wrist (joint 6), flange = end effector.
  EXPECT_NEAR(cache_.X_WL[model_.FindLink("link2")].translation().z(), 0.4115, 1e-12);
  EXPECT_NEAR(cache_.X_WL[model_.FindLink("link4")].translation().z(), 0.6675, 1e-12);
  EXPECT_NEAR(cache_.X_WL[model_.FindLink("link6")].translation().z(), 0.8775, 1e-12);
  EXPECT_TRUE(cache_.X_WE.translation().isApprox(Eigen::Vector3d(0.0, 0.115, 1.0215), 1e-12));
}

TEST_F(KinematicsTest, ArmMountIsOffsetAndYawedMinus45DegInTheMovedBase) {
  WholeBodyState state = ZeroState();
  state.x_m = 1.5;
  state.y_m = -2.0;
  state.yaw_rad = 0.7;
  kinematics_.Update(state, &cache_);
  const Eigen::Isometry3d& X_WM = cache_.X_WL[model_.FindLink("arm_base_link")];
  const Eigen::Matrix3d R_WB = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d p_WM =
      Eigen::Vector3d(1.5, -2.0, 0.0) + R_WB * Eigen::Vector3d(0, 0.115, 0.171);
  EXPECT_TRUE(X_WM.translation().isApprox(p_WM, 1e-12));
  const Eigen::Matrix3d R_WM =
      Eigen::AngleAxisd(0.7 - std::numbers::pi / 4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  EXPECT_TRUE(X_WM.linear().isApprox(R_WM, 1e-12));
  EXPECT_TRUE(cache_.X_WB.translation().isApprox(Eigen::Vector3d(1.5, -2.0, 0.0)));
}

TEST_F(KinematicsTest, JointOneTurnsTheArmAboutItsAxis) {
  WholeBodyState state = ZeroState();
  state.q_rad(0) = 0.5;
  state.q_rad(1) = std::numbers::pi / 2;  // shoulder pitched: the arm points horizontally
  kinematics_.Update(state, &cache_);
  const Eigen::Vector3d r = cache_.X_WE.translation() - Eigen::Vector3d(0, 0.115, 0.4115);
  EXPECT_NEAR(r.z(), 0.0, 1e-12);
  EXPECT_NEAR(r.norm(), 0.256 + 0.21 + 0.144, 1e-12);
  // Horizontal direction: the mount's x axis (yaw -45 deg) turned by q1 = 0.5 rad.
  EXPECT_NEAR(std::atan2(r.y(), r.x()), -std::numbers::pi / 4 + 0.5, 1e-12);
}

// Update (Rodrigues terms precomputed per link) equals the URDF composition written out with
// Eigen's axis-angle rotation, X_WC = X_WP X_PJ R(axis, q), at random configurations.
TEST_F(KinematicsTest, UpdateMatchesTheAxisAngleComposition) {
  std::srand(3);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd z = Eigen::VectorXd::Random(3 + model_.num_joints()) * 3.0;
    const KinematicsCache cache = At(z);
    const WholeBodyState state = WholeBodyState::FromVector(z);
    std::vector<Eigen::Isometry3d> X_WL(model_.links.size());
    for (std::size_t i = 0; i < model_.links.size(); ++i) {
      const Link& link = model_.links[i];
      const Eigen::Isometry3d& X_WP = link.parent < 0 ? state.BasePose() : X_WL[link.parent];
      Eigen::Isometry3d X_JC = Eigen::Isometry3d::Identity();
      if (link.joint_type == JointType::kRevolute) {
        X_JC.linear() = Eigen::AngleAxisd(state.q_rad(link.q_index), link.axis_J).toRotationMatrix();
      } else if (link.joint_type == JointType::kPrismatic) {
        X_JC.translation() = link.axis_J * state.q_rad(link.q_index);
      }
      X_WL[i] = X_WP * link.X_PJ * X_JC;
      EXPECT_LT((cache.X_WL[i].matrix() - X_WL[i].matrix()).norm(), 1e-12)
          << "link " << link.name << ", trial " << trial;
    }
  }
}

TEST_F(KinematicsTest, SphereJacobiansMatchCentralDifferences) {
  Rng rng(11);
  Eigen::MatrixXd J(3, kinematics_.num_states());
  for (int trial = 0; trial < kNumRandomStates; ++trial) {
    const Eigen::VectorXd z = RandomState(model_, &rng).ToVector();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache_);
    for (int s = 0; s < static_cast<int>(model_.spheres.size()); ++s) {
      kinematics_.SphereJacobian(cache_, s, J);
      const Eigen::MatrixXd numeric = NumericPoseJacobian(z, [&](const Eigen::VectorXd& zz) {
                                        Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
                                        X.translation() = At(zz).p_WS[s];
                                        return X;
                                      }).bottomRows(3);
      ASSERT_LT(RelativeError(J, numeric), kMaxRelativeError)
          << "trial " << trial << " sphere " << s;
    }
  }
}

TEST_F(KinematicsTest, EndEffectorJacobianMatchesCentralDifferences) {
  Rng rng(12);
  Eigen::MatrixXd J(6, kinematics_.num_states());
  for (int trial = 0; trial < kNumRandomStates; ++trial) {
    const Eigen::VectorXd z = RandomState(model_, &rng).ToVector();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache_);
    kinematics_.EndEffectorJacobian(cache_, J);
    const Eigen::MatrixXd numeric =
        NumericPoseJacobian(z, [&](const Eigen::VectorXd& zz) { return At(zz).X_WE; });
    ASSERT_LT(RelativeError(J.topRows(3), numeric.topRows(3)), kMaxRelativeError) << trial;
    ASSERT_LT(RelativeError(J.bottomRows(3), numeric.bottomRows(3)), kMaxRelativeError) << trial;
  }
}

TEST_F(KinematicsTest, LinkJacobiansMatchCentralDifferences) {
  Rng rng(13);
  Eigen::MatrixXd J(6, kinematics_.num_states());
  for (int trial = 0; trial < kNumRandomStates; ++trial) {
    const Eigen::VectorXd z = RandomState(model_, &rng).ToVector();
    kinematics_.Update(WholeBodyState::FromVector(z), &cache_);
    for (int l = 0; l < static_cast<int>(model_.links.size()); ++l) {
      kinematics_.LinkJacobian(cache_, l, J);
      const Eigen::MatrixXd numeric =
          NumericPoseJacobian(z, [&](const Eigen::VectorXd& zz) { return At(zz).X_WL[l]; });
      ASSERT_LT(RelativeError(J, numeric), kMaxRelativeError) << "trial " << trial << " link " << l;
    }
  }
}

TEST_F(KinematicsTest, JacobianTransposeProductEqualsExplicitProduct) {
  Rng rng(14);
  Eigen::MatrixXd J(3, kinematics_.num_states());
  for (int trial = 0; trial < 20; ++trial) {
    kinematics_.Update(RandomState(model_, &rng), &cache_);
    const int s = static_cast<int>(rng.UniformInt(0, model_.spheres.size() - 1));
    const Eigen::Vector3d f(rng.Normal(), rng.Normal(), rng.Normal());
    kinematics_.SphereJacobian(cache_, s, J);
    Eigen::VectorXd gradient = Eigen::VectorXd::Ones(kinematics_.num_states());
    kinematics_.AddPointJacobianTransposeTimes(cache_, model_.spheres[s].link, cache_.p_WS[s], f,
                                               gradient);
    const Eigen::VectorXd expected =
        Eigen::VectorXd::Ones(kinematics_.num_states()) + J.transpose() * f;
    EXPECT_LT((gradient - expected).norm(), 1e-12 * std::max(1.0, expected.norm()));
  }
}

TEST_F(KinematicsTest, UpdateAndJacobiansDoNotAllocate) {
  Rng rng(15);
  const WholeBodyState state = RandomState(model_, &rng);
  Eigen::MatrixXd J(6, kinematics_.num_states());
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(kinematics_.num_states());
  const testing::AllocationCounter allocations;
  kinematics_.Update(state, &cache_);
  kinematics_.EndEffectorJacobian(cache_, J);
  kinematics_.LinkJacobian(cache_, 3, J);
  kinematics_.AddPointJacobianTransposeTimes(cache_, 5, cache_.p_WS[5], Eigen::Vector3d::UnitZ(),
                                             gradient);
  EXPECT_EQ(allocations.count(), 0);
}

TEST_F(KinematicsTest, AllocationCounterSeesMakeCacheAllocate) {
  // The check above is only meaningful if the counter sees allocations at all.
  const testing::AllocationCounter allocations;
  const KinematicsCache cache = kinematics_.MakeCache();
  EXPECT_GT(allocations.count(), 0);
  EXPECT_EQ(cache.X_WL.size(), model_.links.size());
}

TEST_F(KinematicsTest, RejectsWrongSizedStateNaNAndBadBuffers) {
  WholeBodyState state = ZeroState();
  state.q_rad.resize(6);
  state.q_rad.setZero();
  EXPECT_THROW(kinematics_.Update(state, &cache_), std::invalid_argument);
  state = ZeroState();
  state.q_rad(2) = std::nan("");
  EXPECT_THROW(kinematics_.Update(state, &cache_), std::invalid_argument);
  kinematics_.Update(ZeroState(), &cache_);
  Eigen::MatrixXd wrong(6, kinematics_.num_states() - 1);
  EXPECT_THROW(kinematics_.EndEffectorJacobian(cache_, wrong), std::invalid_argument);
  Eigen::MatrixXd J(3, kinematics_.num_states());
  EXPECT_THROW(kinematics_.SphereJacobian(cache_, static_cast<int>(model_.spheres.size()), J),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
