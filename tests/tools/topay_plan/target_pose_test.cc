#include "tools/topay_plan/target_pose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace topay::plan {
namespace {

Eigen::Matrix3d Rx(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d Ry(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
Eigen::Matrix3d Rz(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

TEST(TargetPoseTest, RollPitchYawAreFixedAxesInXyzOrder) {
  const Eigen::Isometry3d X = PoseFromXyzRpy({1, 2, 0.8}, 0.3, -0.4, 2.0);
  EXPECT_TRUE(X.translation().isApprox(Eigen::Vector3d(1, 2, 0.8)));
  EXPECT_TRUE(X.linear().isApprox(Rz(2.0) * Ry(-0.4) * Rx(0.3), 1e-15));
  // A pure yaw turns the x axis towards y.
  const Eigen::Isometry3d yaw = PoseFromXyzRpy({0, 0, 0}, 0, 0, M_PI / 2);
  EXPECT_TRUE((yaw.linear() * Eigen::Vector3d::UnitX()).isApprox(Eigen::Vector3d::UnitY()));
}

TEST(TargetPoseTest, RollPitchYawInvertsTheConstruction) {
  for (const Eigen::Vector3d& rpy :
       {Eigen::Vector3d(0.3, -0.4, 2.0), Eigen::Vector3d(-3.0, 1.2, -0.1),
        Eigen::Vector3d(0.0, 0.0, 0.0)}) {
    EXPECT_TRUE(RollPitchYaw(Rz(rpy.z()) * Ry(rpy.y()) * Rx(rpy.x())).isApprox(rpy, 1e-12))
        << rpy.transpose();
  }
  // At pitch = pi/2 only yaw - roll is defined: the result rebuilds the same rotation.
  const Eigen::Matrix3d locked = Rz(0.7) * Ry(M_PI / 2) * Rx(0.2);
  const Eigen::Vector3d rpy = RollPitchYaw(locked);
  EXPECT_TRUE((Rz(rpy.z()) * Ry(rpy.y()) * Rx(rpy.x())).isApprox(locked, 1e-9));
}

TEST(TargetPoseTest, QuaternionsAreNormalisedWithinATolerance) {
  const Eigen::Isometry3d X = PoseFromXyzQuaternion({1, 2, 3}, {0.7071, 0.0, 0.0, 0.7071});
  EXPECT_TRUE(X.linear().isApprox(Rz(M_PI / 2), 1e-12));
  EXPECT_TRUE(X.translation().isApprox(Eigen::Vector3d(1, 2, 3)));
  EXPECT_THROW(PoseFromXyzQuaternion({0, 0, 0}, {1.1, 0.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(PoseFromXyzQuaternion({0, 0, 0}, {0.0, 0.0, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(PoseFromXyzQuaternion({0, 0, 0}, {std::nan(""), 0.0, 0.0, 0.0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay::plan
