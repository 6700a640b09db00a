#include "core/optimization/pose_residual.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/robot/kinematics.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

Eigen::Isometry3d Pose(const Eigen::Vector3d& p, const Eigen::AngleAxisd& r) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = r.toRotationMatrix();
  X.translation() = p;
  return X;
}

TEST(PoseResidualTest, PositionErrorAndRotationVector) {
  const Eigen::Isometry3d goal =
      Pose(Eigen::Vector3d(1, 2, 3), Eigen::AngleAxisd(0.4, Eigen::Vector3d(0, 1, 1).normalized()));
  const Eigen::AngleAxisd extra(0.3, Eigen::Vector3d(1, 0, 0));
  Eigen::Isometry3d pose = goal;
  pose.linear() = extra.toRotationMatrix() * goal.linear();  // rotated by 0.3 rad about W's x
  pose.translation() += Eigen::Vector3d(0.1, -0.2, 0.05);
  const Vector6d r = PoseResidual(pose, goal);
  EXPECT_TRUE(r.head<3>().isApprox(Eigen::Vector3d(0.1, -0.2, 0.05), 1e-12));
  EXPECT_TRUE(r.tail<3>().isApprox(Eigen::Vector3d(0.3, 0, 0), 1e-12));
  EXPECT_NEAR(PoseResidual(goal, goal).norm(), 0.0, 1e-12);
}

TEST(PoseResidualTest, AngleIsTheShortestRotation) {
  const Eigen::Isometry3d goal = Eigen::Isometry3d::Identity();
  const Eigen::Isometry3d pose =
      Pose(Eigen::Vector3d::Zero(),
           Eigen::AngleAxisd(1.5 * std::numbers::pi, Eigen::Vector3d::UnitZ()));
  EXPECT_NEAR(PoseResidual(pose, goal).tail<3>().norm(), 0.5 * std::numbers::pi, 1e-12);
}

// d Log(Exp(w) R) / dw at w = 0 is J_l^{-1}(Log R): check against central differences.
TEST(PoseResidualTest, InverseLeftJacobianMatchesFiniteDifferences) {
  for (double angle : {1e-6, 0.3, 1.2, 2.8}) {
    const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const Eigen::Isometry3d goal = Eigen::Isometry3d::Identity();
    const auto log = [&](const Eigen::Vector3d& w) {
      Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
      X.linear() = Eigen::AngleAxisd(w.norm(), w.norm() > 0 ? Eigen::Vector3d(w.normalized())
                                                            : Eigen::Vector3d::UnitX())
                       .toRotationMatrix() *
                   R;
      return Eigen::Vector3d(PoseResidual(X, goal).tail<3>());
    };
    const Eigen::Matrix3d J = InverseLeftJacobianSO3(angle * axis);
    constexpr double kH = 1e-6;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d e = kH * Eigen::Vector3d::Unit(c);
      const Eigen::Vector3d numeric = (log(e) - log(-e)) / (2 * kH);
      EXPECT_TRUE(J.col(c).isApprox(numeric, 1e-6)) << "angle " << angle << " column " << c
                                                    << "\n" << J.col(c) << "\n" << numeric;
    }
  }
}

// The residual's Jacobian with respect to the whole-body state z against central differences
// of PoseResidual(FK(z)).
TEST(PoseResidualTest, JacobianWithRespectToTheStateMatchesFiniteDifferences) {
  const RobotModel model = testing::LoadTopayModel();
  const Kinematics kinematics(model);
  Rng rng(5);
  KinematicsCache cache = kinematics.MakeCache();
  Eigen::MatrixXd J_WE(6, kinematics.num_states()), dr_dz(6, kinematics.num_states());
  for (int trial = 0; trial < 10; ++trial) {
    const WholeBodyState state = testing::RandomState(model, &rng);
    WholeBodyState goal_state = testing::RandomState(model, &rng);
    goal_state.x_m = state.x_m + 0.2;
    goal_state.y_m = state.y_m;
    const Eigen::Isometry3d goal = kinematics.EndEffectorPose(goal_state);
    kinematics.Update(state, &cache);
    const Vector6d r = PoseResidual(cache.X_WE, goal);
    if (r.tail<3>().norm() > 3.0) continue;  // too close to the log map's cut at pi
    kinematics.EndEffectorJacobian(cache, J_WE);
    PoseResidualJacobian(r, J_WE, dr_dz);
    const Eigen::VectorXd z = state.ToVector();
    constexpr double kH = 1e-6;
    for (int i = 0; i < z.size(); ++i) {
      Eigen::VectorXd plus = z, minus = z;
      plus(i) += kH;
      minus(i) -= kH;
      const Vector6d numeric =
          (PoseResidual(kinematics.EndEffectorPose(WholeBodyState::FromVector(plus)), goal) -
           PoseResidual(kinematics.EndEffectorPose(WholeBodyState::FromVector(minus)), goal)) /
          (2 * kH);
      EXPECT_LT((dr_dz.col(i) - numeric).norm(), 1e-6 * std::max(1.0, numeric.norm()))
          << "trial " << trial << " z(" << i << ")";
    }
  }
}

}  // namespace
}  // namespace topay
